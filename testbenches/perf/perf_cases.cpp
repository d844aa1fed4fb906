// The list of perf_models' SystemC rows (perf_cases.h), which every file of rows adds to.
#include "perf_cases.h"

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace shading::perf {

std::vector<sc_case>& sc_cases() {
    static std::vector<sc_case> c;
    return c;
}

sc_case& add_sc(const std::string& name, const std::string& golden, const std::string& unit,
                std::function<std::unique_ptr<harness>()> make, bool traced) {
    sc_cases().push_back({name, golden, unit, std::move(make), traced, nullptr});
    return sc_cases().back();
}

}  // namespace shading::perf

// Assertion monitor (not a hardware block): at each latching (falling) edge of `ctl`, reports
// through SystemC (shading/input) a data word outside [lo, hi]. What the datapath then does with
// the word is the device's documented behaviour; this block only makes it visible.
#pragma once

#include <sstream>
#include <string>
#include <systemc>

#include "core/report_ids.h"

namespace shading {

template <unsigned W>
class range_checker : public sc_core::sc_module {
public:
    sc_core::sc_in<bool> ctl{"ctl"};
    sc_core::sc_in<sc_dt::sc_uint<W>> d{"d"};

    SC_HAS_PROCESS(range_checker);
    range_checker(const sc_core::sc_module_name& name, uint64_t lo, uint64_t hi, std::string what)
        : sc_module(name), lo_(lo), hi_(hi), what_(std::move(what)) {
        SC_METHOD(check);
        sensitive << ctl.neg();
        dont_initialize();
    }

    unsigned violations() const { return violations_; }

private:
    void check() {
        const uint64_t v = d.read().to_uint64();
        if (v >= lo_ && v <= hi_) return;
        ++violations_;
        std::ostringstream os;
        os << name() << ": " << v << " (0x" << std::hex << v << std::dec << ") latched at "
           << sc_core::sc_time_stamp() << " is outside " << lo_ << ".." << hi_ << "; " << what_;
        SC_REPORT_WARNING(msg::input, os.str().c_str());
    }

    uint64_t lo_, hi_;
    std::string what_;
    unsigned violations_ = 0;
};

}  // namespace shading

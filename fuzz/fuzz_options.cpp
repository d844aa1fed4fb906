// Fuzz target: the bench runner's command line (testbenches/common/bench_runner.h: --vcd, --no-vcd,
// --summary, --mode, --seed, --random, --jobs, the hidden --inject-*), which every testbench program
// of the specular devices and the interpolation units parses through CLI11. The input is split at
// NUL bytes into up to 24 arguments. bench_runner::parse must return an exit status of 0 (--help)
// or 2 (bad usage), or accept the line with every value inside its documented range; any other
// outcome (another status, an exception escaping, a sanitizer report) is a finding.
// "--jobs 1" is appended so that a large --random never starts child processes here; a second
// --jobs in the input then makes the line bad usage, which is also checked.
#include <cstdint>
#include <string>
#include <systemc>
#include <vector>

#include "common/bench_runner.h"
#include "fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    shading::fuzz::input in(data, size);
    const bool with_mode = (in.u8() & 1) != 0;
    std::vector<std::string> args{"bench"};
    std::string cur;
    while (!in.empty() && args.size() < 24) {
        const char c = static_cast<char>(in.u8());
        if (c == '\0') {
            args.push_back(cur);
            cur.clear();
        } else if (cur.size() < 64) {
            cur.push_back(c);
        }
    }
    if (!cur.empty()) args.push_back(cur);
    args.push_back("--jobs");
    args.push_back("1");
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);

    shading::tb::bench_runner run("bench", "fuzzed command line", "traces/fuzz", with_mode);
    const auto status = run.parse(static_cast<int>(args.size()), argv.data());
    if (status) {
        FUZZ_CHECK(*status == 0 || *status == 2, "parse returned exit status %d", *status);
        return 0;
    }
    FUZZ_CHECK(run.mode_name() == "saturate" || run.mode_name() == "wrap", "--mode '%s' accepted",
               run.mode_name().c_str());
    FUZZ_CHECK(!run.random() || (run.random_count() >= 1 && run.random_count() <= (uint64_t{1} << 40)),
               "--random %llu accepted", static_cast<unsigned long long>(run.random_count()));
    return 0;
}

// libsystemc's own main() calls sc_main; this program has its own main (libFuzzer's or the replay
// driver's) and never reaches it, but the library still needs the symbol.
int sc_main(int, char**) { return 2; }

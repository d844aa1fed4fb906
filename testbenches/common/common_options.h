// The options common to every testbench program (ua60553_tb, ua22802_tb, squared_tb, interp_*_tb)
// as a plain struct: the part of each program's command line that the runner (bench_runner.h) and
// the split into processes (bench_jobs.h) read. The programs' parse functions fill it
// (options/bench_options.h):
//   --vcd <stem>          write <stem>.vcd (default: the program's traces/<name>; in random mode
//                         only when given)
//   --no-vcd              write no VCD
//   --summary <file>      append summary rows (default: $SHADING_SUMMARY; none if empty)
//   --mode saturate|wrap  ADD11 overflow (specular devices only)
//   --seed S              seed of every random draw (default 1)
//   --random N            random differential mode: N (1..2^40) random stimuli against the golden model
//   --inject-mismatch K   (hidden, for the tests) corrupt the golden value of sample K
//   --inject-count C      (hidden) ... and of the C - 1 samples after it (default 1)
//   --jobs J              split a random run into J (1..1024) independent processes (default: one
//                         per core for runs of 100 000 stimuli or more); bench_jobs.h
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>

namespace shading::tb {

inline constexpr std::size_t no_injection = std::numeric_limits<std::size_t>::max();
inline constexpr uint64_t max_random = uint64_t{1} << 40;
inline constexpr unsigned max_jobs = 1024;

struct bench_options {
    std::string vcd;           // the VCD's stem: the program's default unless --vcd was given
    bool vcd_given = false;    // --vcd on the command line (a later default_vcd() does not replace it)
    bool no_vcd = false;       // --no-vcd, or --random without --vcd (10^7 stimuli make a huge VCD)
    std::string summary;       // default $SHADING_SUMMARY
    bool with_mode = false;    // the program offers --mode (the specular devices)
    std::string mode = "saturate";
    uint64_t seed = 1, random = 0;  // random 0: not in random mode
    unsigned jobs = 0;              // 0: --jobs not given (bench_jobs.h chooses)
    std::size_t inject = no_injection, inject_count = 1;
    std::string csv;                // the program's --csv when given: the split writes parts of it
};

}  // namespace shading::tb

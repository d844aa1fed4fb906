// The command line, run and verdict shared by every testbench program (the sc_main of
// ua60553_tb, ua22802_tb, interp_*_tb): the same options everywhere, one writer of the summary
// rows (out/summary.tsv, scripts/run.sh), and one exit status: 0 only when every sample matched
// the golden model and SystemC reported nothing the bench did not announce.
//
//   --vcd <stem>          write <stem>.vcd (default: the program's traces/<name>; in random mode
//                         only when given)
//   --no-vcd              write no VCD
//   --summary <file>      append summary rows (default: $SHADING_SUMMARY; none if empty)
//   --mode saturate|wrap  ADD11 overflow (specular devices only)
//   --seed S              seed of every random draw (default 1)
//   --random N            random differential mode: N random stimuli against the golden model
//   --inject-mismatch K   (hidden, for the tests) corrupt the golden value of sample K
//   --inject-count C      (hidden) ... and of the C - 1 samples after it (default 1)
//   --jobs J              split a random run into J independent processes (default: one per core
//                         for runs of 100 000 stimuli or more); bench_jobs.h
#pragma once

#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <systemc>
#include <utility>
#include <vector>

#include "common/bench_jobs.h"
#include "common/exit_status.h"
#include "common/report_log.h"
#include "core/trace.h"
#include "formats/fixed_point.h"

namespace shading::tb {

inline constexpr std::size_t no_injection = std::numeric_limits<std::size_t>::max();

// One row of out/summary.tsv: bench, case, samples, mismatches, max_error, cycles_per_pixel, note.
struct summary_row {
    std::string bench, case_name;
    std::size_t samples = 0, mismatches = 0;
    std::string max_error, cycles_per_pixel, note;
};

// The column formats the README's tables quote.
inline std::string fmt_percent(double fraction, int digits) {
    std::ostringstream os;
    os << std::fixed << std::setprecision(digits) << 100.0 * fraction << '%';
    return os.str();
}
inline std::string fmt_levels(double levels) {
    std::ostringstream os;
    os << std::fixed << std::setprecision(2) << levels << " lv";
    return os.str();
}
inline std::string fmt_number(double v, int significant = 4) {
    std::ostringstream os;
    os << std::setprecision(significant) << v;
    return os.str();
}

// Appends a row to the TSV file at `path`; nothing when `path` is empty.
inline void append_summary(const std::string& path, const summary_row& r) {
    if (path.empty()) return;
    std::ofstream f(path, std::ios::app);
    f << r.bench << '\t' << r.case_name << '\t' << r.samples << '\t' << r.mismatches << '\t' << r.max_error
      << '\t' << r.cycles_per_pixel << '\t' << r.note << '\n';
}

class bench_runner {
public:
    // `bench` names the program in messages and summary rows; `default_vcd` is the stem written
    // when neither --vcd nor --no-vcd is given; `with_mode` adds --mode (the specular devices).
    bench_runner(std::string bench, const std::string& description, std::string default_vcd, bool with_mode = false)
        : app(description), bench_(std::move(bench)), vcd_(std::move(default_vcd)) {
        if (const char* s = std::getenv("SHADING_SUMMARY")) summary_ = s;
        app.add_option("--vcd", vcd_, "write <stem>.vcd (default " + vcd_ + "; random mode: only when given)");
        app.add_flag("--no-vcd", no_vcd_, "write no VCD");
        app.add_option("--summary", summary_, "append TSV summary rows here (default: $SHADING_SUMMARY)");
        if (with_mode)
            app.add_option("--mode", mode_name_, "ADD11 overflow: saturate (default) or wrap (patent-faithful)")
                ->check(CLI::IsMember({"saturate", "wrap"}));
        app.add_option("--seed", seed_, "seed of the random stimuli (default 1)");
        app.add_option("--random", random_, "random differential mode: N random stimuli against the golden model")
            ->check(CLI::Range(uint64_t{1}, uint64_t{1} << 40));
        // Hidden (empty group): the CI proves with it that a mismatch makes the program fail.
        app.add_option("--inject-mismatch", inject_, "corrupt the golden value of sample K (0-based)")->group("");
        app.add_option("--inject-count", inject_count_, "corrupt C samples from K on (256 must not exit 0)")->group("");
        app.add_option("--jobs", jobs_, "random mode: J independent processes (default: one per core from 100000 stimuli)")
            ->check(CLI::Range(1u, 1024u));
    }

    CLI::App app;

    // Parses the command line and installs the report handler. Returns an exit status when the
    // program must stop here (--help, a bad option), nothing when it runs.
    std::optional<int> parse(int argc, char* argv[]) {
        try {
            app.parse(argc, argv);
        } catch (const CLI::ParseError& e) {
            return cli_exit(app, e);
        }
        if (random_ > 0 && app.count("--vcd") == 0) no_vcd_ = true;  // 10^7 stimuli make a huge VCD
        if (random_ > 0) {
            std::string csv;
            if (const auto* o = app.get_option_no_throw("--csv"); o != nullptr && o->count() > 0) csv = o->as<std::string>();
            const split_plan plan = plan_split(random_, app.count("--jobs") > 0 ? jobs_ : 0, seed_, inject_,
                                               inject_count_, app.count("--vcd") > 0);
            if (plan.jobs > 1) return run_split(plan, bench_, argc, argv, summary_, csv);
        }
        report_log::install();
        return std::nullopt;
    }

    const std::string& bench() const { return bench_; }
    bool random() const { return random_ > 0; }
    uint64_t random_count() const { return random_; }
    uint64_t seed() const { return seed_; }
    std::size_t inject() const { return inject_; }
    std::size_t inject_count() const { return inject_count_; }
    const std::string& summary_path() const { return summary_; }
    const std::string& mode_name() const { return mode_name_; }
    overflow_mode mode() const { return mode_name_ == "wrap" ? overflow_mode::wrap : overflow_mode::saturate; }
    bool vcd() const { return !no_vcd_; }
    // A default stem chosen after parsing (e.g. by a device choice); --vcd still wins.
    void default_vcd(const std::string& stem) {
        if (app.count("--vcd") == 0) vcd_ = stem;
    }
    const std::string& vcd_stem() const { return vcd_; }

    // Traces the whole bench into the VCD (unless --no-vcd), runs the simulation up to `limit`
    // (or until the stimulus calls sc_stop) and returns whether the stimulus finished.
    template <typename Bench>
    bool simulate(Bench& bench, const sc_core::sc_time& limit = sc_core::sc_time(1, sc_core::SC_SEC)) {
        std::unique_ptr<vcd_file> vcd;
        if (!no_vcd_) {
            const auto dir = std::filesystem::path(vcd_).parent_path();
            if (!dir.empty()) std::filesystem::create_directories(dir);  // traces/ in a fresh tree
            vcd = std::make_unique<vcd_file>(vcd_);
            vcd->trace(bench);
        }
        const auto t0 = std::chrono::steady_clock::now();
        sc_core::sc_start(limit);
        wall_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        vcd.reset();
        finished_ = bench.finished();
        if (!finished_) std::printf("%s: ERROR: the stimulus did not finish within %s\n", bench_.c_str(),
                                    limit.to_string().c_str());
        return finished_;
    }
    double wall_seconds() const { return wall_; }

    void summary(const summary_row& r) const { append_summary(summary_, r); }

    // The random run's figures: printed, and one summary row.
    void report_random(const std::string& case_name, std::size_t samples, std::size_t mismatches,
                       const std::string& unit = "pixels") const {
        const double rate = wall_ > 0 ? static_cast<double>(samples) / wall_ : 0.0;
        std::printf("%s random (%s): %zu samples, %zu mismatches, %.0f %s/s (%.2f s simulated, seed %llu)\n",
                    bench_.c_str(), case_name.c_str(), samples, mismatches, rate, unit.c_str(), wall_,
                    static_cast<unsigned long long>(seed_));
        summary({bench_, case_name, samples, mismatches, "-", "-",
                 "random differential vs golden, seed " + std::to_string(seed_) + ", " + fmt_number(rate, 3) +
                     " " + unit + "/s"});
    }

    // The verdict: 0 only with zero mismatches, zero unexpected reports, a finished stimulus and
    // no failed bench-specific check (`other_failures`); 1 otherwise (never a count: 256 would
    // wrap to 0).
    int finish(std::size_t samples, std::size_t mismatches, std::size_t other_failures = 0) const {
        const unsigned unexpected = report_log::get().unexpected();
        const bool ok = mismatches == 0 && unexpected == 0 && finished_ && other_failures == 0 && samples > 0;
        std::printf("%s: %zu samples, %zu mismatches, %u unexpected reports%s -> %s\n", bench_.c_str(), samples,
                    mismatches, unexpected, other_failures ? ", failed checks" : "", ok ? "PASS" : "FAIL");
        if (!no_vcd_) std::printf("VCD: %s.vcd\n", vcd_.c_str());
        return ok ? 0 : 1;
    }

private:
    std::string bench_, vcd_, summary_, mode_name_ = "saturate";
    bool no_vcd_ = false, finished_ = false;
    uint64_t seed_ = 1, random_ = 0;
    unsigned jobs_ = 1;
    std::size_t inject_ = no_injection, inject_count_ = 1;
    double wall_ = 0.0;
};

}  // namespace shading::tb

// The run and verdict shared by every testbench program (the sc_main of ua60553_tb, ua22802_tb,
// squared_tb, interp_*_tb): one writer of the summary rows (out/summary.tsv, scripts/run.sh), and
// one exit status: 0 only when every sample matched the golden model and SystemC reported nothing
// the bench did not announce. The command line is parsed before, by the program's parse function
// (options/bench_options.h); the runner takes the part common to every bench (common_options.h,
// which lists those options):
//
//   bench_options o = ...;                        // from parse_<program>(argc, argv, ...)
//   bench_runner run("ua60553", o);
//   if (auto rc = run.start(argc, argv)) return *rc;   // a split random run (bench_jobs.h) ends here
#pragma once

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

#include "testbenches/common/bench_jobs.h"
#include "testbenches/common/common_options.h"
#include "testbenches/common/exit_status.h"
#include "testbenches/common/report_log.h"
#include "core/trace.h"
#include "formats/fixed_point.h"

namespace shading::tb {

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
    // `bench` names the program in messages and summary rows; `options` is the parsed command line.
    bench_runner(std::string bench, bench_options options) : bench_(std::move(bench)), o_(std::move(options)) {}

    // Starts the run: a random run split into processes (bench_jobs.h) re-runs this program's own
    // argv and returns the exit status here; otherwise the report handler is installed and the
    // program simulates (nothing returned).
    std::optional<int> start(int argc, char* argv[]) {
        if (o_.random > 0) {
            const split_plan plan = plan_split(o_.random, o_.jobs, o_.seed, o_.inject, o_.inject_count, o_.vcd_given);
            if (plan.jobs > 1) return run_split(plan, bench_, argc, argv, o_.summary, o_.csv);
        }
        report_log::install();
        return std::nullopt;
    }

    const std::string& bench() const { return bench_; }
    bool random() const { return o_.random > 0; }
    uint64_t random_count() const { return o_.random; }
    uint64_t seed() const { return o_.seed; }
    std::size_t inject() const { return o_.inject; }
    std::size_t inject_count() const { return o_.inject_count; }
    const std::string& summary_path() const { return o_.summary; }
    const std::string& mode_name() const { return o_.mode; }
    overflow_mode mode() const { return o_.mode == "wrap" ? overflow_mode::wrap : overflow_mode::saturate; }
    bool vcd() const { return !o_.no_vcd; }
    // A default stem chosen after parsing (e.g. by a device choice); --vcd still wins.
    void default_vcd(const std::string& stem) {
        if (!o_.vcd_given) o_.vcd = stem;
    }
    const std::string& vcd_stem() const { return o_.vcd; }

    // Traces the whole bench into the VCD (unless --no-vcd), runs the simulation up to `limit`
    // (or until the stimulus calls sc_stop) and returns whether the stimulus finished.
    template <typename Bench>
    bool simulate(Bench& bench, const sc_core::sc_time& limit = sc_core::sc_time(1, sc_core::SC_SEC)) {
        std::unique_ptr<vcd_file> vcd;
        if (!o_.no_vcd) {
            const auto dir = std::filesystem::path(o_.vcd).parent_path();
            if (!dir.empty()) std::filesystem::create_directories(dir);  // traces/ in a fresh tree
            vcd = std::make_unique<vcd_file>(o_.vcd);
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

    void summary(const summary_row& r) const { append_summary(o_.summary, r); }

    // The random run's figures: printed, and one summary row.
    void report_random(const std::string& case_name, std::size_t samples, std::size_t mismatches,
                       const std::string& unit = "pixels") const {
        const double rate = wall_ > 0 ? static_cast<double>(samples) / wall_ : 0.0;
        std::printf("%s random (%s): %zu samples, %zu mismatches, %.0f %s/s (%.2f s simulated, seed %llu)\n",
                    bench_.c_str(), case_name.c_str(), samples, mismatches, rate, unit.c_str(), wall_,
                    static_cast<unsigned long long>(o_.seed));
        summary({bench_, case_name, samples, mismatches, "-", "-",
                 "random differential vs golden, seed " + std::to_string(o_.seed) + ", " + fmt_number(rate, 3) +
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
        if (!o_.no_vcd) std::printf("VCD: %s.vcd\n", o_.vcd.c_str());
        return ok ? 0 : 1;
    }

private:
    std::string bench_;
    bench_options o_;
    bool finished_ = false;
    double wall_ = 0.0;
};

}  // namespace shading::tb

// A long random run split into independent processes, for every bench program through
// bench_runner::start: `--random N --jobs J` re-executes the program J times with --jobs 1, child i
// streaming its share of the N stimuli (N / J, the first N % J children one more) with seed
// S + i * 2^32 (child 0 keeps S; no child's seed is another run's small seed), its summary rows
// into a temporary file and its CSV (if the program has --csv and it was given) into <csv>.part<i>.
// A progress line counts the finished processes; then the rows of the same bench and case are
// merged (samples and mismatches summed, the per-process rates summed), appended to the summary,
// the CSV parts concatenated (one header), and the exit status is 0 only when every child exited 0.
// Without --jobs a run of 100 000 stimuli or more uses one process per core; smaller runs, runs
// with an explicit --vcd, and runs whose injected mismatches do not fall in child 0's share stay
// in one process.
#pragma once

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "testbenches/common/child_processes.h"

namespace shading::tb {

inline constexpr uint64_t auto_split_from = 100000;

struct split_plan {
    unsigned jobs = 1;
    uint64_t total = 0, seed = 0;
    std::size_t inject = SIZE_MAX, inject_count = 1;
    uint64_t share(unsigned i) const { return total / jobs + (i < total % jobs ? 1 : 0); }
    uint64_t seed_of(unsigned i) const { return seed + (static_cast<uint64_t>(i) << 32); }
};

// requested_jobs 0: not given on the command line.
inline split_plan plan_split(uint64_t total, unsigned requested_jobs, uint64_t seed, std::size_t inject,
                             std::size_t inject_count, bool explicit_vcd) {
    split_plan p;
    p.total = total;
    p.seed = seed;
    p.inject = inject;
    p.inject_count = inject_count;
    unsigned j = requested_jobs;
    if (j == 0) j = total >= auto_split_from ? std::max(1u, std::thread::hardware_concurrency()) : 1;
    if (explicit_vcd) j = 1;
    j = static_cast<unsigned>(std::min<uint64_t>(j, total));
    p.jobs = std::max(1u, j);
    if (inject != SIZE_MAX && inject + inject_count > p.share(0)) p.jobs = 1;
    return p;
}

namespace detail {

// Drops `--name value` and `--name=value` for the options the split sets itself.
inline std::vector<std::string> child_args(int argc, char* argv[], const std::vector<std::string>& drop) {
    std::vector<std::string> out;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        bool dropped = false;
        for (const auto& d : drop) {
            if (a == d) {
                ++i;  // its value
                dropped = true;
            } else if (a.rfind(d + "=", 0) == 0) {
                dropped = true;
            }
        }
        if (!dropped) out.push_back(a);
    }
    return out;
}

inline std::vector<std::vector<std::string>> read_tsv(const std::string& path) {
    std::vector<std::vector<std::string>> rows;
    std::ifstream f(path);
    for (std::string line; std::getline(f, line);) {
        std::vector<std::string> cols;
        std::stringstream ss(line);
        for (std::string c; std::getline(ss, c, '\t');) cols.push_back(c);
        if (cols.size() >= 7) rows.push_back(cols);
    }
    return rows;
}

// "..., 1.97e+05 pixels/s" -> rate and unit.
inline bool note_rate(const std::string& note, double& rate, std::string& unit) {
    const auto comma = note.rfind(", ");
    if (comma == std::string::npos) return false;
    std::istringstream is(note.substr(comma + 2));
    if (!(is >> rate >> unit)) return false;
    return unit.size() > 2 && unit.compare(unit.size() - 2, 2, "/s") == 0;
}

// Child i's command line: the program's own arguments less those the split sets, then its share,
// its seed, its summary file, child 0's injected mismatches, and its part of the CSV.
inline child_spec split_child(const split_plan& plan, const std::filesystem::path& dir, const char* argv0,
                              const std::vector<std::string>& common, const std::string& csv, std::size_t i) {
    child_spec c{"/proc/self/exe", {argv0}, (dir / ("out" + std::to_string(i))).string()};
    auto& args = c.args;
    args.insert(args.end(), common.begin(), common.end());
    args.insert(args.end(), {"--jobs", "1", "--random", std::to_string(plan.share(i)), "--seed",
                             std::to_string(plan.seed_of(i)), "--summary", (dir / ("rows" + std::to_string(i))).string()});
    if (i == 0 && plan.inject != SIZE_MAX) {
        args.insert(args.end(), {"--inject-mismatch", std::to_string(plan.inject), "--inject-count",
                                 std::to_string(plan.inject_count)});
    }
    if (!csv.empty()) args.insert(args.end(), {"--csv", csv + ".part" + std::to_string(i)});
    return c;
}

// The rows of one bench and case, summed over the processes.
struct merged_row {
    std::vector<std::string> row;
    uint64_t samples = 0, mismatches = 0;
    double rate = 0;
    std::string unit;
    unsigned processes = 0;
};

// The children's summary rows merged by bench and case, keys in first-seen order; a child that
// failed has its output printed and makes `ok` false.
struct merged_rows {
    std::vector<std::string> order;
    std::map<std::string, merged_row> rows;
    bool ok = true;
};

inline merged_rows merge_children(const split_plan& plan, const std::string& bench, const std::filesystem::path& dir,
                                  const std::vector<int>& status) {
    merged_rows out;
    for (unsigned i = 0; i < plan.jobs; ++i) {
        if (status[i] != 0) {
            out.ok = false;
            std::printf("%s: process %u (seed %llu) exited with status %d; its output:\n", bench.c_str(), i,
                        static_cast<unsigned long long>(plan.seed_of(i)), status[i]);
            std::ifstream f(dir / ("out" + std::to_string(i)));
            std::cout << f.rdbuf();
        }
        for (const auto& r : read_tsv((dir / ("rows" + std::to_string(i))).string())) {
            const std::string key = r[0] + '\t' + r[1];
            auto [it, fresh] = out.rows.try_emplace(key);
            if (fresh) {
                out.order.push_back(key);
                it->second.row = r;
            }
            auto& m = it->second;
            m.samples += std::strtoull(r[2].c_str(), nullptr, 10);
            m.mismatches += std::strtoull(r[3].c_str(), nullptr, 10);
            double rate = 0;
            std::string unit;
            if (note_rate(r[6], rate, unit)) {
                m.rate += rate;
                m.unit = unit;
            }
            ++m.processes;
        }
    }
    return out;
}

// One merged row printed and appended to the summary (when one is written).
inline void report_merged(merged_row& m, const split_plan& plan, const std::string& bench, double wall,
                          const std::string& summary) {
    std::ostringstream note;
    note << "random differential vs golden, " << m.processes << " processes, seeds " << plan.seed << " + i*2^32";
    if (!m.unit.empty()) note << ", " << std::setprecision(3) << m.rate << ' ' << m.unit << " summed";
    std::printf("%s random (%s): %llu samples, %llu mismatches, %u processes, %.4g %s summed over the "
                "processes, %.2f s wall\n",
                bench.c_str(), m.row[1].c_str(), static_cast<unsigned long long>(m.samples),
                static_cast<unsigned long long>(m.mismatches), m.processes, m.rate,
                m.unit.empty() ? "/s" : m.unit.c_str(), wall);
    m.row[2] = std::to_string(m.samples);
    m.row[3] = std::to_string(m.mismatches);
    m.row[6] = note.str();
    if (!summary.empty()) {
        std::ofstream f(summary, std::ios::app);
        for (std::size_t c = 0; c < m.row.size(); ++c) f << (c ? "\t" : "") << m.row[c];
        f << '\n';
    }
}

// One CSV: the parts in order, the header once; the parts removed.
inline void join_csv_parts(const std::string& csv, unsigned jobs) {
    std::ofstream out(csv);
    for (unsigned i = 0; i < jobs; ++i) {
        const std::string part = csv + ".part" + std::to_string(i);
        std::ifstream f(part);
        std::string line;
        for (bool first = true; std::getline(f, line); first = false)
            if (i == 0 || !first) out << line << '\n';
        std::error_code ignored;
        std::filesystem::remove(part, ignored);
    }
}

}  // namespace detail

// Runs the split; returns the exit status the program returns.
inline int run_split(const split_plan& plan, const std::string& bench, int argc, char* argv[],
                     const std::string& summary, const std::string& csv) {
    namespace fs = std::filesystem;
    std::string tmpl = (fs::temp_directory_path() / (bench + "_jobs.XXXXXX")).string();
    if (mkdtemp(tmpl.data()) == nullptr) {
        std::fprintf(stderr, "%s: cannot create a temporary folder for the split run\n", bench.c_str());
        return 1;
    }
    const fs::path dir = tmpl;
    const auto common = detail::child_args(
        argc, argv, {"--jobs", "--random", "--seed", "--summary", "--inject-mismatch", "--inject-count", "--csv"});
    const auto t0 = std::chrono::steady_clock::now();
    std::printf("%s: %llu random stimuli in %u processes (seed %llu, process i: seed + i*2^32)\n", bench.c_str(),
                static_cast<unsigned long long>(plan.total), plan.jobs, static_cast<unsigned long long>(plan.seed));
    std::fflush(stdout);
    auto spec = [&](std::size_t i) { return detail::split_child(plan, dir, argv[0], common, csv, i); };
    // Progress: one line, rewritten on a terminal, as processes finish.
    const bool tty = isatty(STDERR_FILENO) != 0;
    unsigned done = 0;
    const std::vector<int> status = run_children(plan.jobs, plan.jobs, spec, [&](std::size_t, int) {
        ++done;
        const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        std::fprintf(stderr, "%s%s: %u/%u processes done, %.1f s%s", tty ? "\r" : "", bench.c_str(), done, plan.jobs, s,
                     tty && done < plan.jobs ? "" : "\n");
    });
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    auto merged = detail::merge_children(plan, bench, dir, status);
    uint64_t samples = 0, mismatches = 0;
    for (const auto& key : merged.order) {
        auto& m = merged.rows[key];
        samples += m.samples;
        mismatches += m.mismatches;
        detail::report_merged(m, plan, bench, wall, summary);
    }
    if (!csv.empty()) detail::join_csv_parts(csv, plan.jobs);
    std::error_code ignored;
    fs::remove_all(dir, ignored);
    const bool ok = merged.ok && samples > 0 && mismatches == 0;
    std::printf("%s: %llu samples, %llu mismatches in %u processes -> %s\n", bench.c_str(),
                static_cast<unsigned long long>(samples), static_cast<unsigned long long>(mismatches), plan.jobs,
                ok ? "PASS" : "FAIL");
    return ok ? 0 : 1;
}

}  // namespace shading::tb

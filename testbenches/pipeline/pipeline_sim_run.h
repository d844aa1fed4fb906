// The simulation run behind simulate_frame() (pipeline_sim.cpp), one translation unit per evaluator
// (pipeline_sim_horner.cpp, pipeline_sim_fd.cpp) so the two pipelines compile in parallel.
#pragma once

#include <algorithm>
#include <chrono>
#include <ctime>
#include <filesystem>
#include <memory>
#include <string>

#include "core/report_ids.h"
#include "core/trace.h"
#include "pipeline_bench.h"
#include "pipeline_sim.h"
#include "pipeline_tops.h"
#include "tuned/a_gen_tuned.h"
#include "ua22802/a_gen_rom.h"
#include "ua60553/a_gen_linear.h"
#include "sqmul/sqmul_device.h"
#include "squared/squared_device.h"

namespace shading::pipeline::sim_detail {


// This process's CPU time (user + system): on a shared machine the simulator's speed, where wall
// time also counts the other processes.
inline double cpu_seconds() {
    timespec ts{};
    ::clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

// A watchdog far beyond any plan: 24 clocks per job and per sample (the square-and-multiply device's
// floor(log2 n) + popcount(n) + 4 <= 23 clocks per sample), 6 per pixel, and the frame load.
inline sc_core::sc_time time_limit(const plan& p) {
    uint64_t clocks = 100;
    for (const auto& j : p.jobs) clocks += 24 + 24 * 4 + 6ull * std::min(j.len, 64u);
    return pipeline_period() * static_cast<double>(clocks);
}

template <class AGen, evaluator EVAL, bool FAST = false>
sim_result run(const plan& p, const frame_constants& k, const scene::device_config& dev, const plan_config& c,
               const typename AGen::config& gen, const sim_options& o) {
    sim_result res;
    res.period_ns = pipeline_period().to_seconds() * 1e9;
    res.f = empty_frame(p.width, p.height);
    auto bench = std::make_unique<pipeline_bench<AGen, EVAL, FAST>>("tb", p, k, dev, c, gen, o.progress, o.others_done);
    bench->checker.inject_mismatch(o.inject_mismatch);
    bench->checker.keep_order(o.keep_write_order);
    std::unique_ptr<vcd_file> vcd;
    if (!o.vcd_path.empty()) {
        std::string path = o.vcd_path;
        if (path.size() > 4 && path.compare(path.size() - 4, 4, ".vcd") == 0) path.resize(path.size() - 4);
        // Its folder is created if missing (as SHADING_TRACE's, core/trace.h); if that fails, SystemC's
        // own error for the unopenable file names the path.
        std::error_code ignored;
        if (const auto dir = std::filesystem::path(path).parent_path(); !dir.empty())
            std::filesystem::create_directories(dir, ignored);
        vcd = std::make_unique<vcd_file>(path);
        vcd->trace(*bench);
    }
    const auto t0 = std::chrono::steady_clock::now();
    const double c0 = cpu_seconds();
    sc_core::sc_start(std::max(time_limit(p), sc_core::sc_time(o.at_least_ns, sc_core::SC_NS)));
    res.cpu_seconds = cpu_seconds() - c0;
    res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (!bench->finished()) {
        SC_REPORT_WARNING(msg::mismatch, "simulate_frame: the pipeline did not drain within the watchdog's time");
    }
    bench->checker.finish();
    res.mismatches = bench->checker.mismatches();
    res.write_order = bench->checker.order();
    res.jobs_dropped = bench->checker.dropped();
    res.samples_formed = bench->dut.samples();
    res.samples_carried = bench->dut.carried();
    res.clocks = static_cast<uint64_t>(bench->last_write() / pipeline_period());
    res.frame_load_clocks = bench->src.frame_loaded_at_edge();
    for (const auto& j : p.jobs) {
        const uint8_t degree = j.m == 0 ? 1 : (j.deg2 ? 2 : 3);
        for (unsigned i = 0; i < j.len; ++i) {
            const unsigned x = j.x0 + i;
            if (x >= p.width || j.y >= p.height) continue;
            if (!bench->fb.written(x, j.y)) continue;
            const std::size_t at = std::size_t(j.y) * p.width + x;
            res.f.degree[at] = degree;
            res.f.log2_len[at] = static_cast<uint8_t>(j.m);
            res.f.zone[at] = j.zone;
        }
    }
    for (unsigned yy = 0; yy < p.height; ++yy)
        for (unsigned xx = 0; xx < p.width; ++xx) {
            if (!bench->fb.written(xx, yy)) continue;
            const std::size_t at = std::size_t(yy) * p.width + xx;
            const auto& v = bench->fb.pixel(xx, yy);
            res.f.px[at] = {v[0], v[1], v[2]};
            res.f.covered[at] = 1;
        }
    // The bench stays elaborated (SystemC cannot tear a design down): released with the process.
    bench.release();
    return res;
}

// The fast abstraction's run (pipeline_sim_fast.cpp; it names the device by dev, no generator type).
template <evaluator EVAL>
sim_result run_fast(const plan& p, const frame_constants& k, const scene::device_config& dev, const plan_config& c,
                    const sim_options& o);

template <evaluator EVAL>
inline sim_result run_device(const plan& p, const frame_constants& k, const scene::device_config& dev, const plan_config& c,
                      const sim_options& o) {
    if (o.level == abstraction::fast) return run_fast<EVAL>(p, k, dev, c, o);
    switch (dev.device) {
        case scene::specular_device::patent: return run<a_gen_linear, EVAL>(p, k, dev, c, ua60553::patent, o);
        case scene::specular_device::minimax: return run<a_gen_tuned, EVAL>(p, k, dev, c, ua60553::minimax, o);
        case scene::specular_device::rom_matched:
            return run<a_gen_tuned, EVAL>(p, k, dev, c, ua60553::rom_matched, o);
        case scene::specular_device::ua22802:
            return run<a_gen_rom, EVAL>(p, k, dev, c, a_gen_rom::default_config(), o);
        case scene::specular_device::squared:
            return run<squared_device, EVAL>(p, k, dev, c, squared_device::default_config(), o);
        case scene::specular_device::sqmul:
            return run<sqmul_device, EVAL>(p, k, dev, c, sqmul_device::default_config(), o);
    }
    return {};
}

// Each evaluator's runs are compiled in their own translation unit, the fast ones in a third.
extern template sim_result run_fast<evaluator::horner>(const plan&, const frame_constants&, const scene::device_config&,
                                                        const plan_config&, const sim_options&);
extern template sim_result run_fast<evaluator::fd>(const plan&, const frame_constants&, const scene::device_config&,
                                                    const plan_config&, const sim_options&);
extern template sim_result run_device<evaluator::horner>(const plan&, const frame_constants&, const scene::device_config&,
                                                          const plan_config&, const sim_options&);
extern template sim_result run_device<evaluator::fd>(const plan&, const frame_constants&, const scene::device_config&,
                                                      const plan_config&, const sim_options&);

}  // namespace shading::pipeline::sim_detail

// The SystemC shading pipeline (modules/pipeline/shading_pipeline.h) run over a planned frame, for
// the render program and the tests. One elaboration per process: simulate_frame() may be called
// once (SystemC cannot elaborate twice); a second call reports shading/config and returns an empty
// frame with every pixel counted as a mismatch.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "interp/abstraction.h"
#include "golden_pipeline/pipeline.h"

namespace shading::pipeline {

struct sim_options {
    // block: shading_pipeline<AGen, EVAL> (every block of the figures); fast: shading_pipeline_fast
    // (the same pins and timing at them, one process; modules/pipeline/shading_pipeline_fast.h).
    shading::abstraction level = shading::abstraction::block;
    std::string vcd_path;  // empty: no trace; else a VCD there (".vcd" appended unless given)
    std::function<void(std::size_t done, std::size_t total)> progress;  // pixels written / expected
    // For the tests of the verdict: the golden codes of the k-th pixel written are corrupted (one
    // LSB of R), so the checker must count exactly one mismatch.
    std::size_t inject_mismatch = SIZE_MAX;
    // sim_result::write_order is filled (8 bytes per write); off for long runs (soak_pipeline),
    // whose memory would otherwise grow with the log.
    bool keep_write_order = true;
    // A unit simulated beside the pipeline (the cell unit, cell_unit_bench.h): the simulation stops
    // when the pipeline has drained and others_done() holds, and the watchdog allows at least
    // at_least_ns.
    std::function<bool()> others_done;
    double at_least_ns = 0.0;
};

struct sim_result {
    frame f;                     // the frame buffer's content (covered = written)
    uint64_t clocks = 0;         // clock cycles from the first rising edge to the last pixel's write
    double seconds = 0.0;        // wall time of the simulation (elaboration excluded)
    double cpu_seconds = 0.0;    // the process's CPU time over the same span (the speed on a shared machine)
    std::size_t mismatches = 0;  // pixels that differ from golden_interval, or missing, or unexpected
    // For the tests.
    std::vector<std::size_t> write_order;  // frame index of every frame-buffer write, in order (keep_write_order)
    std::size_t jobs_dropped = 0;          // jobs the hardware refused (bad input, reported)
    std::size_t samples_formed = 0;        // colour samples the device formed
    std::size_t samples_carried = 0;       // colour samples taken from the last-sample registers (carry)
    uint64_t frame_load_clocks = 0;        // clocks until the frame constants were latched
    double period_ns = 0.0;                // the clock period
};

// Elaborates the pipeline for dev.device (patent, minimax, rom_matched, ua22802) and c.eval (the
// forward differences built for c.m with c.length fixed, or for any m per interval, fd_eval_var, with
// c.length adaptive), c.set and c.div, runs every job of p, returns the frame
// buffer's content, the clocks taken, wall time, and the mismatches against golden_interval.
sim_result simulate_frame(const plan& p, const frame_constants& k, const scene::device_config& dev,
                          const plan_config& c, const sim_options& o = {});

// The clock period of the simulated pipeline.
double sim_period_ns();

}  // namespace shading::pipeline

// Testbench of the cell unit (modules/pipeline/cell_unit.h) in three parts, for its GoogleTest suite:
//   cell_stimulus  drives the handshake: at a falling edge the cell's pins and start = 1; start = 0
//                  once ready has fallen; the next cell once ready has risen again
//   frame_buffer   the monitor: samples the pixel stream at the rising edges where px_valid = 1
//   cell_checker   compares every write with the golden model's pixel there (cell_pixels, forward
//                  differences), counts mismatches and pixels written twice or never, and records
//                  each cell's first and last write (the streaming rate)
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <sstream>
#include <string>
#include <systemc>
#include <vector>

#include "core/report_ids.h"
#include "golden_pipeline/cells.h"
#include "pipeline/cell_unit.h"
#include "pipeline/frame_buffer.h"
#include "pipeline_sim.h"
#include "scene/raster.h"
#include "scene/shade.h"
#include "scene/world.h"

namespace shading::tb {

// One cell as the geometry side hands it over: its corner, m (s = 2^m) and lattice colours.
struct cell_input {
    unsigned x0 = 0, y0 = 0, m = 2;
    std::array<pipeline::rgb_codes, 9> lattice{};
};

inline sc_core::sc_time cell_period() { return sc_core::sc_time(20, sc_core::SC_NS); }

class cell_stimulus : public sc_core::sc_module {
public:
    sc_core::sc_in<bool> clk{"clk"}, ready{"ready"};
    sc_core::sc_out<bool> start{"start"};
    sc_core::sc_out<cell_unit::coord_t> x0{"x0"}, y0{"y0"};
    sc_core::sc_out<cell_unit::m_t> m{"m"};
    sc_core::sc_vector<sc_core::sc_out<pipeline::sample_t>> lat_r{"lat_r", 9}, lat_g{"lat_g", 9}, lat_b{"lat_b", 9};

    SC_HAS_PROCESS(cell_stimulus);
    cell_stimulus(const sc_core::sc_module_name& name, std::vector<cell_input> cells)
        : sc_module(name), cells_(std::move(cells)) {
        SC_THREAD(run);
    }
    bool finished() const { return finished_; }

private:
    void run() {
        for (const cell_input& c : cells_) {
            wait(clk.negedge_event());
            while (!ready.read()) wait(clk.negedge_event());
            x0.write(c.x0);
            y0.write(c.y0);
            m.write(c.m);
            for (std::size_t i = 0; i < 9; ++i) {
                lat_r[i].write(c.lattice[i][0]);
                lat_g[i].write(c.lattice[i][1]);
                lat_b[i].write(c.lattice[i][2]);
            }
            start.write(true);
            do wait(clk.negedge_event());
            while (ready.read());
            start.write(false);
        }
        wait(clk.negedge_event());
        while (!ready.read()) wait(clk.negedge_event());
        finished_ = true;
    }

    std::vector<cell_input> cells_;
    bool finished_ = false;
};

// The golden pixels of every cell, placed in a width x height frame; the checker compares the
// frame buffer's writes with them as they come.
class cell_checker {
public:
    cell_checker(const std::vector<cell_input>& cells, unsigned width, unsigned height)
        : width_(width), want_(std::size_t(width) * height), cell_of_(std::size_t(width) * height, -1),
          first_(cells.size()), last_(cells.size()) {
        for (std::size_t k = 0; k < cells.size(); ++k) {
            const cell_input& c = cells[k];
            // A size outside m_min .. m_max is taken as the nearest (cell_ctrl's rule for bad input).
            const unsigned s = 1u << std::clamp(c.m, interp::m_min, interp::m_max);
            const auto px = pipeline::cell_pixels(c.lattice, s, pipeline::evaluator::fd);
            for (unsigned y = 0; y < s; ++y)
                for (unsigned x = 0; x < s; ++x) {
                    const std::size_t at = std::size_t(c.y0 + y) * width + c.x0 + x;
                    want_.at(at) = px[std::size_t(y) * s + x];
                    cell_of_.at(at) = int(k);
                }
        }
    }
    void on_write(unsigned x, unsigned y, const frame_buffer::rgb& v) {
        const std::size_t at = std::size_t(y) * width_ + x;
        const int k = cell_of_.at(at);
        const uint64_t edge = static_cast<uint64_t>(sc_core::sc_time_stamp() / cell_period());
        if (k < 0) {
            ++stray_;
            return;
        }
        if (!first_[std::size_t(k)]) first_[std::size_t(k)] = edge;
        last_[std::size_t(k)] = edge;
        last_edge_ = std::max(last_edge_, edge);
        const pipeline::rgb_codes& w = want_[at];
        if (v[0] != w[0] || v[1] != w[1] || v[2] != w[2]) {
            if (mismatches_++ < 5) {
                std::ostringstream m;
                m << "cell unit: pixel (" << x << ", " << y << ") is " << v[0] << ", " << v[1] << ", " << v[2]
                  << "; the golden model's " << w[0] << ", " << w[1] << ", " << w[2];
                SC_REPORT_WARNING(msg::mismatch, m.str().c_str());
            }
        }
    }
    // Pixels of a cell the frame buffer wrote other than once.
    std::size_t not_once(const frame_buffer& fb) const {
        std::size_t n = 0;
        for (std::size_t at = 0; at < cell_of_.size(); ++at)
            if (cell_of_[at] >= 0 && fb.written(unsigned(at % width_), unsigned(at / width_)) != 1) ++n;
        return n;
    }
    std::size_t mismatches() const { return mismatches_; }
    uint64_t last_edge() const { return last_edge_; }  // the clock edge of the last write
    std::size_t stray() const { return stray_; }
    // Clocks from the cell's first pixel to its last (s^2 - 1 when its rows stream back to back).
    std::optional<uint64_t> span(std::size_t k) const {
        if (!first_.at(k)) return std::nullopt;
        return *last_.at(k) - *first_.at(k);
    }

private:
    unsigned width_;
    std::vector<pipeline::rgb_codes> want_;
    std::vector<int> cell_of_;
    std::vector<std::optional<uint64_t>> first_, last_;
    std::size_t mismatches_ = 0, stray_ = 0;
    uint64_t last_edge_ = 0;
};

class cell_unit_bench : public sc_core::sc_module {
public:
    sc_core::sc_clock clk{"clk", cell_period()};
    sc_core::sc_signal<bool> start{"start"}, ready{"ready"}, px_valid{"px_valid"};
    sc_core::sc_signal<cell_unit::coord_t> x0{"x0"}, y0{"y0"}, px_x{"px_x"}, px_y{"px_y"};
    sc_core::sc_signal<cell_unit::m_t> m{"m"};
    sc_core::sc_vector<sc_core::sc_signal<pipeline::sample_t>> lat_r{"lat_r", 9}, lat_g{"lat_g", 9}, lat_b{"lat_b", 9};
    sc_core::sc_signal<pipeline::sample_t> px_r{"px_r"}, px_g{"px_g"}, px_b{"px_b"};

    cell_stimulus src;
    cell_unit dut{"dut"};
    frame_buffer fb;
    cell_checker checker;

    cell_unit_bench(const sc_core::sc_module_name& name, const std::vector<cell_input>& cells, unsigned width,
                    unsigned height)
        : sc_module(name), src("src", cells), fb("fb", width, height), checker(cells, width, height) {
        src.clk(clk); src.ready(ready); src.start(start); src.x0(x0); src.y0(y0); src.m(m);
        dut.clk(clk); dut.start(start); dut.ready(ready); dut.in_x0(x0); dut.in_y0(y0); dut.in_m(m);
        for (std::size_t i = 0; i < 9; ++i) {
            src.lat_r[i](lat_r[i]); src.lat_g[i](lat_g[i]); src.lat_b[i](lat_b[i]);
            dut.in_lat_r[i](lat_r[i]); dut.in_lat_g[i](lat_g[i]); dut.in_lat_b[i](lat_b[i]);
        }
        dut.px_valid(px_valid); dut.px_x(px_x); dut.px_y(px_y); dut.px_r(px_r); dut.px_g(px_g); dut.px_b(px_b);
        fb.clk(clk); fb.valid(px_valid); fb.x(px_x); fb.y(px_y); fb.r(px_r); fb.g(px_g); fb.b(px_b);
        fb.on_write([this](unsigned x, unsigned y, const frame_buffer::rgb& v) { checker.on_write(x, y, v); });
    }
    bool finished() const { return src.finished(); }
};

// The cells of a plan as the geometry side hands them to the unit: the lattice colours the sample
// stage forms (cell_lattice_colours).
inline std::vector<cell_input> cell_inputs(const pipeline::cell_plan& p, const pipeline::frame_constants& k,
                                           const scene::device_config& dev) {
    std::vector<cell_input> out;
    for (const pipeline::cell_job& j : p.cells) {
        cell_input c;
        c.x0 = j.x0;
        c.y0 = j.y0;
        while ((1u << c.m) < j.s) ++c.m;
        c.lattice = pipeline::cell_lattice_colours(j, k, dev);
        out.push_back(c);
    }
    return out;
}

// The head at size x size with the squared device (its scene read from source_dir), planned into
// cells (forward differences; the pipeline's channel built for any m per interval, as simulate_frame
// takes the rest): test_cell_unit's and test_rtl_cell_unit's real cells.
struct head_cells {
    head_cells(unsigned size, const std::string& source_dir)
        : w(scene::builtin_scene("head", source_dir, size, size)), r(scene::rasterise(w)),
          k(pipeline::frame_constants_of(w)) {
        dev.device = scene::parse_device("squared");
        c.eval = pipeline::evaluator::fd;
        c.length = pipeline::length_policy::adaptive;
        p = pipeline::make_cell_plan(r, k, dev, c, pipeline::cell_config{});
    }
    scene::world w;
    scene::rasterised r;  // points at w
    pipeline::frame_constants k;
    scene::device_config dev;
    pipeline::plan_config c;
    pipeline::cell_plan p;
};

// The scheme's whole frame in SystemC (one elaboration: call once per process): the plan's cells
// through the cell unit, its intervals and the cells' points through the shading pipeline
// (pipeline_plan; c as simulate_frame takes it), the pipeline's frame buffer over the cell unit's,
// compared code for code with golden_cell_frame.
struct cells_run {
    pipeline::frame f;                  // the composed frame
    std::size_t differ = 0;             // covered pixels not the golden model's (or delivered by neither)
    std::size_t stray = 0;              // uncovered pixels written
    std::size_t unit_mismatches = 0, pipeline_mismatches = 0;  // each bench's own checker
    uint64_t unit_clocks = 0, pipeline_clocks = 0;
    bool finished = false;
};
inline cells_run simulate_cells(const scene::rasterised& r, const pipeline::cell_plan& p,
                                const pipeline::frame_constants& k, const scene::device_config& dev,
                                const pipeline::plan_config& c) {
    const std::vector<cell_input> cells = cell_inputs(p, k, dev);
    uint64_t clocks = 100;
    for (const cell_input& ci : cells) clocks += 2 * ((1ull << (2 * ci.m)) + (1ull << ci.m) + 16);
    auto* unit = new cell_unit_bench("cells", cells, r.width, r.height);  // elaborated with the pipeline's
    // The pipeline's bench stops the simulation: not before the cell unit has finished too.
    pipeline::sim_options o;
    o.others_done = [unit] { return unit->finished(); };
    o.at_least_ns = cell_period().to_seconds() * 1e9 * double(clocks);
    const pipeline::sim_result res = pipeline::simulate_frame(pipeline::pipeline_plan(p), k, dev, c, o);
    cells_run out;
    out.finished = unit->finished();
    out.unit_mismatches = unit->checker.mismatches() + unit->checker.not_once(unit->fb) + unit->checker.stray();
    out.pipeline_mismatches = res.mismatches;
    out.unit_clocks = unit->checker.last_edge();
    out.pipeline_clocks = res.clocks;
    const pipeline::frame g = pipeline::golden_cell_frame(p, k, dev, c);
    const pipeline::frame piped = pipeline::cells_frame_of(p, res.f);  // the column jobs' part folded back
    out.f = g;
    for (unsigned y = 0; y < r.height; ++y)
        for (unsigned x = 0; x < r.width; ++x) {
            const std::size_t at = r.index(x, y);
            const bool by_unit = unit->fb.written(x, y) != 0, by_pipe = piped.covered[at] != 0;
            if (!r.covered(x, y)) {
                out.stray += by_unit || by_pipe;
                continue;
            }
            pipeline::rgb_codes v{};
            if (by_pipe) {
                v = piped.px[at];
            } else if (by_unit) {
                const auto& u = unit->fb.pixel(x, y);
                v = {u[0], u[1], u[2]};
            } else {
                ++out.differ;  // delivered by neither
                continue;
            }
            out.differ += v != g.px[at];
            out.f.px[at] = v;
        }
    return out;  // the benches stay elaborated: SystemC cannot tear a design down
}

}  // namespace shading::tb

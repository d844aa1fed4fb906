// A virtual platform built against the installed package only (shading::tlm, shading::pipeline): a
// traffic generator standing in for the CPU and the geometry side, a router, specular TLM wrappers
// (UA 60553 and the squared-quadratic device, ours) and raster-line unit wrappers, each loosely
// timed and pin-accurate, and a frame-buffer memory. The generator rasterises the head scan
// (installed with its attribution under SHADING_DATA_DIR, "Infinite, 3D Head Scan" by Lee
// Perry-Smith, CC BY 3.0) and takes the raster line of the face (the middle half of the frame)
// with the most highlight. Per specular wrapper: the line's N.H codes in one COS_BLOCK burst write,
// the R, G, B out of one RESULT_BLOCK burst read, checked against the device's golden model
// (golden_ua60553, golden_squared). Per raster-line wrapper: the interpolation paper's plan of the
// line (fixed m = 5, cubic, forward differences), each channel's interval samples (the sample
// stage, golden_sample) in one INTERVAL_BLOCK burst, the pixels out of one PIXEL_BLOCK read,
// clamped to the pixel format and checked against pipeline::golden_interval. Every line goes into
// the frame buffer by one burst write and is read back; both timing modes of each wrapper must
// agree on data and on time (the squared device's lines start on its 20 ns clock's rising edge,
// as a CPU on that clock would, since its time depends on the clock's phase).
// Exits 0 only if all of it held and SystemC reported no warning.
#include <array>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>
#include <systemc>
#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>
#include <tlm_utils/simple_target_socket.h>

#include "arith/specular_arith.h"  // shading::floor: golden_ua60553
#include "arith/squared_arith.h"   // shading::floor: golden_squared
#include "golden_pipeline/pipeline.h"        // shading::pipeline: frame constants, sample stage, plan, golden_interval
#include "scene/raster.h"             // shading::scene: the rasteriser
#include "scene/world.h"              // shading::scene: the head scene
#include "tlm/line_tlm.h"             // shading::tlm
#include "tlm/specular_tlm.h"         // shading::tlm

#ifndef SHADING_DATA_DIR
#error "SHADING_DATA_DIR: the package's data root (find_package(shading) sets it; CMakeLists.txt passes it)"
#endif

using sc_core::sc_time;
using sc_core::SC_NS;
using sc_core::SC_ZERO_TIME;

// Address map of the platform.
constexpr uint64_t SHADE_LT = 0x40000000, SHADE_PA = 0x40010000, SHADE_SIZE = 0x10000;
constexpr uint64_t SQUARED_LT = 0x40020000, SQUARED_PA = 0x40030000;
constexpr uint64_t LINE_LT = 0x41000000, LINE_PA = 0x41020000, LINE_SIZE = 0x20000;
constexpr uint64_t FB = 0x80000000, FB_SIZE = 0x10000;
constexpr unsigned PIXELS = 256;  // the frame is PIXELS x PIXELS
constexpr unsigned M = 5;         // the raster-line unit's intervals: 2^5 pixels
using line_unit = shading::line_tlm<M, shading::interp::sample_set::case1, shading::interp::div3_mode::shift_add>;

// A frame buffer: plain memory behind a target socket.
struct frame_buffer : sc_core::sc_module {
    tlm_utils::simple_target_socket<frame_buffer> socket{"socket"};
    std::vector<unsigned char> mem = std::vector<unsigned char>(FB_SIZE);
    explicit frame_buffer(const sc_core::sc_module_name& name) : sc_module(name) {
        socket.register_b_transport(this, &frame_buffer::b_transport);
    }
    void b_transport(tlm::tlm_generic_payload& p, sc_time& delay) {
        if (p.get_address() + p.get_data_length() > mem.size() || p.get_byte_enable_ptr()) {
            p.set_response_status(tlm::TLM_ADDRESS_ERROR_RESPONSE);
            return;
        }
        unsigned char* at = mem.data() + p.get_address();
        if (p.is_write()) std::memcpy(at, p.get_data_ptr(), p.get_data_length());
        if (p.is_read()) std::memcpy(p.get_data_ptr(), at, p.get_data_length());
        delay += sc_time(10, SC_NS);  // one access of a plain SRAM
        p.set_response_status(tlm::TLM_OK_RESPONSE);
    }
};

// A router: one target socket for the initiator, one initiator socket per region.
struct router : sc_core::sc_module {
    struct region { uint64_t base, size; };
    tlm_utils::simple_target_socket<router> socket{"socket"};
    using to = tlm_utils::simple_initiator_socket<router>;
    std::array<to, 7> out{to{"to_shade_lt"}, to{"to_shade_pa"}, to{"to_squared_lt"}, to{"to_squared_pa"},
                          to{"to_line_lt"},  to{"to_line_pa"},  to{"to_fb"}};
    std::array<region, 7> map{{{SHADE_LT, SHADE_SIZE}, {SHADE_PA, SHADE_SIZE}, {SQUARED_LT, SHADE_SIZE},
                               {SQUARED_PA, SHADE_SIZE}, {LINE_LT, LINE_SIZE}, {LINE_PA, LINE_SIZE}, {FB, FB_SIZE}}};
    explicit router(const sc_core::sc_module_name& name) : sc_module(name) {
        socket.register_b_transport(this, &router::b_transport);
    }
    void b_transport(tlm::tlm_generic_payload& p, sc_time& delay) {
        const uint64_t a = p.get_address();
        for (std::size_t i = 0; i < map.size(); ++i)
            if (a >= map[i].base && a < map[i].base + map[i].size) {
                p.set_address(a - map[i].base);
                out[i]->b_transport(p, delay);
                p.set_address(a);
                return;
            }
        p.set_response_status(tlm::TLM_ADDRESS_ERROR_RESPONSE);
    }
};

// The traffic generator: a CPU (or a rasteriser's back end) shading one line per wrapper.
struct traffic_generator : sc_core::sc_module {
    tlm_utils::simple_initiator_socket<traffic_generator> socket{"socket"};
    unsigned errors = 0, checked = 0;
    SC_HAS_PROCESS(traffic_generator);
    explicit traffic_generator(const sc_core::sc_module_name& name) : sc_module(name) { SC_THREAD(run); }

    // One blocking access; the annotated delay is consumed at once (no temporal decoupling here).
    void access(tlm::tlm_command cmd, uint64_t addr, void* data, unsigned len) {
        tlm::tlm_generic_payload p;
        sc_time delay = SC_ZERO_TIME;
        p.set_command(cmd);
        p.set_address(addr);
        p.set_data_ptr(static_cast<unsigned char*>(data));
        p.set_data_length(len);
        p.set_streaming_width(len);
        p.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
        socket->b_transport(p, delay);
        wait(delay);
        if (!p.is_response_ok()) {
            std::printf("access 0x%llx: %s\n", (unsigned long long)addr, p.get_response_string().c_str());
            ++errors;
        }
    }
    void write32(uint64_t addr, uint32_t v) { access(tlm::TLM_WRITE_COMMAND, addr, &v, 4); }

    // Shades the line through the wrapper at `base`, frame-buffer line `fb_line`; returns the time it took.
    sc_time shade_line(uint64_t base, unsigned fb_line, const std::vector<uint16_t>& cos,
                       const std::array<uint32_t, 4>& surface) {
        const sc_time start = sc_core::sc_time_stamp();
        write32(base + shading::tlm_map::N, surface[0]);
        write32(base + shading::tlm_map::KSI_R, surface[1]);
        write32(base + shading::tlm_map::KSI_G, surface[2]);
        write32(base + shading::tlm_map::KSI_B, surface[3]);
        std::vector<uint16_t> cos_copy = cos;
        access(tlm::TLM_WRITE_COMMAND, base + shading::tlm_map::COS_BLOCK, cos_copy.data(), 2 * PIXELS);
        std::vector<uint32_t> result(4 * PIXELS);  // R, G, B, cos per pixel
        access(tlm::TLM_READ_COMMAND, base + shading::tlm_map::RESULT_BLOCK, result.data(), 16 * PIXELS);
        std::vector<uint32_t> rgb(3 * PIXELS);
        for (unsigned i = 0; i < PIXELS; ++i)
            for (unsigned c = 0; c < 3; ++c) rgb[3 * i + c] = result[4 * i + c];
        access(tlm::TLM_WRITE_COMMAND, FB + fb_line * 12 * PIXELS, rgb.data(), 12 * PIXELS);
        return sc_core::sc_time_stamp() - start;
    }

    // Interpolates the line's intervals through the raster-line wrapper at `base`, one channel per
    // burst, clamps the pixels to the pixel format (as the pipeline's output stage) and writes the
    // R, G, B words of the line's covered pixels to frame-buffer line `fb_line`; returns the time.
    sc_time interpolate_line(uint64_t base, unsigned fb_line, const std::vector<shading::pipeline::interval_job>& jobs,
                             const std::vector<std::array<shading::pipeline::rgb_codes, 4>>& samples) {
        namespace m = shading::line_tlm_map;
        const sc_time start = sc_core::sc_time_stamp();
        std::size_t pixels = 0;
        for (const auto& j : jobs) pixels += j.len;
        std::vector<uint32_t> rgb(3 * pixels);
        for (unsigned c = 0; c < 3; ++c) {
            std::vector<unsigned char> ivs(m::INTERVAL_STRIDE * jobs.size());
            for (std::size_t j = 0; j < jobs.size(); ++j) {
                unsigned char* at = ivs.data() + j * m::INTERVAL_STRIDE;
                for (unsigned s = 0; s < 4; ++s) {
                    const auto code = static_cast<uint16_t>(samples[j][s][c]);  // colour_fmt = the unit's Q8.8 sample
                    std::memcpy(at + 2 * s, &code, 2);
                }
                const uint32_t len = jobs[j].len;
                std::memcpy(at + m::IV_LEN, &len, 4);
            }
            access(tlm::TLM_WRITE_COMMAND, base + m::INTERVAL_BLOCK, ivs.data(), static_cast<unsigned>(ivs.size()));
            std::vector<uint32_t> px(pixels);
            access(tlm::TLM_READ_COMMAND, base + m::PIXEL_BLOCK, px.data(), static_cast<unsigned>(4 * pixels));
            for (std::size_t p = 0; p < pixels; ++p)
                rgb[3 * p + c] = static_cast<uint32_t>(shading::pipeline::golden_output_clamp(px[p]));
        }
        access(tlm::TLM_WRITE_COMMAND, FB + fb_line * 12 * PIXELS, rgb.data(), static_cast<unsigned>(12 * pixels));
        return sc_core::sc_time_stamp() - start;
    }

    void run() {
        namespace sc = shading::scene;
        namespace pl = shading::pipeline;
        // The head scan from the installed data, its frame constants (n, k_s*I per channel).
        const sc::world head = sc::builtin_scene("head", SHADING_DATA_DIR, PIXELS, PIXELS);
        const sc::rasterised r = sc::rasterise(head);
        const pl::frame_constants k = pl::frame_constants_of(head);
        const sc::device_config dev{};  // UA 60553 as patented, saturating: the wrappers' device
        const std::array<uint64_t, 3> ksi = k.ksi;
        const std::array<uint32_t, 4> surface{k.n, static_cast<uint32_t>(ksi[0]), static_cast<uint32_t>(ksi[1]),
                                              static_cast<uint32_t>(ksi[2])};

        // Per line of the middle half (the face), every pixel's N.H code (0 where not covered); the
        // line with the most highlight.
        unsigned y = 0, best = 0;
        std::vector<uint16_t> cos(PIXELS);
        for (unsigned yy = PIXELS / 4; yy < 3 * PIXELS / 4; ++yy) {
            std::vector<uint16_t> line(PIXELS, 0);
            unsigned lit = 0;
            for (unsigned x = 0; x < PIXELS; ++x) {
                if (!r.covered(x, yy)) continue;
                line[x] = static_cast<uint16_t>(pl::sample_of(sc::geometry_at(r, x, yy, nullptr)).cos_nh);
                lit += shading::golden_ua60553(k.n, line[x], ksi, shading::overflow_mode::saturate).out[0] != 0;
            }
            if (lit > best) best = lit, y = yy, cos = line;
        }

        // The UA 60553 wrappers: the line's per-pixel specular colour; then the squared device's,
        // each line from a rising edge of its 20 ns clock.
        const sc_time t_lt = shade_line(SHADE_LT, 0, cos, surface);
        const sc_time t_pa = shade_line(SHADE_PA, 1, cos, surface);
        const sc_time clock = shading::tlm_strobe_timing{}.clk_period;
        wait(clock - sc_core::sc_time_stamp() % clock);
        const sc_time t_sq_lt = shade_line(SQUARED_LT, 4, cos, surface);
        wait(clock - sc_core::sc_time_stamp() % clock);
        const sc_time t_sq_pa = shade_line(SQUARED_PA, 5, cos, surface);

        // The raster-line wrappers: the interpolation paper's plan of the frame, the line's intervals
        // and samples.
        pl::plan_config c;
        c.length = pl::length_policy::fixed;
        c.m = M;
        c.degree = pl::degree_policy::cubic;
        c.eval = pl::evaluator::fd;
        c.set = shading::interp::sample_set::case1;
        c.div = shading::interp::div3_mode::shift_add;
        const pl::plan plan = pl::make_plan(r, k, dev, c);
        std::vector<pl::interval_job> jobs;
        std::vector<std::array<pl::rgb_codes, 4>> samples;
        for (const auto& j : plan.jobs)
            if (j.y == y) {
                jobs.push_back(j);
                samples.push_back({});
                for (unsigned s = 0; s < 4; ++s) samples.back()[s] = pl::golden_sample(dev, k, j.s[s]);
            }
        const sc_time t_line_lt = interpolate_line(LINE_LT, 2, jobs, samples);
        const sc_time t_line_pa = interpolate_line(LINE_PA, 3, jobs, samples);

        // Read the six lines back from the frame buffer and check them against the golden models.
        std::vector<uint32_t> fb(6 * 3 * PIXELS);
        access(tlm::TLM_READ_COMMAND, FB, fb.data(), static_cast<unsigned>(4 * fb.size()));
        unsigned lit = 0, lit_sq = 0;
        for (unsigned line : {0u, 1u, 4u, 5u})
            for (unsigned i = 0; i < PIXELS; ++i) {
                const auto want = line < 2 ? shading::golden_ua60553(k.n, cos[i], ksi, shading::overflow_mode::saturate).out
                                           : shading::golden_squared(k.n, cos[i], ksi, shading::overflow_mode::saturate).out;
                for (unsigned ch = 0; ch < 3; ++ch) {
                    const uint32_t got = fb[(line * PIXELS + i) * 3 + ch];
                    errors += got != want[ch];
                    ++checked;
                    lit += line == 0 && ch == 0 && got != 0;
                    lit_sq += line == 4 && ch == 0 && got != 0;
                }
            }
        std::size_t interpolated = 0;
        for (unsigned line = 2; line < 4; ++line) {
            std::size_t p = 0;
            for (const auto& j : jobs) {
                const auto want = pl::golden_interval(j, k, dev, c.eval, c.set, c.div);
                for (const auto& px : want) {
                    for (unsigned ch = 0; ch < 3; ++ch) {
                        errors += fb[(line * PIXELS + p) * 3 + ch] != px[ch];
                        ++checked;
                    }
                    ++p;
                }
            }
            interpolated = p;
        }
        std::printf("head, %ux%u, line %u: %u pixels with highlight; UA 60553 loosely timed %s, pin-accurate %s\n",
                    PIXELS, PIXELS, y, lit, t_lt.to_string().c_str(), t_pa.to_string().c_str());
        std::printf("  squared-quadratic: %u pixels with highlight; loosely timed %s, pin-accurate %s\n", lit_sq,
                    t_sq_lt.to_string().c_str(), t_sq_pa.to_string().c_str());
        std::printf("  raster-line unit: %zu intervals, %zu pixels x 3 channels; loosely timed %s, pin-accurate %s\n",
                    jobs.size(), interpolated, t_line_lt.to_string().c_str(), t_line_pa.to_string().c_str());
        expected = 4 * 3 * PIXELS + 2 * 3 * interpolated;
        if (t_lt != t_pa || t_sq_lt != t_sq_pa || t_line_lt != t_line_pa) {
            std::printf("the two timing modes took different times\n");
            ++errors;
        }
        if (lit == 0 || lit_sq == 0 || jobs.empty() || interpolated == 0) {  // a line with no highlight would not test much
            std::printf("no lit pixel or no interval on the line\n");
            ++errors;
        }
        sc_core::sc_stop();
    }
    std::size_t expected = 1;  // words to check, known once the line is planned
};

int sc_main(int, char*[]) {
    traffic_generator cpu("cpu");
    router bus("bus");
    shading::specular_tlm_ua60553 shade_lt("shade_lt", shading::tlm_timing::loosely_timed);
    shading::specular_tlm_ua60553 shade_pa("shade_pa", shading::tlm_timing::pin_accurate);
    shading::specular_tlm_squared squared_lt("squared_lt", shading::tlm_timing::loosely_timed);
    shading::specular_tlm_squared squared_pa("squared_pa", shading::tlm_timing::pin_accurate);
    line_unit line_lt("line_lt", shading::tlm_timing::loosely_timed);
    line_unit line_pa("line_pa", shading::tlm_timing::pin_accurate);
    frame_buffer fb("fb");
    cpu.socket.bind(bus.socket);
    bus.out[0].bind(shade_lt.socket);
    bus.out[1].bind(shade_pa.socket);
    bus.out[2].bind(squared_lt.socket);
    bus.out[3].bind(squared_pa.socket);
    bus.out[4].bind(line_lt.socket);
    bus.out[5].bind(line_pa.socket);
    bus.out[6].bind(fb.socket);
    sc_core::sc_start(1, sc_core::SC_MS);
    const bool stopped = sc_core::sc_get_status() == sc_core::SC_STOPPED;
    const auto warnings = sc_core::sc_report_handler::get_count(sc_core::SC_WARNING);
    std::printf("virtual platform: %u words checked, %u errors, %u warnings, %s\n", cpu.checked, cpu.errors,
                unsigned(warnings), stopped ? "stopped" : "NOT STOPPED");
    return (cpu.checked == cpu.expected && cpu.errors == 0 && stopped && warnings == 0) ? 0 : 1;
}

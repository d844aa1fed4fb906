// Issue 9's virtual platform, built against the installed package only (shading::tlm): a traffic
// generator standing in for the CPU, a router, two UA 60553 TLM wrappers (loosely timed and
// pin-accurate) and a frame-buffer memory. The generator shades one raster line of the sphere scene
// (scene::sphere_line_cos, in libshading_golden) per wrapper with one COS_BLOCK burst write and one
// RESULT_BLOCK burst read, copies the pixels into the frame buffer with one burst write, reads them
// back and compares every word with golden_ua60553. Both wrappers must agree on data and on time.
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

#include "golden/specular_golden.h"  // shading::golden
#include "scene/scene.h"              // shading::golden: the sphere line and the cos quantisation
#include "tlm/specular_tlm.h"         // shading::tlm

using sc_core::sc_time;
using sc_core::SC_NS;
using sc_core::SC_ZERO_TIME;

// Address map of the platform.
constexpr uint64_t SHADE_LT = 0x40000000, SHADE_PA = 0x40010000, SHADE_SIZE = 0x10000;
constexpr uint64_t FB = 0x80000000, FB_SIZE = 0x10000;
constexpr unsigned PIXELS = 256;

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
    std::array<tlm_utils::simple_initiator_socket<router>, 3> out{
        tlm_utils::simple_initiator_socket<router>{"to_shade_lt"},
        tlm_utils::simple_initiator_socket<router>{"to_shade_pa"}, tlm_utils::simple_initiator_socket<router>{"to_fb"}};
    std::array<region, 3> map{{{SHADE_LT, SHADE_SIZE}, {SHADE_PA, SHADE_SIZE}, {FB, FB_SIZE}}};
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

    void run() {
        // The sphere seen head-on, lit from the upper left; the line at y = 0.3.
        std::vector<uint16_t> cos;
        for (double c : shading::scene::sphere_line_cos(0.3, PIXELS, -0.4, 0.5, 1.0))
            cos.push_back(static_cast<uint16_t>(shading::scene::cos_code(c)));
        const std::array<uint32_t, 4> surface{40, 255, 200, 90};
        const sc_time t_lt = shade_line(SHADE_LT, 0, cos, surface);
        const sc_time t_pa = shade_line(SHADE_PA, 1, cos, surface);

        // Read both lines back from the frame buffer and check them against the golden model.
        std::vector<uint32_t> fb(2 * 3 * PIXELS);
        access(tlm::TLM_READ_COMMAND, FB, fb.data(), 4 * fb.size());
        unsigned lit = 0;
        for (unsigned line = 0; line < 2; ++line)
            for (unsigned i = 0; i < PIXELS; ++i) {
                const auto want = shading::golden_ua60553(surface[0], cos[i], {surface[1], surface[2], surface[3]},
                                                          shading::overflow_mode::saturate);
                for (unsigned c = 0; c < 3; ++c) {
                    const uint32_t got = fb[(line * PIXELS + i) * 3 + c];
                    errors += got != want.out[c];
                    ++checked;
                    lit += line == 0 && c == 0 && got != 0;
                }
            }
        std::printf("line of %u pixels (%u lit): loosely timed %s, pin-accurate %s of simulated time\n", PIXELS, lit,
                    t_lt.to_string().c_str(), t_pa.to_string().c_str());
        if (t_lt != t_pa) {
            std::printf("the two timing modes took different times\n");
            ++errors;
        }
        if (lit == 0) {  // a line with no highlight would not test much
            std::printf("no lit pixel on the line\n");
            ++errors;
        }
        sc_core::sc_stop();
    }
};

int sc_main(int, char*[]) {
    traffic_generator cpu("cpu");
    router bus("bus");
    shading::specular_tlm_ua60553 shade_lt("shade_lt", shading::tlm_timing::loosely_timed);
    shading::specular_tlm_ua60553 shade_pa("shade_pa", shading::tlm_timing::pin_accurate);
    frame_buffer fb("fb");
    cpu.socket.bind(bus.socket);
    bus.out[0].bind(shade_lt.socket);
    bus.out[1].bind(shade_pa.socket);
    bus.out[2].bind(fb.socket);
    sc_core::sc_start(1, sc_core::SC_MS);
    const bool stopped = sc_core::sc_get_status() == sc_core::SC_STOPPED;
    const auto warnings = sc_core::sc_report_handler::get_count(sc_core::SC_WARNING);
    std::printf("virtual platform: %u words checked, %u errors, %u warnings, %s\n", cpu.checked, cpu.errors,
                unsigned(warnings), stopped ? "stopped" : "NOT STOPPED");
    return (cpu.checked == 2 * 3 * PIXELS && cpu.errors == 0 && stopped && warnings == 0) ? 0 : 1;
}

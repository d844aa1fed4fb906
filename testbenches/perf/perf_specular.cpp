// perf_models' rows for the specular devices (perf_cases.h says why they are a file of their own):
// UA 60553, UA 22802 and the tuned device at block level and as the fast pin-level model, each with
// block delays on and off, traced and untraced; the clocked devices (squared-quadratic,
// square-and-multiply) likewise with their delays (all zero is a configuration error for them);
// the Verilator twin; the UA 60553 TLM wrapper.
#include <array>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "arith/specular_arith.h"
#include "arith/sqmul_arith.h"
#include "arith/squared_arith.h"
#include "arith/ua22802_arith.h"
#include "arith/ua60553_tuned_arith.h"
#include "perf_cases.h"
#include "perf_harness.h"
#include "perf_specular.h"
#include "sqmul/sqmul.h"
#include "squared/squared.h"
#include "tlm/specular_tlm.h"
#include "tuned/ua60553_tuned.h"
#include "ua22802/ua22802.h"
#include "ua60553/ua60553.h"
#ifdef SHADING_PERF_VERILATOR
#include "Vperf_ua60553.h"
#endif

namespace shading::perf {

namespace {

constexpr std::array<uint64_t, 3> ksi{255, 140, 40};

// Every pixel is checked against the golden model through a table of its results for every cos
// code (n and k_s*I are fixed), filled before the first access: the row times the wrapper, not the
// golden model (which would otherwise take three quarters of the loosely-timed row's time).
template <class Wrapper>
struct specular_tlm_top : tlm_harness {
    Wrapper w;
    specular_tlm_top(const sc_core::sc_module_name& n, tlm_timing t)
        : tlm_harness(n, &specular_tlm_top::script,
                      t == tlm_timing::loosely_timed ? lt_quantum() : sc_core::sc_time(4 * 20 * 1024, sc_core::SC_NS),
                      sc_core::sc_time(20, sc_core::SC_NS)),
          w("w", t) {
        init.socket.bind(w.socket);
    }
    // The script's buffers are members, not locals of the thread that never returns: its stack is
    // never unwound, so LeakSanitizer would report what only that stack points to.
    std::vector<std::array<uint32_t, 3>> golden_;
    std::vector<uint16_t> codes_;
    std::vector<uint32_t> res_;

    static void script(tlm_harness& self) {
        namespace m = shading::tlm_map;
        auto& i = self.init;
        auto& top = static_cast<specular_tlm_top&>(self);
        auto& golden = top.golden_;
        golden.assign(spec::cos_one + 1, {});
        for (uint64_t c = 0; c <= spec::cos_one; ++c) {
            const auto g = golden_ua60553(120, c, ksi, overflow_mode::saturate).out;
            golden[c] = {static_cast<uint32_t>(g[0]), static_cast<uint32_t>(g[1]), static_cast<uint32_t>(g[2])};
        }
        tlm_utils::tlm_quantumkeeper::set_global_quantum(lt_quantum());
        tlm_utils::tlm_quantumkeeper qk;
        qk.reset();
        i.write32(m::N, 120);
        for (unsigned c = 0; c < 3; ++c) i.write32(m::KSI_R + 4 * c, static_cast<uint32_t>(ksi[c]));
        auto& codes = top.codes_;
        auto& res = top.res_;
        codes.assign(m::BLOCK_PIXELS, 0);
        res.assign(4 * m::BLOCK_PIXELS, 0);
        for (uint64_t l = 0;; ++l) {
            for (std::size_t p = 0; p < m::BLOCK_PIXELS; ++p)
                codes[p] = static_cast<uint16_t>((l * 7919 + p * 31) % (spec::cos_one + 1));
            lt_access(i, qk, tlm::TLM_WRITE_COMMAND, m::COS_BLOCK, reinterpret_cast<unsigned char*>(codes.data()),
                      2 * m::BLOCK_PIXELS);
            lt_access(i, qk, tlm::TLM_READ_COMMAND, m::RESULT_BLOCK, reinterpret_cast<unsigned char*>(res.data()),
                      16 * m::BLOCK_PIXELS);
            for (std::size_t p = 0; p < m::BLOCK_PIXELS; ++p) {
                const auto& g = golden[codes[p]];
                self.mismatches_ += res[4 * p] != g[0] || res[4 * p + 1] != g[1] || res[4 * p + 2] != g[2];
            }
            self.items_ += m::BLOCK_PIXELS;
        }
    }
};

// The specular devices: block delays on and off, tracing on and off.
template <class Device>
void add_specular(const std::string& name, const std::string& golden,
                  typename perf::specular_harness<Device>::golden_fn g,
                  const typename Device::generator::config& gen = Device::generator::default_config()) {
    using H = perf::specular_harness<Device>;
    for (bool delays : {true, false})
        for (bool traced : {false, true}) {
            const std::string n = name + (delays ? "/delays" : "/no_delays") + (traced ? "/traced" : "");
            add_sc(n, golden, "evaluations",
                   [=] {
                       return std::unique_ptr<harness>(new H("top", g, overflow_mode::saturate, gen,
                                                             delays ? block_delays{} : perf::zero_delays()));
                   },
                   traced);
        }
}

// A clocked device, `clocks` clocks of 20 ns a pixel; tracing on and off.
template <class Device>
void add_clocked(const std::string& name, const std::string& golden, unsigned clocks,
                 typename perf::clocked_harness<Device>::golden_fn g) {
    using H = perf::clocked_harness<Device>;
    for (bool traced : {false, true})
        add_sc(name + "/delays" + (traced ? "/traced" : ""), golden, "evaluations",
               [=] { return std::unique_ptr<harness>(new H("top", clocks, g, overflow_mode::saturate, block_delays{})); },
               traced);
}

#ifdef SHADING_PERF_VERILATOR
// The RTL twin's UA 60553 datapath (rtl/specular/specular_device.v, AGEN 0, saturate) compiled by
// `verilator --sc` (cmake/verilator.cmake), in the same harness: ctl17 from an sc_clock.
void add_verilator() {
    using H = perf::specular_harness<Vperf_ua60553, a_gen_linear>;
    add_sc("verilator/ua60553", "golden/ua60553", "evaluations", [] {
        return std::unique_ptr<harness>(new H("top", [](uint64_t n, uint64_t c, const std::array<uint64_t, 3>& k) {
            return golden_ua60553(n, c, k, overflow_mode::saturate);
        }));
    });
    sc_cases().back().strict = false;
}
#endif

}  // namespace

void register_specular_cases() {
    const auto mode = overflow_mode::saturate;
    add_specular<device_ua60553>("sc/ua60553", "golden/ua60553", [mode](uint64_t n, uint64_t c, const auto& k) {
        return golden_ua60553(n, c, k, mode);
    });
    add_specular<device_ua22802>("sc/ua22802", "golden/ua22802", [mode](uint64_t n, uint64_t c, const auto& k) {
        return golden_ua22802(n, c, k, mode);
    });
    add_specular<device_ua60553_tuned>("sc/ua60553_tuned", "golden/ua60553_tuned",
                                       [mode](uint64_t n, uint64_t c, const auto& k) {
                                           return golden_ua60553_tuned(n, c, k, mode);
                                       });
    // The fast pin-level abstraction (modules/specular/specular_fast.h): same pins, timing, constructor.
    add_specular<device_ua60553_fast>("sc/ua60553_fast", "golden/ua60553", [mode](uint64_t n, uint64_t c, const auto& k) {
        return golden_ua60553(n, c, k, mode);
    });
    add_specular<device_ua22802_fast>("sc/ua22802_fast", "golden/ua22802", [mode](uint64_t n, uint64_t c, const auto& k) {
        return golden_ua22802(n, c, k, mode);
    });
    add_specular<device_ua60553_tuned_fast>("sc/ua60553_tuned_fast", "golden/ua60553_tuned",
                                            [mode](uint64_t n, uint64_t c, const auto& k) {
                                                return golden_ua60553_tuned(n, c, k, mode);
                                            });
    // The clocked devices (ours), 15 and 24 clocks a pixel (specular_tb.h's squared_timing, sqmul_timing).
    const auto squared = [mode](uint64_t n, uint64_t c, const std::array<uint64_t, 3>& k) {
        return golden_squared(n, c, k, mode).out;
    };
    const auto sqmul = [mode](uint64_t n, uint64_t c, const std::array<uint64_t, 3>& k) {
        return golden_sqmul(n, c, k, mode).out;
    };
    add_clocked<device_squared>("sc/squared", "golden/squared", 15, squared);
    add_clocked<device_squared_fast>("sc/squared_fast", "golden/squared", 15, squared);
    add_clocked<device_sqmul>("sc/sqmul", "golden/sqmul", 24, sqmul);
    add_clocked<device_sqmul_fast>("sc/sqmul_fast", "golden/sqmul", 24, sqmul);
#ifdef SHADING_PERF_VERILATOR
    add_verilator();
#endif
}

void add_specular_tlm(const std::string& name, bool pin) {
    add_sc(name, "golden/ua60553", "evaluations",
           module<specular_tlm_top<specular_tlm_ua60553>>(pin ? tlm_timing::pin_accurate : tlm_timing::loosely_timed));
}

}  // namespace shading::perf

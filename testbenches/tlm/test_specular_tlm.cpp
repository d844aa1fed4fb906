// TLM-2.0 wrapper of the specular devices (modules/tlm/specular_tlm.h: the UA 60553 family, the
// squared-quadratic and the square-and-multiply devices): the register map, every error response with the state unchanged,
// both timing modes against the golden models (src/golden, written independently of the wrapper's
// own per-pixel path) and against each other on random traffic, the time of each access against
// hand-worked timing, the burst path for a whole line and debug transport. Each TEST elaborates
// one bench (ctest runs each in its own process).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "testbenches/common/report_log.h"
#include "testbenches/common/sim_guard.h"
#include "core/report_ids.h"
#include "arith/specular_arith.h"
#include "arith/sqmul_arith.h"
#include "arith/squared_arith.h"
#include "arith/ua22802_arith.h"
#include "arith/ua60553_tuned_arith.h"
#include "tlm/specular_tlm.h"
#include "tlm_bad_access.h"
#include "tlm_initiator.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_specular_tlm {

using namespace shading;
using namespace shading::tb;
using sc_core::SC_NS;
using sc_core::sc_time;
namespace m = shading::tlm_map;

namespace {

// Fig. 3's strobe period with the default timing, by hand: t_high 5 ns + t_low 15 ns.
sc_time fig3_pixel_end(const sc_time& start, unsigned) { return start + sc_time(20, SC_NS); }

// The squared device's pixel worked by hand from its documented timing (modules/tlm/README.md) with
// the defaults: cos at `start`, strobe 17 falls at the first falling edge of the 20 ns clock (10 ns +
// 20 ns m) at least 2.5 ns later, the synchroniser samples it at the rising edge 10 ns after that,
// and output 29 rises k + 3 clocks later (the synchroniser's second edge, the taking edge, k squares,
// the done edge) plus the AND gate's 100 ps; k = floor(log2 n) (9 - leading zeros of the 10-bit n),
// 0 for n = 0.
sc_time squared_pixel_end(const sc_time& start, unsigned n) {
    unsigned k = 0;
    while (k < 9 && (n >> (k + 1)) != 0) ++k;
    const double after_first_fall = start / sc_time(1, SC_NS) + 2.5 - 10.0;
    const double m = after_first_fall <= 0 ? 0 : std::ceil(after_first_fall / 20.0);
    return sc_time(10.0 + 20.0 * m + 10.0 + 20.0 * (k + 3) + 0.1, SC_NS);
}

// The square-and-multiply device's pixel the same way (the same synchroniser), with floor(log2 n) +
// popcount(n) + 2 clocks after the sampling edge in place of k + 3: the synchroniser's second edge,
// the taking edge, its walk of floor(log2 n) squares and popcount(n) - 1 multiplications, the done
// edge (n = 0 read as 1).
sc_time sqmul_pixel_end(const sc_time& start, unsigned n) {
    if (n == 0) n = 1;
    unsigned steps = 0;
    for (unsigned v = n; v > 1; v >>= 1) ++steps;
    for (unsigned v = n; v != 0; v >>= 1) steps += v & 1u;
    const double after_first_fall = start / sc_time(1, SC_NS) + 2.5 - 10.0;
    const double m = after_first_fall <= 0 ? 0 : std::ceil(after_first_fall / 20.0);
    return sc_time(10.0 + 20.0 * m + 10.0 + 20.0 * (steps + 2) + 0.1, SC_NS);
}

struct ua60553_v {
    using gen = a_gen_linear;
    static constexpr uint32_t code = 0;
    static datapath_nets golden(uint64_t n, uint64_t c, const std::array<uint64_t, 3>& k, overflow_mode md) {
        return golden_ua60553(n, c, k, md);
    }
    static sc_time pixel_end(const sc_time& start, unsigned n) { return fig3_pixel_end(start, n); }
};
struct ua22802_v {
    using gen = a_gen_rom;
    static constexpr uint32_t code = 1;
    static datapath_nets golden(uint64_t n, uint64_t c, const std::array<uint64_t, 3>& k, overflow_mode md) {
        return golden_ua22802(n, c, k, md);
    }
    static sc_time pixel_end(const sc_time& start, unsigned n) { return fig3_pixel_end(start, n); }
};
struct tuned_v {
    using gen = a_gen_tuned;
    static constexpr uint32_t code = 2;
    static datapath_nets golden(uint64_t n, uint64_t c, const std::array<uint64_t, 3>& k, overflow_mode md) {
        return golden_ua60553_tuned(n, c, k, md);
    }
    static sc_time pixel_end(const sc_time& start, unsigned n) { return fig3_pixel_end(start, n); }
};
struct squared_v {
    using gen = squared_device;
    static constexpr uint32_t code = 3;
    static squared_nets golden(uint64_t n, uint64_t c, const std::array<uint64_t, 3>& k, overflow_mode md) {
        return golden_squared(n, c, k, md);
    }
    static sc_time pixel_end(const sc_time& start, unsigned n) { return squared_pixel_end(start, n); }
};
struct sqmul_v {
    using gen = sqmul_device;
    static constexpr uint32_t code = 4;
    static sqmul_nets golden(uint64_t n, uint64_t c, const std::array<uint64_t, 3>& k, overflow_mode md) {
        return golden_sqmul(n, c, k, md);
    }
    static sc_time pixel_end(const sc_time& start, unsigned n) { return sqmul_pixel_end(start, n); }
};

// The time a burst of `count` pixels at n takes from `start`: its pixels back to back.
template <class V>
sc_time burst_time(const sc_time& start, unsigned n, std::size_t count) {
    sc_time t = start;
    for (std::size_t p = 0; p < count; ++p) t = V::pixel_end(t, n);
    return t - start;
}

// One initiator bound to one wrapper, or to a pair (LT and pin-accurate) through two sockets.
template <class Gen>
using bench = tlm_bench<specular_tlm<Gen>>;
template <class Gen>
using pair_bench = tlm_pair_bench<specular_tlm<Gen>>;

const sc_time limit(1, sc_core::SC_SEC);

// Every byte of the model's state visible through debug transport, STATUS's error log masked.
std::vector<unsigned char> snapshot(tlm_initiator& i) {
    auto s = i.debug_read(0, m::REG_END);
    s[m::STATUS] &= m::STATUS_READY;
    auto c = i.debug_read(m::COS_BLOCK, m::COS_BLOCK_END - m::COS_BLOCK);
    auto r = i.debug_read(m::RESULT_BLOCK, m::RESULT_BLOCK_END - m::RESULT_BLOCK);
    s.insert(s.end(), c.begin(), c.end());
    s.insert(s.end(), r.begin(), r.end());
    return s;
}

template <class V>
class SpecularTlm : public ::testing::Test {};
using variants = ::testing::Types<ua60553_v, ua22802_v, tuned_v, squared_v, sqmul_v>;
TYPED_TEST_SUITE(SpecularTlm, variants);

// Register map: reset values, field widths, read-only fields, READY's life, a pixel against golden.
TYPED_TEST(SpecularTlm, RegisterMap) {
    using V = TypeParam;
    bench<typename V::gen> b("b", tlm_timing::loosely_timed, [](tlm_initiator& i) {
        EXPECT_EQ(i.read32(m::N), 0u);
        EXPECT_EQ(i.read32(m::STATUS), 0u) << "nothing shaded yet";
        EXPECT_EQ(i.read32(m::CONTROL), V::code << 4) << "saturate, variant, loosely timed";
        ASSERT_EQ(i.write32(m::N, 0xFFFFF000u | 37u), tlm::TLM_OK_RESPONSE);
        EXPECT_EQ(i.read32(m::N), 37u) << "n is 10 bits: bits 31:10 ignored";
        ASSERT_EQ(i.write32(m::KSI_R, 0x1FFu), tlm::TLM_OK_RESPONSE);
        ASSERT_EQ(i.write32(m::KSI_G, 128u), tlm::TLM_OK_RESPONSE);
        ASSERT_EQ(i.write32(m::KSI_B, 7u), tlm::TLM_OK_RESPONSE);
        EXPECT_EQ(i.read32(m::KSI_R), 0xFFu) << "k_s*I is 8 bits";
        EXPECT_EQ(i.read32(m::KSI_G), 128u);
        EXPECT_EQ(i.read32(m::KSI_B), 7u);
        ASSERT_EQ(i.write32(m::COS, 0x7000u), tlm::TLM_OK_RESPONSE);
        EXPECT_EQ(i.read32(m::COS), 0x7000u);
        EXPECT_EQ(i.read32(m::STATUS), m::STATUS_READY);
        const auto g = V::golden(37, 0x7000, {255, 128, 7}, overflow_mode::saturate);
        EXPECT_EQ(i.read32(m::RESULT_R), g.out[0]);
        EXPECT_EQ(i.read32(m::RESULT_G), g.out[1]);
        EXPECT_EQ(i.read32(m::RESULT_B), g.out[2]);
        // Variant and timing bits are read-only; OVF is writable and clears READY.
        ASSERT_EQ(i.write32(m::CONTROL, 0x131u), tlm::TLM_OK_RESPONSE);
        EXPECT_EQ(i.read32(m::CONTROL), (V::code << 4) | m::CONTROL_OVF);
        EXPECT_EQ(i.read32(m::STATUS), 0u) << "OVF changed: READY cleared";
        ASSERT_EQ(i.write32(m::COS, 0x9000u), tlm::TLM_OK_RESPONSE);  // cos > 1.0 in wrap mode
        const auto w = V::golden(37, 0x9000, {255, 128, 7}, overflow_mode::wrap);
        EXPECT_EQ(i.read32(m::RESULT_R), w.out[0]);
        EXPECT_EQ(i.read32(m::RESULT_B), w.out[2]);
        ASSERT_EQ(i.write32(m::N, 38u), tlm::TLM_OK_RESPONSE);
        EXPECT_EQ(i.read32(m::STATUS), 0u) << "N written: READY cleared";
    });
    ASSERT_TRUE(run_to_completion(b, limit));
}

// Every error response, its warning, its log bit; the state unchanged; no time charged.
template <class Gen>
void every_error_leaves_state_unchanged() {
    report_log::get().expect(msg::tlm);
    const unsigned before = report_log::get().count(msg::tlm);
    bench<Gen> b("b", tlm_timing::pin_accurate, [](tlm_initiator& i) {
        ASSERT_EQ(i.write32(m::N, 20u), tlm::TLM_OK_RESPONSE);
        ASSERT_EQ(i.write32(m::KSI_R, 200u), tlm::TLM_OK_RESPONSE);
        std::vector<unsigned char> line(64);
        for (std::size_t k = 0; k < line.size(); k += 2) line[k + 1] = static_cast<unsigned char>(k);
        ASSERT_EQ(i.access(tlm::TLM_WRITE_COMMAND, m::COS_BLOCK, line.data(), 64), tlm::TLM_OK_RESPONSE);
        expect_bad_accesses(
            i,
            {
                {"unmapped register", tlm::TLM_WRITE_COMMAND, 0x028, 4, false, 0, tlm::TLM_ADDRESS_ERROR_RESPONSE, m::ERR_ADDRESS},
                {"between windows", tlm::TLM_READ_COMMAND, 0x1800, 4, false, 0, tlm::TLM_ADDRESS_ERROR_RESPONSE, m::ERR_ADDRESS},
                {"past the map", tlm::TLM_WRITE_COMMAND, 0x6000, 4, false, 0, tlm::TLM_ADDRESS_ERROR_RESPONSE, m::ERR_ADDRESS},
                {"2-byte register", tlm::TLM_WRITE_COMMAND, m::N, 2, false, 0, tlm::TLM_BURST_ERROR_RESPONSE, m::ERR_SIZE},
                {"8-byte register", tlm::TLM_WRITE_COMMAND, m::KSI_R, 8, false, 0, tlm::TLM_BURST_ERROR_RESPONSE, m::ERR_SIZE},
                {"misaligned register", tlm::TLM_WRITE_COMMAND, m::N + 1, 4, false, 0, tlm::TLM_BURST_ERROR_RESPONSE, m::ERR_SIZE},
                {"odd cos burst", tlm::TLM_WRITE_COMMAND, m::COS_BLOCK, 3, false, 0, tlm::TLM_BURST_ERROR_RESPONSE, m::ERR_SIZE},
                {"cos burst past end", tlm::TLM_WRITE_COMMAND, m::COS_BLOCK_END - 2, 4, false, 0, tlm::TLM_BURST_ERROR_RESPONSE, m::ERR_SIZE},
                {"streaming", tlm::TLM_WRITE_COMMAND, m::COS_BLOCK, 8, false, 2, tlm::TLM_BURST_ERROR_RESPONSE, m::ERR_SIZE},
                {"misaligned result", tlm::TLM_READ_COMMAND, m::RESULT_BLOCK + 2, 4, false, 0, tlm::TLM_BURST_ERROR_RESPONSE, m::ERR_SIZE},
                {"byte enables", tlm::TLM_WRITE_COMMAND, m::N, 4, true, 0, tlm::TLM_BYTE_ENABLE_ERROR_RESPONSE, m::ERR_BYTE_ENABLE},
                {"write RESULT_R", tlm::TLM_WRITE_COMMAND, m::RESULT_R, 4, false, 0, tlm::TLM_COMMAND_ERROR_RESPONSE, m::ERR_COMMAND},
                {"write STATUS", tlm::TLM_WRITE_COMMAND, m::STATUS, 4, false, 0, tlm::TLM_COMMAND_ERROR_RESPONSE, m::ERR_COMMAND},
                {"write result window", tlm::TLM_WRITE_COMMAND, m::RESULT_BLOCK, 16, false, 0, tlm::TLM_COMMAND_ERROR_RESPONSE, m::ERR_COMMAND},
                {"RESULT_G before a pixel", tlm::TLM_READ_COMMAND, m::RESULT_G, 4, false, 0, tlm::TLM_GENERIC_ERROR_RESPONSE, m::ERR_NOT_READY},
                {"result window past the burst", tlm::TLM_READ_COMMAND, m::RESULT_BLOCK + 16 * 31, 32, false, 0, tlm::TLM_GENERIC_ERROR_RESPONSE, m::ERR_NOT_READY},
            },
            [](tlm_initiator& t) { return t.read32(m::STATUS) & ~m::STATUS_READY; },
            [](tlm_initiator& t) { return t.write32(m::CONTROL, m::CONTROL_CLEAR_ERR); }, snapshot);
        // The burst's 32 pixels are readable, the one past it (above) was not.
        unsigned char ok[32 * 16];
        EXPECT_EQ(i.access(tlm::TLM_READ_COMMAND, m::RESULT_BLOCK, ok, sizeof ok), tlm::TLM_OK_RESPONSE);
    });
    ASSERT_TRUE(run_to_completion(b, limit));
    EXPECT_EQ(report_log::get().count(msg::tlm) - before, 16u) << "one warning per bad access";
}
TEST(SpecularTlmErrors, EveryErrorLeavesStateUnchanged) { every_error_leaves_state_unchanged<a_gen_linear>(); }
TEST(SpecularTlmErrors, EveryErrorLeavesStateUnchangedSquared) { every_error_leaves_state_unchanged<squared_device>(); }
TEST(SpecularTlmErrors, EveryErrorLeavesStateUnchangedSqmul) { every_error_leaves_state_unchanged<sqmul_device>(); }

// >= 10^4 random (n, k_s*I, cos) in loosely-timed mode against the device's golden model, both
// overflow modes, with the annotated delay of every access checked against the hand-worked pixel
// time, from a random incoming delay (the initiator's local time: a clocked device's phase).
TYPED_TEST(SpecularTlm, LooselyTimedRandomMatchesGolden) {
    using V = TypeParam;
    bench<typename V::gen> b("b", tlm_timing::loosely_timed, [](tlm_initiator& i) {
        std::mt19937_64 rng(60553 + V::code);
        unsigned n = 1, ovf = 0;
        std::array<uint64_t, 3> k{0, 0, 0};
        std::size_t mismatches = 0;
        for (int p = 0; p < 12000; ++p) {
            i.delay_in = sc_time(static_cast<double>(rng() % 50000), sc_core::SC_PS);
            if (p % 8 == 0) {
                n = static_cast<unsigned>(rng() % 1000 + 1);
                ASSERT_EQ(i.write32(m::N, n), tlm::TLM_OK_RESPONSE);
                ASSERT_EQ(i.last_delay, i.delay_in + sc_time(8, SC_NS)) << "two 4 ns halves of strobe 15";
                for (unsigned c = 0; c < 3; ++c) {
                    k[c] = rng() % 256;
                    ASSERT_EQ(i.write32(m::KSI_R + 4 * c, static_cast<uint32_t>(k[c])), tlm::TLM_OK_RESPONSE);
                }
                ovf = static_cast<unsigned>(rng() % 2);
                ASSERT_EQ(i.write32(m::CONTROL, ovf), tlm::TLM_OK_RESPONSE);
                ASSERT_EQ(i.last_delay, i.delay_in) << "CONTROL costs no strobe";
            }
            const uint32_t c = static_cast<uint32_t>(rng() % (ovf ? 0x10000 : spec::cos_one + 1));
            ASSERT_EQ(i.write32(m::COS, c), tlm::TLM_OK_RESPONSE);
            const sc_time now = sc_core::sc_time_stamp();
            ASSERT_EQ(i.last_delay, V::pixel_end(now + i.delay_in, n) - now) << "n " << n << " from " << i.delay_in;
            ASSERT_EQ(i.last_elapsed, sc_core::SC_ZERO_TIME) << "loosely timed: annotated, never waited";
            const auto g = V::golden(n, c, k, ovf ? overflow_mode::wrap : overflow_mode::saturate);
            const std::array<uint64_t, 3> got{i.read32(m::RESULT_R), i.read32(m::RESULT_G), i.read32(m::RESULT_B)};
            if (got != g.out && ++mismatches <= 5)
                ADD_FAILURE() << "n=" << n << " cos=0x" << std::hex << c << std::dec << " got " << got[0] << ","
                              << got[1] << "," << got[2] << " golden " << g.out[0] << "," << g.out[1] << "," << g.out[2];
        }
        EXPECT_EQ(mismatches, 0u);
    });
    ASSERT_TRUE(run_to_completion(b, limit));
}

// A few hundred random accesses (single pixels and short bursts, reloads, both overflow modes)
// through the pin-accurate wrapper and the loosely-timed one: identical data, and the pin-accurate
// access takes exactly the time the loosely-timed one annotates, which is the hand-worked time.
TYPED_TEST(SpecularTlm, PinAccurateMatchesLooselyTimed) {
    using V = TypeParam;
    pair_bench<typename V::gen> b("b", [](tlm_initiator& lt, tlm_initiator& pin) {
        std::mt19937_64 rng(22802 + V::code);
        auto both_write = [&](uint64_t addr, uint32_t v) {
            ASSERT_EQ(lt.write32(addr, v), tlm::TLM_OK_RESPONSE);
            ASSERT_EQ(pin.write32(addr, v), tlm::TLM_OK_RESPONSE);
            EXPECT_EQ(pin.last_elapsed, lt.last_delay) << "access at 0x" << std::hex << addr;
            EXPECT_EQ(pin.last_delay, sc_core::SC_ZERO_TIME);
        };
        std::size_t pixels = 0;
        while (pixels < 400) {
            const unsigned n = static_cast<unsigned>(rng() % 1000 + 1);
            both_write(m::N, n);
            EXPECT_EQ(pin.last_elapsed, sc_time(8, SC_NS));
            for (unsigned c = 0; c < 3; ++c) both_write(m::KSI_R + 4 * c, static_cast<uint32_t>(rng() % 256));
            both_write(m::CONTROL, static_cast<uint32_t>(rng() % 2));
            for (int p = 0; p < 4; ++p, ++pixels) {
                const sc_time start = sc_core::sc_time_stamp();
                both_write(m::COS, static_cast<uint32_t>(rng() % (spec::cos_one + 1)));
                EXPECT_EQ(pin.last_elapsed, V::pixel_end(start, n) - start) << "n " << n << " at " << start;
                for (uint64_t r = m::RESULT_R; r <= m::RESULT_B; r += 4) EXPECT_EQ(pin.read32(r), lt.read32(r));
            }
            const unsigned count = static_cast<unsigned>(rng() % 16 + 1), first = static_cast<unsigned>(rng() % 1000);
            std::vector<uint16_t> codes(count);
            for (auto& c : codes) c = static_cast<uint16_t>(rng() % (spec::cos_one + 1));
            const uint64_t addr = m::COS_BLOCK + 2 * first;
            auto* d = reinterpret_cast<unsigned char*>(codes.data());
            const sc_time start = sc_core::sc_time_stamp();
            ASSERT_EQ(lt.access(tlm::TLM_WRITE_COMMAND, addr, d, 2 * count), tlm::TLM_OK_RESPONSE);
            ASSERT_EQ(pin.access(tlm::TLM_WRITE_COMMAND, addr, d, 2 * count), tlm::TLM_OK_RESPONSE);
            EXPECT_EQ(lt.last_delay, burst_time<V>(start, n, count));
            EXPECT_EQ(pin.last_elapsed, lt.last_delay);
            std::vector<unsigned char> a(16 * count), c(16 * count);
            const uint64_t raddr = m::RESULT_BLOCK + 16 * first;
            ASSERT_EQ(lt.access(tlm::TLM_READ_COMMAND, raddr, a.data(), 16 * count), tlm::TLM_OK_RESPONSE);
            ASSERT_EQ(pin.access(tlm::TLM_READ_COMMAND, raddr, c.data(), 16 * count), tlm::TLM_OK_RESPONSE);
            EXPECT_EQ(a, c) << "burst of " << count << " at pixel " << first;
            pixels += count;
        }
    });
    ASSERT_TRUE(run_to_completion(b, limit));
    for (const auto* d : {b.pin.dev_sat.get(), b.pin.dev_wrap.get()})
        EXPECT_EQ(d->chk_timing.violations(), 0u) << "strobes 20, 22, 24 against output 29's rise";
}

// The pin-accurate wrapper honours the caller's delay first (it synchronises), then charges the
// strobes: an N write 2 x load_pulse, a COS write t_high + t_low.
TEST(SpecularTlmTiming, PinAccurateWaitsIncomingDelayThenStrobes) {
    bench<a_gen_linear> b("b", tlm_timing::pin_accurate, [](tlm_initiator& i) {
        i.delay_in = sc_time(7, SC_NS);
        ASSERT_EQ(i.write32(m::N, 5), tlm::TLM_OK_RESPONSE);
        EXPECT_EQ(i.last_elapsed, sc_time(7 + 8, SC_NS));
        EXPECT_EQ(i.last_delay, sc_core::SC_ZERO_TIME);
        ASSERT_EQ(i.write32(m::COS, 0x4000), tlm::TLM_OK_RESPONSE);
        EXPECT_EQ(i.last_elapsed, sc_time(7 + 20, SC_NS));
        i.delay_in = sc_core::SC_ZERO_TIME;
        EXPECT_EQ(i.read32(m::RESULT_R), 0u) << "k_s*I still 0";
        EXPECT_EQ(i.last_elapsed, sc_core::SC_ZERO_TIME) << "a read costs no strobe";
    });
    ASSERT_TRUE(run_to_completion(b, limit));
    EXPECT_EQ(b.dut.dev_sat->chk_timing.violations(), 0u);
}

// The squared device, pin-accurate, hand-worked (20 ns clock rising at 0, 20, 40 ns, ...; n = 5:
// k = 2): the N write waits 7 ns, then 8 ns of strobe 15; the COS write at 15 ns waits 7 ns, sets
// cos at 22 ns, strobe 17 falls at the first falling edge from 24.5 ns (30 ns), the synchroniser
// samples it at 40 ns, done rises 5 clocks later (60 and 80 ns: its second stage and the taking
// edge; 100, 120 ns: the squares; 140 ns), output 29 at 140.1 ns: 125.1 ns. A COS write whose
// set-up ends exactly on a falling edge (cos at 147.5 ns) falls there: 150, 160, 260.1 ns.
TEST(SpecularTlmTiming, SquaredPinAccurateStrobeFollowsTheClock) {
    bench<squared_device> b("b", tlm_timing::pin_accurate, [](tlm_initiator& i) {
        i.delay_in = sc_time(7, SC_NS);
        ASSERT_EQ(i.write32(m::N, 5), tlm::TLM_OK_RESPONSE);
        EXPECT_EQ(i.last_elapsed, sc_time(15, SC_NS));
        ASSERT_EQ(i.write32(m::COS, 0x4000), tlm::TLM_OK_RESPONSE);
        EXPECT_EQ(i.last_elapsed, sc_time(125.1, SC_NS));
        EXPECT_EQ(i.last_delay, sc_core::SC_ZERO_TIME);
        i.delay_in = sc_core::SC_ZERO_TIME;
        sc_core::wait(sc_time(147.5, SC_NS) - sc_core::sc_time_stamp());
        ASSERT_EQ(i.write32(m::COS, 0x4000), tlm::TLM_OK_RESPONSE);
        EXPECT_EQ(i.last_elapsed, sc_time(112.6, SC_NS));
        EXPECT_EQ(i.read32(m::RESULT_R), 0u) << "k_s*I still 0";
        EXPECT_EQ(i.last_elapsed, sc_core::SC_ZERO_TIME) << "a read costs no strobe";
    });
    ASSERT_TRUE(run_to_completion(b, limit));
    for (const auto* d : {b.dut.dev_sat.get(), b.dut.dev_wrap.get()}) {
        EXPECT_EQ(d->chk_timing.violations(), 0u);
        EXPECT_EQ(d->chk_load.violations(), 0u) << "RG1, RG2 settled at each LOAD";
        EXPECT_EQ(d->chk_clk.violations(), 0u);
        EXPECT_EQ(d->stage().ctl_sq.dropped(), 0u) << "no strobe before the previous result was valid";
    }
}

// The same in loosely-timed mode, where only the local time (the incoming delay) moves the phase:
// from 7 ns cos is set up by 9.5 ns, strobe 17 falls at 10 ns, is sampled at 20 ns, output 29 rises
// 5 clocks later, at 120.1 ns; from 7.5 ns the set-up ends on the falling edge at 10 ns (the same);
// from 8 ns it ends after it: 30, 40, 140.1 ns. n = 1000 (k = 9) from 0: 10, 20, 20 + 12 x 20 =
// 260.1 ns.
TEST(SpecularTlmTiming, SquaredLooselyTimedDelayFollowsTheClockPhase) {
    bench<squared_device> b("b", tlm_timing::loosely_timed, [](tlm_initiator& i) {
        ASSERT_EQ(i.write32(m::N, 5), tlm::TLM_OK_RESPONSE);
        const std::pair<double, double> from_to[] = {{7.0, 120.1}, {7.5, 120.1}, {8.0, 140.1}};  // ns
        for (const auto& [in, out] : from_to) {
            i.delay_in = sc_time(in, SC_NS);
            ASSERT_EQ(i.write32(m::COS, 0x4000), tlm::TLM_OK_RESPONSE);
            EXPECT_EQ(i.last_delay, sc_time(out, SC_NS)) << "from " << in << " ns";
        }
        i.delay_in = sc_core::SC_ZERO_TIME;
        ASSERT_EQ(i.write32(m::N, 1000), tlm::TLM_OK_RESPONSE);
        ASSERT_EQ(i.write32(m::COS, 0x4000), tlm::TLM_OK_RESPONSE);
        EXPECT_EQ(i.last_delay, sc_time(260.1, SC_NS));
        EXPECT_EQ(sc_core::sc_time_stamp(), sc_core::SC_ZERO_TIME) << "annotated, never waited";
    });
    ASSERT_TRUE(run_to_completion(b, limit));
}

// Another clock and a long strobe: a 10 ns clock (falling edges at 5, 15, 25 ns, ...) and strobe
// 17 low 40 ns, so for k = 0 output 29 follows strobe 17's rise (done 5 + 3 x 10 ns after the
// strobe), for k >= 1 the squaring stage's done. By hand: KSI_R and N = 1 (k = 0) from 0 ns, then
// COS from 16 ns: set-up to 18.5 ns, strobe 17 falls at 25 ns, sampled at 30 ns, done rises at
// 60 ns, strobe 17 at 65 ns, output 29 at 65.1 ns: 49.1 ns. N = 8 (k = 3), then COS from 73.1 ns:
// falls at 85 ns, sampled at 90 ns, done at 90 + 6 x 10 = 150 ns (after the strobe's 125 ns),
// output 29 at 150.1 ns: 77 ns. Then random n and pixels, both modes equal in data and time.
struct squared_10ns_long_strobe : specular_tlm_squared {
    static tlm_strobe_timing timing() {
        tlm_strobe_timing t;
        t.clk_period = sc_time(10, SC_NS);
        t.t_low = sc_time(40, SC_NS);
        return t;
    }
    squared_10ns_long_strobe(const sc_core::sc_module_name& name, tlm_timing t)
        : specular_tlm_squared(name, t, {}, timing()) {}
};
TEST(SpecularTlmTiming, SquaredOtherClockAndLongStrobe) {
    tlm_pair_bench<squared_10ns_long_strobe> b("b", [](tlm_initiator& lt, tlm_initiator& pin) {
        // Writes through both; the pin-accurate access's elapsed time (= the LT one's delay).
        auto both_write = [&](uint64_t addr, uint32_t v) {
            EXPECT_EQ(lt.write32(addr, v), tlm::TLM_OK_RESPONSE);
            EXPECT_EQ(pin.write32(addr, v), tlm::TLM_OK_RESPONSE);
            const sc_time elapsed = pin.last_elapsed;
            EXPECT_EQ(elapsed, lt.last_delay) << "access at 0x" << std::hex << addr;
            for (uint64_t r = m::RESULT_R; r <= m::RESULT_B; r += 4) {
                if (addr == m::COS) {
                    EXPECT_EQ(pin.read32(r), lt.read32(r));
                }
            }
            return elapsed;
        };
        both_write(m::KSI_R, 200);
        both_write(m::N, 1);
        EXPECT_EQ(both_write(m::COS, 0x7000), sc_time(49.1, SC_NS));
        both_write(m::N, 8);
        EXPECT_EQ(both_write(m::COS, 0x7000), sc_time(77, SC_NS));
        std::mt19937_64 rng(10);
        for (int p = 0; p < 60; ++p) {
            if (p % 4 == 0) both_write(m::N, static_cast<uint32_t>(rng() % 1000 + 1));
            both_write(m::COS, static_cast<uint32_t>(rng() % (spec::cos_one + 1)));
        }
    });
    ASSERT_TRUE(run_to_completion(b, limit));
    for (const auto* d : {b.pin.dev_sat.get(), b.pin.dev_wrap.get()}) {
        EXPECT_EQ(d->chk_load.violations(), 0u);
        EXPECT_EQ(d->chk_clk.violations(), 0u);
    }
}

// A whole raster line (1024 pixels) in one burst, each mode against the golden model and the
// hand-worked time, then the same results by debug transport. `total` is the burst's time by hand:
// UA 60553 20 ns a pixel; squared (n = 300: k = 8) the first pixel from 0 ns (loosely timed: no
// time has passed) falls at 10 ns, is sampled at 20 ns and ends (k + 3) x 20 ns later, at
// 240.1 ns; from 32 ns (pin-accurate: after four 8 ns loads) it falls at 50 ns and ends at
// 280.1 ns; each further pixel (k + 4) x 20 ns (from a done edge: 10 ns to the next falling edge,
// 10 more to the sampling edge, k + 3 clocks).
template <class V, tlm_timing T>
void whole_line(const sc_time& total) {
    bench<typename V::gen> b("b", T, [total](tlm_initiator& i) {
        ASSERT_EQ(i.write32(m::N, 300), tlm::TLM_OK_RESPONSE);
        ASSERT_EQ(i.write32(m::KSI_R, 255), tlm::TLM_OK_RESPONSE);
        ASSERT_EQ(i.write32(m::KSI_G, 90), tlm::TLM_OK_RESPONSE);
        ASSERT_EQ(i.write32(m::KSI_B, 3), tlm::TLM_OK_RESPONSE);
        std::vector<uint16_t> codes(m::BLOCK_PIXELS);
        for (std::size_t p = 0; p < codes.size(); ++p)  // a highlight across the line: cos rises to 1, falls
            codes[p] = static_cast<uint16_t>(spec::cos_one - std::abs(static_cast<long>(p) - 512) * 24);
        const sc_time start = sc_core::sc_time_stamp();
        ASSERT_EQ(i.access(tlm::TLM_WRITE_COMMAND, m::COS_BLOCK, reinterpret_cast<unsigned char*>(codes.data()),
                           2 * m::BLOCK_PIXELS),
                  tlm::TLM_OK_RESPONSE);
        EXPECT_EQ(i.last_delay + i.last_elapsed, total);
        EXPECT_EQ(total, burst_time<V>(start, 300, m::BLOCK_PIXELS));
        std::vector<uint32_t> res(4 * m::BLOCK_PIXELS);
        ASSERT_EQ(i.access(tlm::TLM_READ_COMMAND, m::RESULT_BLOCK, reinterpret_cast<unsigned char*>(res.data()),
                           16 * m::BLOCK_PIXELS),
                  tlm::TLM_OK_RESPONSE);
        std::size_t bad = 0;
        for (std::size_t p = 0; p < m::BLOCK_PIXELS; ++p) {
            const auto g = V::golden(300, codes[p], {255, 90, 3}, overflow_mode::saturate);
            bad += res[4 * p] != g.out[0] || res[4 * p + 1] != g.out[1] || res[4 * p + 2] != g.out[2] ||
                   res[4 * p + 3] != codes[p];
        }
        EXPECT_EQ(bad, 0u);
        EXPECT_EQ(res[4 * 512], 255u << 8) << "cos = 1: the BRDF is 1.0, R = k_s*I exactly (hand-worked)";
        const auto dbg = i.debug_read(m::RESULT_BLOCK, 16 * m::BLOCK_PIXELS);
        ASSERT_EQ(dbg.size(), 16 * m::BLOCK_PIXELS);
        EXPECT_EQ(0, std::memcmp(dbg.data(), res.data(), dbg.size()));
    });
    ASSERT_TRUE(run_to_completion(b, sc_core::sc_time(1, sc_core::SC_SEC)));
}
const sc_time fig3_line = sc_time(20, SC_NS) * 1024.0;
const sc_time squared_rest = sc_time(240, SC_NS) * 1023.0;
TEST(SpecularTlmBurst, WholeLineLooselyTimed) { whole_line<ua60553_v, tlm_timing::loosely_timed>(fig3_line); }
TEST(SpecularTlmBurst, WholeLinePinAccurate) { whole_line<ua60553_v, tlm_timing::pin_accurate>(fig3_line); }
TEST(SpecularTlmBurst, WholeLineLooselyTimedSquared) {
    whole_line<squared_v, tlm_timing::loosely_timed>(sc_time(240.1, SC_NS) + squared_rest);
}
TEST(SpecularTlmBurst, WholeLinePinAccurateSquared) {
    whole_line<squared_v, tlm_timing::pin_accurate>(sc_time(280.1 - 32, SC_NS) + squared_rest);
}

// Debug transport: register reads without side effects or time (a not-ready result too, with no
// warning), reads spanning a region's end refused, debug writes refused.
template <class Gen>
void debug_read_has_no_side_effects(uint32_t variant) {
    bench<Gen> b("b", tlm_timing::pin_accurate, [variant](tlm_initiator& i) {
        ASSERT_EQ(i.write32(m::N, 9), tlm::TLM_OK_RESPONSE);
        const sc_time t0 = sc_core::sc_time_stamp();
        auto regs = i.debug_read(0, m::REG_END);
        ASSERT_EQ(regs.size(), m::REG_END);
        uint32_t n, ctl, res;
        std::memcpy(&n, regs.data() + m::N, 4);
        std::memcpy(&ctl, regs.data() + m::CONTROL, 4);
        std::memcpy(&res, regs.data() + m::RESULT_R, 4);
        EXPECT_EQ(n, 9u);
        EXPECT_EQ(ctl, (variant << 4) | m::CONTROL_TIMING) << "variant, pin-accurate";
        EXPECT_EQ(res, 0u);
        EXPECT_EQ(i.debug_read(m::N + 1, 2).size(), 2u) << "any byte range within the registers";
        EXPECT_EQ(i.debug_read(m::REG_END - 4, 8).size(), 0u) << "past the register file";
        EXPECT_EQ(i.debug_read(m::RESULT_BLOCK_END - 4, 8).size(), 0u) << "past the result window";
        unsigned char w[4] = {1, 0, 0, 0};
        EXPECT_EQ(i.debug(tlm::TLM_WRITE_COMMAND, m::N, w, 4), 0u) << "debug writes are not supported";
        EXPECT_EQ(i.read32(m::N), 9u);
        EXPECT_EQ(i.read32(m::STATUS), 0u) << "no error logged, still not ready";
        EXPECT_EQ(sc_core::sc_time_stamp(), t0);
    });
    ASSERT_TRUE(run_to_completion(b, limit));
}
TEST(SpecularTlmDebug, DebugReadHasNoSideEffects) { debug_read_has_no_side_effects<a_gen_rom>(1); }
TEST(SpecularTlmDebug, DebugReadHasNoSideEffectsSquared) { debug_read_has_no_side_effects<squared_device>(3); }

}  // namespace

}  // namespace test_specular_tlm

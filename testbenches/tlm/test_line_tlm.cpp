// TLM-2.0 wrapper of the raster-line interpolator (modules/tlm/line_tlm.h): the register map,
// every error response with the state unchanged, both timing modes against the golden chain
// (interp::golden_interp_line, src/golden, called here independently of the wrapper) and against
// each other on random bursts, the burst time against the unit's documented latency (pixels + 1
// clocks), the incoming delay and debug transport. Each TEST elaborates one bench in its own
// process (ctest); SHADING_TRACE=<dir> writes <dir>/<Suite.Test>.vcd.
#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <vector>

#include "testbenches/common/report_log.h"
#include "testbenches/common/sim_guard.h"
#include "core/report_ids.h"
#include "golden/interp_golden.h"
#include "tlm/line_tlm.h"
#include "tlm_bad_access.h"
#include "tlm_initiator.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_line_tlm {

using namespace shading;
using namespace shading::tb;
using sc_core::SC_NS;
using sc_core::sc_time;
namespace m = shading::line_tlm_map;
namespace ip = shading::interp;

namespace {

// The configurations under test: the README's default line (m = 5, case 1, shift-and-add /3) and
// a short-interval one with the other sample set and the exact divider.
struct cfg_m5 {
    static constexpr unsigned M = 5;
    static constexpr ip::sample_set set = ip::sample_set::case1;
    static constexpr ip::div3_mode div = ip::div3_mode::shift_add;
    static constexpr uint32_t control = 5u | (3u << 12);
};
struct cfg_m3 {
    static constexpr unsigned M = 3;
    static constexpr ip::sample_set set = ip::sample_set::case2;
    static constexpr ip::div3_mode div = ip::div3_mode::exact;
    static constexpr uint32_t control = 3u | (1u << 4) | (1u << 5) | (3u << 12);
};
template <class C>
using wrapper = line_tlm<C::M, C::set, C::div>;

// One initiator bound to one wrapper, or to a pair (LT and pin-accurate) through two sockets.
template <class C>
using bench = tlm_bench<wrapper<C>>;
template <class C>
using pair_bench = tlm_pair_bench<wrapper<C>>;

const sc_time limit(1, sc_core::SC_SEC);

// K intervals as INTERVAL_BLOCK bytes: I1..I4 (16 bits each), LEN (32 bits), reserved.
std::vector<unsigned char> encode(const std::vector<ip::interval_samples>& ivs, uint32_t reserved = 0) {
    std::vector<unsigned char> b(16 * ivs.size());
    for (std::size_t k = 0; k < ivs.size(); ++k) {
        for (unsigned s = 0; s < 4; ++s) {
            const uint16_t v = static_cast<uint16_t>(ivs[k].i[s]);
            std::memcpy(&b[16 * k + 2 * s], &v, 2);
        }
        const uint32_t l = ivs[k].len;
        std::memcpy(&b[16 * k + 8], &l, 4);
        std::memcpy(&b[16 * k + 12], &reserved, 4);
    }
    return b;
}

std::vector<ip::interval_samples> random_burst(std::mt19937_64& rng, unsigned n, std::size_t max_intervals) {
    std::vector<ip::interval_samples> v(rng() % max_intervals + 1);
    for (auto& iv : v) {
        for (auto& s : iv.i) s = rng() % 0x10000;  // the whole Q8.8 sample bus
        iv.len = static_cast<unsigned>(rng() % n + 1);
    }
    return v;
}

tlm::tlm_response_status write_burst(tlm_initiator& i, const std::vector<ip::interval_samples>& ivs,
                                     std::size_t first = 0) {
    auto b = encode(ivs);
    return i.access(tlm::TLM_WRITE_COMMAND, m::INTERVAL_BLOCK + 16 * first, b.data(), static_cast<unsigned>(b.size()));
}

std::vector<uint32_t> read_pixels(tlm_initiator& i, std::size_t count) {
    std::vector<uint32_t> px(count, 0xDEADBEEF);
    EXPECT_EQ(i.access(tlm::TLM_READ_COMMAND, m::PIXEL_BLOCK, reinterpret_cast<unsigned char*>(px.data()),
                       static_cast<unsigned>(4 * count)),
              tlm::TLM_OK_RESPONSE);
    return px;
}

template <class C>
std::vector<uint32_t> golden(const std::vector<ip::interval_samples>& ivs) {
    const auto g = ip::golden_interp_line(ivs, C::M, C::set, C::div);
    return std::vector<uint32_t>(g.begin(), g.end());
}

std::size_t pixels_of(const std::vector<ip::interval_samples>& ivs) {
    std::size_t n = 0;
    for (const auto& iv : ivs) n += iv.len;
    return n;
}

// Every byte of the state visible through debug transport, STATUS's error log masked.
std::vector<unsigned char> snapshot(tlm_initiator& i) {
    auto s = i.debug_read(0, m::REG_END);
    s[m::STATUS] &= static_cast<unsigned char>(~m::ERR_MASK);
    auto a = i.debug_read(m::INTERVAL_BLOCK, m::INTERVAL_BLOCK_END - m::INTERVAL_BLOCK);
    auto p = i.debug_read(m::PIXEL_BLOCK, m::PIXEL_BLOCK_END - m::PIXEL_BLOCK);
    s.insert(s.end(), a.begin(), a.end());
    s.insert(s.end(), p.begin(), p.end());
    return s;
}

// Register map: reset values, read-only CONTROL fields, a hand-worked flat interval, READY and the
// pixel count, the reserved word, the interval window read back.
TEST(LineTlm, RegisterMap) {
    bench<cfg_m5> b("b", tlm_timing::loosely_timed, [](tlm_initiator& i) {
        EXPECT_EQ(i.read32(m::STATUS), 0u) << "no burst yet";
        EXPECT_EQ(i.read32(m::CONTROL), cfg_m5::control) << "M = 5, case 1, shift-add, whole sum, LT, cubic";
        ASSERT_EQ(i.write32(m::CONTROL, 0x7FFFFFFFu), tlm::TLM_OK_RESPONSE);
        EXPECT_EQ(i.read32(m::CONTROL), cfg_m5::control) << "configuration fields are read-only";
        // Flat shading, I = 100.0 (Q8.8 0x6400): A = B = C = 0, D = I1, every pixel 100.0 in Q16.16
        // (hand-worked: the /3 error of the whole sum is A/128 = 0).
        std::vector<ip::interval_samples> flat{{{0x6400, 0x6400, 0x6400, 0x6400}, 32}, {{0x6400, 0x6400, 0x6400, 0x6400}, 7}};
        auto bytes = encode(flat, 0xFFFFFFFFu);
        ASSERT_EQ(i.access(tlm::TLM_WRITE_COMMAND, m::INTERVAL_BLOCK, bytes.data(), 32), tlm::TLM_OK_RESPONSE);
        EXPECT_EQ(i.read32(m::STATUS), m::STATUS_READY | (39u << 16));
        const auto px = read_pixels(i, 39);
        for (std::size_t p = 0; p < px.size(); ++p) ASSERT_EQ(px[p], 100u << 16) << "pixel " << p;
        EXPECT_EQ(px, golden<cfg_m5>(flat));
        auto back = encode(flat, 0);  // the reserved word reads 0
        std::vector<unsigned char> rd(32);
        ASSERT_EQ(i.access(tlm::TLM_READ_COMMAND, m::INTERVAL_BLOCK, rd.data(), 32), tlm::TLM_OK_RESPONSE);
        EXPECT_EQ(rd, back);
        // A ramp 0 -> 96 (case 1: t = 0, 1/4, 1/2, 1) at interval 5: pixel 0 is D = I1 = 0 exactly.
        std::vector<ip::interval_samples> ramp{{{0, 24 << 8, 48 << 8, 96 << 8}, 32}};
        ASSERT_EQ(write_burst(i, ramp, 5), tlm::TLM_OK_RESPONSE);
        EXPECT_EQ(i.read32(m::STATUS), m::STATUS_READY | (32u << 16)) << "the last burst's pixels";
        const auto r = read_pixels(i, 32);
        EXPECT_EQ(r[0], 0u);
        EXPECT_EQ(r, golden<cfg_m5>(ramp));
        uint32_t p32 = 0;
        EXPECT_EQ(i.read32(m::PIXEL_BLOCK + 4 * 32, p32), tlm::TLM_GENERIC_ERROR_RESPONSE) << "past the burst";
        EXPECT_EQ(i.read32(m::STATUS), m::STATUS_READY | m::ERR_NOT_READY | (32u << 16));
        ASSERT_EQ(i.write32(m::CONTROL, m::CONTROL_CLEAR_ERR), tlm::TLM_OK_RESPONSE);
        EXPECT_EQ(i.read32(m::STATUS), m::STATUS_READY | (32u << 16));
    });
    report_log::get().expect(msg::tlm);
    ASSERT_TRUE(run_to_completion(b, limit));
}

// Every error response, its warning, its log bit; the state unchanged; no time charged.
TEST(LineTlmErrors, EveryErrorLeavesStateUnchanged) {
    report_log::get().expect(msg::tlm);
    const unsigned before = report_log::get().count(msg::tlm);
    bench<cfg_m5> b("b", tlm_timing::pin_accurate, [](tlm_initiator& i) {
        uint32_t v = 0;
        EXPECT_EQ(i.read32(m::PIXEL_BLOCK, v), tlm::TLM_GENERIC_ERROR_RESPONSE) << "no burst yet";
        ASSERT_EQ(i.write32(m::CONTROL, m::CONTROL_CLEAR_ERR), tlm::TLM_OK_RESPONSE);
        std::mt19937_64 rng(4);
        const auto ivs = random_burst(rng, 32, 4);
        ASSERT_EQ(write_burst(i, ivs), tlm::TLM_OK_RESPONSE);
        const unsigned px = static_cast<unsigned>(pixels_of(ivs));
        auto badlen = encode({{{1, 2, 3, 4}, 32}, {{1, 2, 3, 4}, 33}});
        auto zerolen = encode({{{1, 2, 3, 4}, 0}});
        expect_bad_accesses(
            i,
            {
                {"unmapped register", tlm::TLM_WRITE_COMMAND, 0x008, 4, false, 0, tlm::TLM_ADDRESS_ERROR_RESPONSE, m::ERR_ADDRESS},
                {"between windows", tlm::TLM_READ_COMMAND, 0x2000, 4, false, 0, tlm::TLM_ADDRESS_ERROR_RESPONSE, m::ERR_ADDRESS},
                {"past the map", tlm::TLM_READ_COMMAND, 0x20000, 4, false, 0, tlm::TLM_ADDRESS_ERROR_RESPONSE, m::ERR_ADDRESS},
                {"2-byte register", tlm::TLM_READ_COMMAND, m::STATUS, 2, false, 0, tlm::TLM_BURST_ERROR_RESPONSE, m::ERR_SIZE},
                {"8-byte register", tlm::TLM_WRITE_COMMAND, m::STATUS, 8, false, 0, tlm::TLM_BURST_ERROR_RESPONSE, m::ERR_SIZE},
                {"misaligned register", tlm::TLM_WRITE_COMMAND, m::CONTROL + 1, 4, false, 0, tlm::TLM_BURST_ERROR_RESPONSE, m::ERR_SIZE},
                {"interval of 8 bytes", tlm::TLM_WRITE_COMMAND, m::INTERVAL_BLOCK, 8, false, 0, tlm::TLM_BURST_ERROR_RESPONSE, m::ERR_SIZE},
                {"misaligned interval", tlm::TLM_WRITE_COMMAND, m::INTERVAL_BLOCK + 8, 16, false, 0, tlm::TLM_BURST_ERROR_RESPONSE, m::ERR_SIZE},
                {"intervals past the end", tlm::TLM_WRITE_COMMAND, m::INTERVAL_BLOCK_END - 16, 32, false, 0, tlm::TLM_BURST_ERROR_RESPONSE, m::ERR_SIZE, badlen.data()},
                {"streaming", tlm::TLM_WRITE_COMMAND, m::INTERVAL_BLOCK, 32, false, 16, tlm::TLM_BURST_ERROR_RESPONSE, m::ERR_SIZE, badlen.data()},
                {"misaligned pixel", tlm::TLM_READ_COMMAND, m::PIXEL_BLOCK + 2, 4, false, 0, tlm::TLM_BURST_ERROR_RESPONSE, m::ERR_SIZE},
                {"byte enables", tlm::TLM_WRITE_COMMAND, m::CONTROL, 4, true, 0, tlm::TLM_BYTE_ENABLE_ERROR_RESPONSE, m::ERR_BYTE_ENABLE},
                {"write STATUS", tlm::TLM_WRITE_COMMAND, m::STATUS, 4, false, 0, tlm::TLM_COMMAND_ERROR_RESPONSE, m::ERR_COMMAND},
                {"write pixel window", tlm::TLM_WRITE_COMMAND, m::PIXEL_BLOCK, 16, false, 0, tlm::TLM_COMMAND_ERROR_RESPONSE, m::ERR_COMMAND},
                {"pixels past the burst", tlm::TLM_READ_COMMAND, m::PIXEL_BLOCK + 4 * (px - 1), 8, false, 0, tlm::TLM_GENERIC_ERROR_RESPONSE, m::ERR_NOT_READY},
                {"len 33 > 2^M", tlm::TLM_WRITE_COMMAND, m::INTERVAL_BLOCK, 32, false, 0, tlm::TLM_GENERIC_ERROR_RESPONSE, m::ERR_LENGTH, badlen.data()},
                {"len 0", tlm::TLM_WRITE_COMMAND, m::INTERVAL_BLOCK + 16, 16, false, 0, tlm::TLM_GENERIC_ERROR_RESPONSE, m::ERR_LENGTH, zerolen.data()},
            },
            [](tlm_initiator& t) { return t.read32(m::STATUS) & m::ERR_MASK; },
            [](tlm_initiator& t) { return t.write32(m::CONTROL, m::CONTROL_CLEAR_ERR); }, snapshot);
        // The burst's pixels are all readable, and they are the golden chain's.
        EXPECT_EQ(read_pixels(i, px), golden<cfg_m5>(ivs));
    });
    ASSERT_TRUE(run_to_completion(b, limit));
    EXPECT_EQ(report_log::get().count(msg::tlm) - before, 18u) << "one warning per bad access";
    EXPECT_EQ(b.dut.unit->phase_violations(), 0u);
}

template <class C>
class LineTlmModes : public ::testing::Test {};
using configs = ::testing::Types<cfg_m5, cfg_m3>;
TYPED_TEST_SUITE(LineTlmModes, configs);

// Random bursts in loosely-timed mode against the golden chain; every burst annotated with
// pixels + 1 clocks (20 ns each), never waited.
TYPED_TEST(LineTlmModes, LooselyTimedMatchesGolden) {
    using C = TypeParam;
    bench<C> b("b", tlm_timing::loosely_timed, [](tlm_initiator& i) {
        std::mt19937_64 rng(60553 + C::M);
        std::size_t mismatches = 0, pixels = 0;
        while (pixels < 20000) {
            const auto ivs = random_burst(rng, 1u << C::M, 24);
            const std::size_t first = rng() % (m::BLOCK_INTERVALS - ivs.size() + 1);
            ASSERT_EQ(write_burst(i, ivs, first), tlm::TLM_OK_RESPONSE);
            const std::size_t n = pixels_of(ivs);
            ASSERT_EQ(i.last_delay, sc_time(20.0 * static_cast<double>(n + 1), SC_NS));
            ASSERT_EQ(i.last_elapsed, sc_core::SC_ZERO_TIME) << "loosely timed: annotated, never waited";
            mismatches += read_pixels(i, n) != golden<C>(ivs);
            pixels += n;
        }
        EXPECT_EQ(mismatches, 0u);
    });
    ASSERT_TRUE(run_to_completion(b, limit));
}

// Random bursts through the pin-accurate wrapper and the loosely-timed one: identical pixels, equal
// to the golden chain, and the pin-accurate burst takes exactly the time the other annotates, the
// unit's pixels + 1 clocks; then the whole interval window in one burst.
TYPED_TEST(LineTlmModes, PinAccurateMatchesLooselyTimed) {
    using C = TypeParam;
    pair_bench<C> b("b", [](tlm_initiator& lt, tlm_initiator& pin) {
        std::mt19937_64 rng(22802 + C::M);
        auto both = [&](const std::vector<ip::interval_samples>& ivs, std::size_t first) {
            ASSERT_EQ(write_burst(lt, ivs, first), tlm::TLM_OK_RESPONSE);
            ASSERT_EQ(write_burst(pin, ivs, first), tlm::TLM_OK_RESPONSE);
            const std::size_t n = pixels_of(ivs);
            EXPECT_EQ(lt.last_delay, sc_time(20.0 * static_cast<double>(n + 1), SC_NS));
            EXPECT_EQ(pin.last_elapsed, lt.last_delay) << n << " pixels";
            EXPECT_EQ(pin.last_delay, sc_core::SC_ZERO_TIME);
            const auto a = read_pixels(lt, n), p = read_pixels(pin, n);
            EXPECT_EQ(a, p) << "burst of " << ivs.size() << " intervals at " << first;
            EXPECT_EQ(p, golden<C>(ivs));
            EXPECT_EQ(lt.read32(m::STATUS), pin.read32(m::STATUS) & ~m::ERR_MASK);
        };
        for (int burst = 0; burst < 60; ++burst) {
            const auto ivs = random_burst(rng, 1u << C::M, 8);
            both(ivs, rng() % (m::BLOCK_INTERVALS - ivs.size() + 1));
        }
        std::vector<ip::interval_samples> all(m::BLOCK_INTERVALS);
        for (auto& iv : all) {
            for (auto& s : iv.i) s = rng() % 0x10000;
            iv.len = 1u << C::M;
        }
        all.back().len = 1;  // a raster line's short last interval
        both(all, 0);
        EXPECT_EQ(lt.debug_read(m::INTERVAL_BLOCK, 4096), pin.debug_read(m::INTERVAL_BLOCK, 4096));
    });
    ASSERT_TRUE(run_to_completion(b, sc_time(10, sc_core::SC_SEC)));
    EXPECT_EQ(b.pin.unit->phase_violations(), 0u);
}

// The pin-accurate wrapper honours the caller's delay first (it synchronises), then runs the
// unit's clocks; reads and CONTROL cost nothing.
TEST(LineTlmTiming, PinAccurateWaitsIncomingDelayThenClocks) {
    bench<cfg_m3> b("b", tlm_timing::pin_accurate, [](tlm_initiator& i) {
        i.delay_in = sc_time(7, SC_NS);
        std::vector<ip::interval_samples> ivs{{{0x100, 0x200, 0x300, 0x400}, 8}, {{0x400, 0x300, 0x200, 0x100}, 3}};
        ASSERT_EQ(write_burst(i, ivs), tlm::TLM_OK_RESPONSE);
        EXPECT_EQ(i.last_elapsed, sc_time(7 + 20 * 12, SC_NS)) << "7 ns, then 11 pixels + 1 clocks";
        EXPECT_EQ(i.last_delay, sc_core::SC_ZERO_TIME);
        EXPECT_EQ(i.read32(m::STATUS), m::STATUS_READY | (11u << 16));
        EXPECT_EQ(i.last_elapsed, sc_core::SC_ZERO_TIME) << "a read costs no clock";
        EXPECT_EQ(i.last_delay, sc_time(7, SC_NS)) << "and leaves the delay untouched";
        EXPECT_EQ(i.read32(m::CONTROL), cfg_m3::control | m::CONTROL_TIMING);
        i.delay_in = sc_core::SC_ZERO_TIME;
        EXPECT_EQ(read_pixels(i, 11), golden<cfg_m3>(ivs));
        ASSERT_EQ(write_burst(i, {{{0, 0, 0, 0}, 1}}), tlm::TLM_OK_RESPONSE);
        EXPECT_EQ(i.last_elapsed, sc_time(40, SC_NS)) << "one pixel: 2 clocks";
    });
    ASSERT_TRUE(run_to_completion(b, limit));
    EXPECT_EQ(b.dut.unit->phase_violations(), 0u);
}

// Debug transport: reads without side effects or time (pixels before any burst too, with no
// warning), ranges crossing a region's end refused, debug writes refused.
TEST(LineTlmDebug, DebugReadHasNoSideEffects) {
    bench<cfg_m5> b("b", tlm_timing::pin_accurate, [](tlm_initiator& i) {
        const sc_time t0 = sc_core::sc_time_stamp();
        EXPECT_EQ(i.debug_read(m::PIXEL_BLOCK, 16).size(), 16u) << "no readiness check";
        std::vector<ip::interval_samples> ivs{{{0x1234, 0x2345, 0x3456, 0x4567}, 9}};
        ASSERT_EQ(write_burst(i, ivs, 3), tlm::TLM_OK_RESPONSE);
        const sc_time t1 = sc_core::sc_time_stamp();
        EXPECT_EQ(t1 - t0, sc_time(200, SC_NS));
        auto regs = i.debug_read(0, m::REG_END);
        ASSERT_EQ(regs.size(), m::REG_END);
        uint32_t st, ctl;
        std::memcpy(&st, regs.data() + m::STATUS, 4);
        std::memcpy(&ctl, regs.data() + m::CONTROL, 4);
        EXPECT_EQ(st, m::STATUS_READY | (9u << 16));
        EXPECT_EQ(ctl, cfg_m5::control | m::CONTROL_TIMING);
        EXPECT_EQ(i.debug_read(m::INTERVAL_BLOCK + 48, 16), encode(ivs));
        const auto px = i.debug_read(m::PIXEL_BLOCK, 36);
        const auto g = golden<cfg_m5>(ivs);
        ASSERT_EQ(px.size(), 36u);
        EXPECT_EQ(0, std::memcmp(px.data(), g.data(), 36));
        EXPECT_EQ(i.debug_read(m::CONTROL + 1, 2).size(), 2u) << "any byte range within the registers";
        EXPECT_EQ(i.debug_read(m::REG_END - 4, 8).size(), 0u) << "past the register file";
        EXPECT_EQ(i.debug_read(m::PIXEL_BLOCK_END - 4, 8).size(), 0u) << "past the pixel window";
        unsigned char w[4] = {0, 0, 0, 0x80};
        EXPECT_EQ(i.debug(tlm::TLM_WRITE_COMMAND, m::CONTROL, w, 4), 0u) << "debug writes are not supported";
        EXPECT_EQ(i.read32(m::STATUS), m::STATUS_READY | (9u << 16)) << "no error logged";
        EXPECT_EQ(sc_core::sc_time_stamp(), t1);
    });
    ASSERT_TRUE(run_to_completion(b, limit));
}

}  // namespace

}  // namespace test_line_tlm

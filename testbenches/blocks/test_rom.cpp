// The ROM block alone (modules/rom.h) against hand-worked values: read after the access time,
// the word beyond the table, an address glitch shorter than the access time, a bad table.
#include <gtest/gtest.h>

#include <systemc>

#include "testbenches/common/report_log.h"
#include "core/report_ids.h"
#include "blocks/rom.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_rom {

using namespace shading;
using sc_core::SC_NS;
using sc_core::sc_time;

namespace {
struct rom_bench {
    sc_core::sc_signal<sc_dt::sc_uint<3>> addr{"addr"};
    sc_core::sc_signal<sc_dt::sc_uint<5>> data{"data"};
    rom<3, 5> dut;
    rom_bench(std::vector<uint64_t> content, uint64_t blank = 0)
        : dut("rom", std::move(content), sc_time(2, SC_NS), blank) {
        dut.addr(addr);
        dut.data(data);
    }
};
}  // namespace

TEST(Rom, ReadsTheWordAfterTheAccessTimeAndBlankBeyondTheTable) {
    rom_bench b({0x11, 0x1f, 0x05}, 0x0a);  // 3 of 8 words programmed, blank word 0x0a
    EXPECT_EQ(b.dut.bits, 8u * 5u);
    sc_core::sc_start(sc_time(5, SC_NS));
    EXPECT_EQ(b.data.read(), 0x11u) << "word 0, read at initialisation";
    b.addr.write(1);
    sc_core::sc_start(sc_time(1, SC_NS));
    EXPECT_EQ(b.data.read(), 0x11u) << "1 ns after the change: still word 0";
    sc_core::sc_start(sc_time(1.5, SC_NS));
    EXPECT_EQ(b.data.read(), 0x1fu) << "2 ns = access time: word 1 (sampled at 2.5 ns)";
    b.addr.write(2);
    sc_core::sc_start(sc_time(3, SC_NS));
    EXPECT_EQ(b.data.read(), 0x05u);
    b.addr.write(6);  // beyond the table
    sc_core::sc_start(sc_time(3, SC_NS));
    EXPECT_EQ(b.data.read(), 0x0au);
    EXPECT_EQ(b.dut.word(7), 0x0au);
    EXPECT_EQ(b.dut.word(0), 0x11u);
}

TEST(Rom, AnAddressGlitchShorterThanTheAccessTimeIsSwallowed) {
    rom_bench b({1, 2, 3, 4});
    sc_core::sc_start(sc_time(5, SC_NS));
    EXPECT_EQ(b.data.read(), 1u);
    b.addr.write(3);
    sc_core::sc_start(sc_time(1, SC_NS));
    b.addr.write(0);  // back before word 3 appeared
    sc_core::sc_start(sc_time(1.5, SC_NS));
    EXPECT_EQ(b.data.read(), 1u) << "word 3 must never reach the output";
    sc_core::sc_start(sc_time(5, SC_NS));
    EXPECT_EQ(b.data.read(), 1u);
}

TEST(Rom, AWordWiderThanTheBusIsAConfigurationError) {
    tb::report_log::get().expect(msg::config);
    const unsigned before = tb::report_log::get().count(msg::config);
    rom_bench b({1, 0x20});  // 0x20 needs 6 bits
    EXPECT_EQ(tb::report_log::get().count(msg::config), before + 1);
}

}  // namespace test_rom

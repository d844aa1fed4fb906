// The new block kinds alone against hand-worked values: multiplexer (with an unused select code),
// key block, shifter (sign extension and floor), shift-and-add network and the paper's /3.
// Each TEST elaborates its own blocks (one process per test).
#include <gtest/gtest.h>

#include <systemc>

#include "testbenches/common/report_log.h"
#include "blocks/adder.h"
#include "blocks/div3_shift_add.h"
#include "blocks/inverter_bank.h"
#include "blocks/key_block.h"
#include "blocks/mux.h"
#include "blocks/shift_add_network.h"
#include "blocks/shifter.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_interp_blocks {

using namespace shading;
using sc_core::SC_NS;
using sc_core::sc_start;

template <unsigned W>
using bus = sc_core::sc_signal<sc_dt::sc_uint<W>>;

TEST(InterpBlocks, MuxSelectsAndDrivesZeroForUnusedCodes) {
    sc_core::sc_vector<bus<8>> in("in", 5);
    bus<3> sel("sel");
    bus<8> y("y");
    mux<8, 5> mx("mx");
    for (unsigned i = 0; i < 5; ++i) mx.in[i](in[i]), in[i].write(10 + i);
    mx.sel(sel); mx.y(y);
    for (unsigned s : {4u, 0u, 2u}) {
        sel.write(s);
        sc_start(1, SC_NS);
        EXPECT_EQ(y.read(), 10u + s);
    }
    sel.write(7);  // no input 7: defined result 0
    sc_start(1, SC_NS);
    EXPECT_EQ(y.read(), 0u);
}

TEST(InterpBlocks, KeyBlockPassesOrForcesZero) {
    bus<32> x("x"), y("y");
    sc_core::sc_signal<bool> pass("pass");
    key_block<32> bk("bk");
    bk.x(x); bk.pass(pass); bk.y(y);
    x.write(0xDEADBEEF);
    pass.write(true);
    sc_start(1, SC_NS);
    EXPECT_EQ(y.read(), 0xDEADBEEFu);
    pass.write(false);
    sc_start(1, SC_NS);
    EXPECT_EQ(y.read(), 0u);
}

TEST(InterpBlocks, ShifterSignExtendsAndFloors) {
    bus<8> x("x");
    bus<16> up("up"), down("down");
    shifter<8, 16, true> sh_up("sh_up", 4);
    shifter<8, 16, true> sh_down("sh_down", -2);
    sh_up.x(x); sh_up.y(up);
    sh_down.x(x); sh_down.y(down);
    x.write(0xFB);  // -5
    sc_start(1, SC_NS);
    EXPECT_EQ(up.read(), 0xFFB0u);    // -80
    EXPECT_EQ(down.read(), 0xFFFEu);  // floor(-5/4) = -2
}

TEST(InterpBlocks, ShiftAddNetworkAndFig2DivisionBy3) {
    sc_core::sc_vector<bus<16>> in("in", 2);
    bus<24> y("y"), x("x");
    bus<32> q("q");
    // 10 I0 - 3 I1 = 8 I0 + 2 I0 - 2 I1 - I1 (the interpolation paper: "10I = 8I + 2I").
    shift_add_network<16, 24> net("net", 2, {{0, 3, false}, {0, 1, false}, {1, 1, true}, {1, 0, true}});
    net.in[0](in[0]); net.in[1](in[1]); net.y(y);
    div3_shift_add<24, 32, 8> div3("div3");  // Q.8 -> Q.16
    div3.x(x); div3.y(q);
    in[0].write(7);
    in[1].write(100);
    x.write(0xFFFF00);  // -1.0 in Q16.8
    sc_start(20, SC_NS);
    EXPECT_EQ(y.read(), sc_dt::sc_uint<24>(70 - 300 + (1 << 24)));  // -230, two's complement
    EXPECT_EQ(q.read(), sc_dt::sc_uint<32>(static_cast<uint32_t>(-22016)));  // -0.3359375 = -86*256/65536
}

// The partial-sum unit's subtractor (coef_unit_cubic_partial_sum.h): an inverter bank and an adder with
// carry-in 1, minuend + ~subtrahend + 1, on Q16.16 buses. Hand-worked: case 1 A for a flat line of
// 1.0, 72 * 43/128 = 24.1875 (the /3 of the divided part, 1585152 LSB) minus 24 (1572864) = 0.1875
// (12288); and 1 - 2 = -1 wraps to two's complement.
TEST(InterpBlocks, SubtractorFromInverterBankAndAdderWithCarryIn) {
    bus<32> minuend("minuend"), subtrahend("subtrahend"), inverted("inverted"), diff("diff");
    bus<24> divided("divided");
    sc_core::sc_signal<bool> carry1("carry1");
    div3_shift_add<24, 32, 8> div3("div3");  // Q16.8 -> Q16.16
    inverter_bank<32> inv("inv");
    adder<32, 32, 32, true, true> sub("sub");
    div3.x(divided); div3.y(minuend);
    inv.x(subtrahend); inv.y(inverted);
    sub.a(minuend); sub.b(inverted); sub.cin(carry1); sub.s(diff);
    carry1.write(true);
    divided.write(72 * 256);          // 72.0, Q16.8
    subtrahend.write(24u * 65536u);   // 24.0, Q16.16
    sc_start(20, SC_NS);
    EXPECT_EQ(minuend.read(), 1585152u);
    EXPECT_EQ(diff.read(), 12288u);
    divided.write(0);
    subtrahend.write(65536u);         // 0 - 1.0
    sc_start(20, SC_NS);
    EXPECT_EQ(diff.read(), sc_dt::sc_uint<32>(static_cast<uint32_t>(-65536)));
}

}  // namespace test_interp_blocks

// Each block alone, against hand-worked values. Every TEST elaborates its own blocks, so ctest
// runs each in its own process (gtest_discover_tests).
#include <gtest/gtest.h>

#include <systemc>

#include "blocks/adder.h"
#include "testbenches/common/report_log.h"
#include "blocks/constant.h"
#include "blocks/eq_cmp.h"
#include "blocks/inverter_bank.h"
#include "blocks/mul.h"
#include "blocks/ram.h"
#include "blocks/reg.h"
#include "blocks/saturator.h"
#include "blocks/synchroniser.h"
#include "core/report_ids.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_blocks {

using namespace shading;
using sc_core::SC_NS;
using sc_core::SC_PS;
using sc_core::sc_start;
using sc_core::sc_time;

template <unsigned W>
using bus = sc_core::sc_signal<sc_dt::sc_uint<W>>;

TEST(Register, LatchesOnFallingEdgeOnlyAfterClockToQ) {
    sc_core::sc_signal<bool> ctl("ctl");
    bus<10> d("d"), q("q");
    reg<10> rg("rg", sc_time(200, SC_PS));
    rg.ctl(ctl); rg.d(d); rg.q(q);

    d.write(513);
    sc_start(1, SC_NS);
    ctl.write(true);  // rising edge: no write
    sc_start(1, SC_NS);
    EXPECT_EQ(q.read(), 0u);
    ctl.write(false);  // falling edge: write, visible 200 ps later
    // sc_start(t) stops before the events at t: step to 1 ps either side of the 200 ps.
    sc_start(199, SC_PS);
    EXPECT_EQ(q.read(), 0u) << "output before clock-to-q elapsed";
    sc_start(2, SC_PS);
    EXPECT_EQ(q.read(), 513u);
    d.write(7);  // data changes while ctl is low: held
    sc_start(5, SC_NS);
    EXPECT_EQ(q.read(), 513u);
    EXPECT_EQ(rg.violations(), 0u);
}

TEST(Register, DataChangingAtTheLatchingEdgeIsReportedAndTheStableValueKept) {
    tb::report_log::get().expect(msg::setup);
    sc_core::sc_signal<bool> ctl("ctl");
    bus<16> d("d"), q("q");
    reg<16> rg("rg");
    rg.ctl(ctl); rg.d(d); rg.q(q);

    d.write(0x1111);
    ctl.write(true);
    sc_start(2, SC_NS);
    d.write(0x2222);  // same delta as the falling edge
    ctl.write(false);
    sc_start(2, SC_NS);
    EXPECT_EQ(q.read(), 0x1111u);
    EXPECT_EQ(rg.violations(), 1u);

    ctl.write(true);
    sc_start(2, SC_NS);
    ctl.write(false);  // edge first ...
    sc_start(sc_core::SC_ZERO_TIME);
    d.write(0x3333);   // ... data one delta later, same instant
    sc_start(2, SC_NS);
    EXPECT_EQ(q.read(), 0x2222u);
    EXPECT_EQ(rg.violations(), 2u);
    EXPECT_EQ(tb::report_log::get().count(msg::setup), 2u);
}

TEST(Multiplier, UnsignedProductIsExact) {
    bus<16> a("a"), b("b");
    bus<32> p("p");
    mul<16, 16, 32> m("m", sc_time(3, SC_NS));
    m.a(a); m.b(b); m.p(p);
    a.write(0xFFFF); b.write(0xFFFF);
    sc_start(2999, SC_PS);
    EXPECT_EQ(p.read(), 0u) << "product before the propagation delay";
    sc_start(2, SC_PS);
    EXPECT_EQ(p.read(), 0xFFFE0001u);  // 65535^2
}

TEST(Multiplier, SignedOperandAndDroppedWiresFloor) {
    bus<8> a("a");
    bus<8> b("b");
    bus<8> p("p");
    mul<8, 8, 8, 2, false, true> m("m");  // unsigned a, two's complement b, 2 low wires dropped
    m.a(a); m.b(b); m.p(p);
    a.write(5); b.write(0xFD);  // 5 * -3 = -15; -15 >> 2 = floor(-3.75) = -4 = 0xFC
    sc_start(5, SC_NS);
    EXPECT_EQ(p.read(), 0xFCu);
    a.write(7); b.write(3);     // 21 >> 2 = 5
    sc_start(5, SC_NS);
    EXPECT_EQ(p.read(), 5u);
}

TEST(Multiplier, InertialDelaySwallowsAPulseShorterThanTheDelay) {
    bus<4> a("a"), b("b");
    bus<8> p("p");
    mul<4, 4, 8> m("m", sc_time(3, SC_NS));
    m.a(a); m.b(b); m.p(p);
    b.write(1);
    sc_start(5, SC_NS);
    a.write(9);          // pulse of 1 ns ...
    sc_start(1, SC_NS);
    a.write(0);          // ... back to 0 before the product could appear
    for (int i = 0; i < 6; ++i) {
        sc_start(1, SC_NS);
        EXPECT_EQ(p.read(), 0u) << "glitch propagated at step " << i;
    }
}

TEST(Adder, TwoComplementSubtractionWithCarryIn) {
    bus<8> a("a"), b("b"), s("s");
    sc_core::sc_signal<bool> cin("cin");
    adder<8, 8, 8> add("add");
    add.a(a); add.b(b); add.cin(cin); add.s(s);
    a.write(20); b.write(static_cast<uint8_t>(~30u)); cin.write(true);  // 20 - 30 = -10 = 0xF6
    sc_start(2, SC_NS);
    EXPECT_EQ(s.read(), 0xF6u);
    a.write(200); b.write(100); cin.write(false);  // 300 wraps to 44
    sc_start(2, SC_NS);
    EXPECT_EQ(s.read(), 44u);
}

TEST(Adder, SignExtendsAndSaturates) {
    bus<12> a("a");
    bus<8> b("b");
    bus<8> s("s");
    sc_core::sc_signal<bool> cin("cin");
    adder<12, 8, 8, true, false> add("add", overflow_mode::saturate, 0, 128);
    add.a(a); add.b(b); add.cin(cin); add.s(s);
    a.write(0xFF0); b.write(10);  // -16 + 10 = -6 -> 0
    sc_start(2, SC_NS);
    EXPECT_EQ(s.read(), 0u);
    a.write(0x7F0); b.write(10);  // 2032 + 10 -> 128
    sc_start(2, SC_NS);
    EXPECT_EQ(s.read(), 128u);
    a.write(0x005); b.write(10); cin.write(true);  // 16, in range
    sc_start(2, SC_NS);
    EXPECT_EQ(s.read(), 16u);
}

TEST(InverterBank, InvertsTheAlignedOperandOnEveryWire) {
    bus<4> x("x");
    bus<10> y("y");
    inverter_bank<4, 10, 3> inv("inv");
    inv.x(x); inv.y(y);
    x.write(0b1010);  // aligned on 10 wires: 000 1010 000 -> inverted: 111 0101 111
    sc_start(1, SC_NS);
    EXPECT_EQ(y.read(), 0b1110101111u);
}

TEST(Constant, DrivesThePatentBitPatternFromTimeZero) {
    EXPECT_EQ(bits_from_string("1100101"), 101u);  // 0.1100101b = 101/128 = 0.7890625
    sc_core::sc_signal<sc_dt::sc_uint<7>> y("y");
    sc_core::sc_signal<bool> one("one");
    constant<sc_dt::sc_uint<7>> k31("k31", bits_from_string("1100101"));
    constant<bool> k28("k28", true);
    k31.y(y); k28.y(one);
    sc_start(1, SC_NS);
    EXPECT_EQ(y.read(), 101u);
    EXPECT_TRUE(one.read());
}

TEST(EqualityComparator, OneOnlyWhereEveryWireAgreesAfterItsDelay) {
    bus<16> a("a"), b("b");
    sc_core::sc_signal<bool> y("y");
    eq_cmp<16> cmp("cmp", sc_time(300, SC_PS));
    cmp.a(a); cmp.b(b); cmp.y(y);
    a.write(0x8000); b.write(0x8000);
    sc_start(1, SC_NS);
    EXPECT_TRUE(y.read());
    b.write(0x8001);  // the lowest wire differs
    sc_start(200, SC_PS);
    EXPECT_TRUE(y.read()) << "not before the comparator's delay";
    sc_start(200, SC_PS);
    EXPECT_FALSE(y.read());
    a.write(0x0001); b.write(0x8001);  // the highest wire differs
    sc_start(1, SC_NS);
    EXPECT_FALSE(y.read());
    a.write(0x8001);
    sc_start(1, SC_NS);
    EXPECT_TRUE(y.read());
}

TEST(Saturator, ClampsAboveHiAfterItsDelayInSaturateModeAndIsWiresInWrapMode) {
    // 19 wires, hi = 1.0 on Q1.18 (0x40000): 0x60000 (1.5) is clamped, 0x3FFFF passes; in wrap mode
    // both pass, with no delay.
    bus<19> x("x"), ys("ys"), yw("yw");
    saturator<19> sat("sat", overflow_mode::saturate, 0x40000, sc_time(1, SC_NS));
    saturator<19> wires("wires", overflow_mode::wrap, 0x40000, sc_time(1, SC_NS));
    sat.x(x); sat.y(ys);
    wires.x(x); wires.y(yw);
    EXPECT_EQ(sat.delay(), sc_time(1, SC_NS));
    EXPECT_EQ(wires.delay(), sc_core::SC_ZERO_TIME);
    x.write(0x60000);
    sc_start(500, SC_PS);
    EXPECT_EQ(ys.read(), 0u) << "not settled yet";
    EXPECT_EQ(yw.read(), 0x60000u);
    sc_start(1, SC_NS);
    EXPECT_EQ(ys.read(), 0x40000u);
    x.write(0x3FFFF);
    sc_start(2, SC_NS);
    EXPECT_EQ(ys.read(), 0x3FFFFu);
    EXPECT_EQ(yw.read(), 0x3FFFFu);
}

TEST(Synchroniser, AChangeReachesQAtTheStagesThRisingEdge) {
    // Two stages, one wire, a 10 ns clock rising at 0, 10, 20 ns, ...: d rises at 3 ns; the first
    // flip-flop takes it at 10 ns, the second (q) at 20 ns. d falls at 43 ns: q falls at 60 ns.
    sc_core::sc_clock clk("clk", sc_time(10, SC_NS));
    sc_core::sc_signal<bool> d("d"), q("q");
    synchroniser<1, 2> sync("sync");
    sync.clk(clk); sync.d(d); sync.q(q);
    sc_start(3, SC_NS);
    d.write(true);
    sc_start(sc_time(16999, SC_PS));  // 19.999 ns
    EXPECT_FALSE(q.read()) << "one rising edge after the change";
    EXPECT_TRUE(sync.chain().stage(0) != 0) << "the first flip-flop took it at 10 ns";
    sc_start(2, SC_PS);  // 20.001 ns
    EXPECT_TRUE(q.read()) << "the second rising edge after the change";
    sc_start(sc_time(22999, SC_PS));  // 43 ns
    d.write(false);
    sc_start(sc_time(16999, SC_PS));  // 59.999 ns
    EXPECT_TRUE(q.read());
    EXPECT_FALSE(sync.chain().stage(0) != 0) << "taken at 50 ns";
    sc_start(2, SC_PS);  // 60.001 ns
    EXPECT_FALSE(q.read());
}

TEST(Synchroniser, ThreeStagesOfAFourWireWord) {
    // Three stages, four wires: 0xA at 1 ns reaches q at the third rising edge after it (30 ns).
    sc_core::sc_clock clk("clk", sc_time(10, SC_NS));
    bus<4> d("d"), q("q");
    synchroniser<4, 3> sync("sync");
    sync.clk(clk); sync.d(d); sync.q(q);
    sc_start(1, SC_NS);
    d.write(0xA);
    sc_start(sc_time(28999, SC_PS));  // 29.999 ns
    EXPECT_EQ(q.read(), 0u);
    sc_start(sc_time(2, SC_PS));  // 30.001 ns
    EXPECT_EQ(q.read(), 0xAu);
}

TEST(Ram, WritesAtRisingEdgesReadsAtOnceAndFlagsADroppedWrite) {
    // Five words of 8 bits on 3 address wires (addresses 5..7 name no word), a 10 ns clock rising at
    // 0, 10, 20 ns, ... Inputs change at 3 ns past an edge. Hand-worked: 10 ns stores 0xA5 at 2;
    // 20 ns, `we` 0: nothing; 30 ns stores 0x3C at 4; 40 ns, a write to 6: dropped, overflow set,
    // reported; 50 ns stores 0x11 at 2 over 0xA5; overflow stays 1 (sticky).
    tb::report_log::get().expect(msg::input);
    sc_core::sc_clock clk("clk", sc_time(10, SC_NS));
    sc_core::sc_signal<bool> we("we"), overflow("overflow");
    bus<3> wa("wa"), ra("ra");
    bus<8> wd("wd"), rd("rd");
    ram<8, 3> mem("mem", 5);
    mem.clk(clk); mem.we(we); mem.wa(wa); mem.ra(ra); mem.wd(wd); mem.rd(rd); mem.overflow(overflow);
    ra.write(2);
    sc_start(3, SC_NS);
    we.write(true); wa.write(2); wd.write(0xA5);
    sc_start(sc_time(6999, SC_PS));  // 9.999 ns
    EXPECT_EQ(rd.read(), 0u) << "every word starts at 0";
    sc_start(2, SC_PS);  // 10.001 ns
    EXPECT_EQ(rd.read(), 0xA5u) << "stored at the rising edge, read at once";
    sc_start(sc_time(2999, SC_PS));  // 13 ns
    we.write(false); wa.write(4); wd.write(0x77);
    sc_start(10, SC_NS);  // 23 ns: the edge at 20 ns wrote nothing
    ra.write(4);
    sc_start(1, SC_PS);
    EXPECT_EQ(rd.read(), 0u) << "`we` 0 at 20 ns: 0x77 not stored";
    we.write(true); wd.write(0x3C);
    sc_start(10, SC_NS);  // 33 ns
    EXPECT_EQ(rd.read(), 0x3Cu);
    wa.write(6); wd.write(0xFF);
    sc_start(sc_time(6998, SC_PS));  // 39.999 ns
    EXPECT_FALSE(overflow.read());
    sc_start(2, SC_PS);  // 40.001 ns
    EXPECT_TRUE(overflow.read()) << "the write to 6 dropped";
    EXPECT_EQ(tb::report_log::get().count(msg::input), 1u);
    wa.write(2); wd.write(0x11);
    sc_start(sc_time(12999, SC_PS));  // 53 ns
    EXPECT_TRUE(overflow.read()) << "sticky";
    ra.write(2);
    sc_start(1, SC_PS);
    EXPECT_EQ(rd.read(), 0x11u);
    EXPECT_EQ(mem.writes(), 3u) << "0xA5, 0x3C, 0x11; the dropped write is not one";
    for (unsigned a = 0; a < 5; ++a) EXPECT_EQ(mem.word_at(a), a == 2 ? 0x11u : a == 4 ? 0x3Cu : 0u) << a;
    ra.write(7);
    sc_start(1, SC_PS);
    EXPECT_EQ(rd.read(), 0u) << "no word at 7: reads 0";
    EXPECT_EQ(tb::report_log::get().count(msg::input), 2u) << "the read beyond the words reported too";
}

}  // namespace test_blocks

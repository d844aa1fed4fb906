// Generator of rtl/interp's Verilog header interp_terms.vh: the Horner controller's select codes
// (horner_ctrl.h), the coefficient networks' term tables (coef_terms in coef_unit_cubic.h and
// coef_unit_quad.h), the forward-difference controllers' select codes and set-up tables (fd_ctrl.h,
// fd_setup.h), the Horner sequence's length per request (horner_steps.h) and the pixel controllers'
// bus widths (pipeline_pins.h, fd_pixel_ctrl.h) and the cell unit's (cell_channel.h's column buffers,
// cell_ctrl.h's coordinates), so the RTL copies no number by hand (the formats'
// widths come from shading_formats.vh, src/tools/gen_rtl.cpp).
// Usage: gen_interp_rtl <output .vh>. Run by testbenches/rtl/interp.cmake when CMake configures
// (Verilator reads the Verilog then); the tables live in SystemC headers, so it links libsystemc.
//
// A term of a shift-and-add network (blocks/shift_add_network.h, sa_term) is packed in 16 bits:
// [15:12] input index, [8] negative, [7:0] shift (two's complement). Term k sits at [16k +: 16];
// a network reads only its first NT terms.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>
#include <type_traits>
#include <vector>

#include "interp/coef_unit_cubic.h"
#include "interp/coef_unit_quad.h"
#include "interp/fd_ctrl.h"
#include "interp/fd_setup.h"
#include "interp/horner_ctrl.h"
#include "interp/horner_steps.h"
#include "pipeline/cell_channel.h"
#include "pipeline/cell_ctrl.h"
#include "pipeline/fd_pixel_ctrl.h"
#include "pipeline/horner_pixel_ctrl.h"
#include "pipeline/pipeline_pins.h"

namespace {

constexpr unsigned term_bits = 16;

// Every table is padded with zero terms to `slots` terms, so the RTL can choose between the
// sample sets' tables without a width mismatch.
std::string term_table(const std::vector<shading::sa_term>& terms, std::size_t slots) {
    std::string hex(4 * (slots - terms.size()), '0');
    for (auto it = terms.rbegin(); it != terms.rend(); ++it) {  // term 0 in the low bits
        const unsigned word = (it->input << 12) | (it->negative ? 0x100u : 0u) |
                              (static_cast<unsigned>(it->shift) & 0xffu);
        char buf[8];
        std::snprintf(buf, sizeof buf, "%04x", word);
        hex += buf;
    }
    return std::to_string(slots * term_bits) + "'h" + hex;
}

// One table per forward difference, every interval length 2^m (m_min..m_max) in one word: m's terms
// at [16 * n * (m - m_min) +: 16 * n], n terms per m (the same for every m; 0 if they differ).
template <class Terms>
std::string fd_table(Terms&& terms_of, std::size_t& n) {
    using shading::interp::m_max;
    using shading::interp::m_min;
    n = terms_of(m_min).size();
    std::string hex;
    for (unsigned m = m_max + 1; m-- > m_min;) {  // m_max's terms in the high bits
        const auto terms = terms_of(m);
        if (terms.size() != n) {
            n = 0;
            return {};
        }
        const std::string one = term_table(terms, n);
        hex += one.substr(one.find('h') + 1);
    }
    return std::to_string(hex.size() * 4) + "'h" + hex;
}

// The widths written below are those of the pixel controllers' ports (shading_pipeline.h binds
// fd_pixel_ctrl's len and m to fd_channel's).
using shading::fd_pixel_ctrl;
using shading::horner_pixel_ctrl;
using shading::pipeline_pins;
static_assert(std::is_same_v<decltype(horner_pixel_ctrl::px_x), sc_core::sc_out<pipeline_pins::coord_t>> &&
                  std::is_same_v<decltype(horner_pixel_ctrl::len), sc_core::sc_in<pipeline_pins::len_t>> &&
                  std::is_same_v<decltype(horner_pixel_ctrl::m), sc_core::sc_in<pipeline_pins::m_t>> &&
                  std::is_same_v<decltype(fd_pixel_ctrl::len_in), sc_core::sc_in<pipeline_pins::len_t>> &&
                  std::is_same_v<decltype(fd_pixel_ctrl::m_in), sc_core::sc_in<pipeline_pins::m_t>>,
              "the pixel controllers' descriptor ports carry pipeline_pins' types");

// The cell unit's buses beside the forward-difference channels' (cell_channel.h binds its len and m
// to fd_channel's; cell_unit.v takes them from INTERP_FD_LEN_W and INTERP_FD_M_W).
using shading::cell_channel;
using shading::cell_ctrl;
static_assert(std::is_same_v<cell_channel::len_t, fd_pixel_ctrl::len_t> &&
                  std::is_same_v<cell_channel::m_t, fd_pixel_ctrl::m_t> &&
                  std::is_same_v<cell_ctrl::addr_t, cell_channel::addr_t>,
              "the cell unit's len, m and buffer addresses are the channels' types");

// Micro-steps of one Horner request (horner_steps.h's sequencer run from idle until done).
unsigned horner_steps_per_request(bool deg2) {
    shading::interp::horner_steps s;
    const auto no_check = [] {};
    s.rising(true, [deg2] { return deg2; }, no_check);
    unsigned n = 1;
    while (!s.done() && n < 64) {
        s.rising(false, [deg2] { return deg2; }, no_check);
        ++n;
    }
    return n;
}

// Wires of a pin type (sc_uint<W>).
template <class T>
uint64_t wires() {
    return static_cast<uint64_t>(T().length());
}

}  // namespace

// sc_main: libsystemc's main() calls it.
int sc_main(int argc, char* argv[]) {
    using namespace shading;
    if (argc != 2) {
        std::cerr << "usage: gen_interp_rtl <output .vh>\n";
        return 2;
    }
    std::ofstream out(argv[1]);
    auto def = [&out](const char* name, const std::string& value, const char* why) {
        out << "// " << why << "\n`define " << name << ' ' << value << '\n';
    };
    auto num = [](uint64_t v) { return std::to_string(v); };
    out << "// Generated by testbenches/rtl/gen_interp_rtl.cpp from modules/interp/horner_ctrl.h,\n"
        << "// coef_unit_cubic.h and coef_unit_quad.h (coef_terms), fd_ctrl.h, fd_setup.h, horner_steps.h\n"
        << "// and modules/pipeline's pin types and cell unit. Do not edit.\n"
        << "`ifndef INTERP_TERMS_VH\n`define INTERP_TERMS_VH\n";
    def("INTERP_MX1_A", num(horner_ctrl::mx1_a), "MX1 code of A");
    def("INTERP_MX1_RG", num(horner_ctrl::mx1_rg), "MX1 code of RG");
    def("INTERP_MX2_ZERO", num(horner_ctrl::mx2_zero), "MX2 code of 0 (hold)");
    def("INTERP_MX2_MUL", num(horner_ctrl::mx2_mul), "MX2 code of MUL");
    def("INTERP_MX2_B", num(horner_ctrl::mx2_b), "MX2 code of B");
    def("INTERP_MX2_C", num(horner_ctrl::mx2_c), "MX2 code of C");
    def("INTERP_MX2_D", num(horner_ctrl::mx2_d), "MX2 code of D");
    const struct {
        const char* name;
        const std::vector<sa_term>& terms;
    } tables[] = {{"A8_CASE1", coef_terms::a8_case1}, {"B_CASE1", coef_terms::b_case1},
                  {"C3_CASE1", coef_terms::c3_case1}, {"A8_CASE2", coef_terms::a8_case2},
                  {"B_CASE2", coef_terms::b_case2},   {"C3_CASE2", coef_terms::c3_case2},
                  {"A_QUAD", coef_terms::a_quad},     {"B_QUAD", coef_terms::b_quad}};
    std::size_t slots = 0;
    for (const auto& t : tables) slots = std::max(slots, t.terms.size());
    def("INTERP_TERM_SLOTS", num(slots), "terms per table (the longest; shorter ones padded with zero terms)");
    for (const auto& t : tables) {
        def(("INTERP_" + std::string(t.name) + "_N").c_str(), num(t.terms.size()), "terms");
        def(("INTERP_" + std::string(t.name)).c_str(), term_table(t.terms, slots), "coef_terms, term 0 lowest");
    }
    // Forward differences (fd_ctrl.h, fd_setup.h).
    def("INTERP_FD_SEL_HOLD", num(fd_ctrl<interp::m_max>::sel_hold), "fd_ctrl: register multiplexers' code of hold");
    def("INTERP_FD_SEL_LOAD", num(fd_ctrl<interp::m_max>::sel_load), "fd_ctrl: code of load (the set-up)");
    def("INTERP_FD_SEL_STEP", num(fd_ctrl<interp::m_max>::sel_step), "fd_ctrl: code of step (the adder)");
    def("INTERP_FD_ALIGN", std::to_string(fd_setup::align), "fd_setup: Q.16 -> Q.34 shift of the set-up and the output");
    const struct {
        const char* name;
        std::vector<sa_term> (*terms)(unsigned);
    } fd_tables[] = {{"INTERP_FD_D1", fd_setup::d1_terms}, {"INTERP_FD_D2", fd_setup::d2_terms},
                     {"INTERP_FD_D3", fd_setup::d3_terms}};
    for (const auto& t : fd_tables) {
        std::size_t n = 0;
        const std::string table = fd_table(t.terms, n);
        if (n == 0) {
            std::cerr << "gen_interp_rtl: " << t.name << ": the term count differs between interval lengths\n";
            return 1;
        }
        def((std::string(t.name) + "_N").c_str(), num(n), "fd_setup terms per interval length");
        def(t.name, table, "fd_setup terms, m = m_min lowest, term 0 lowest within each m");
    }
    def("INTERP_FD_LEN_W", num(wires<fd_pixel_ctrl::len_t>()), "fd_pixel_ctrl / fd_channel: len wires, every m");
    def("INTERP_FD_M_W", num(wires<fd_pixel_ctrl::m_t>()), "fd_pixel_ctrl / fd_channel: m wires (0, m_min..m_max)");
    // Horner (horner_steps.h): micro-steps per request.
    def("INTERP_HORNER_STEPS_CUBIC", num(horner_steps_per_request(false)), "horner_steps: micro-steps, cubic");
    def("INTERP_HORNER_STEPS_QUAD", num(horner_steps_per_request(true)), "horner_steps: micro-steps, deg2");
    // The pixel controllers' descriptor inputs (pipeline_pins.h: the job registers' widths).
    def("PIPELINE_PINS_COORD_W", num(wires<pipeline_pins::coord_t>()), "pipeline_pins: x, y wires");
    def("PIPELINE_PINS_LEN_W", num(wires<pipeline_pins::len_t>()), "pipeline_pins: job len wires");
    def("PIPELINE_PINS_M_W", num(wires<pipeline_pins::m_t>()), "pipeline_pins: job m wires");
    // The cell unit (cell_channel.h, cell_ctrl.h).
    def("CELL_BUF_DEPTH", num(cell_channel::depth), "cell_channel: words of a column buffer (rows of the largest cell)");
    def("CELL_BUF_ADDR_W", num(cell_channel::buffer::addr_width), "cell_channel: column buffer address wires (wa, ra)");
    def("CELL_COORD_W", num(wires<cell_ctrl::coord_t>()), "cell_ctrl: x0, y0, px_x, px_y wires");
    out << "`endif\n";
    return out ? 0 : 1;
}

// Multiplier block: WA x WB -> WP bits. The full product is formed exactly, then DROP low wires
// are left unconnected (floor, also for signed products) and the WP wires above them are the
// output (a product that does not fit wraps: the caller's format table must rule that out).
// Operands are two's complement when ASIGNED/BSIGNED, else unsigned.
#pragma once

#include <cstdint>
#include <systemc>

#include "core/comb_delay.h"
#include "core/timed_block.h"

namespace shading {

template <unsigned WA, unsigned WB, unsigned WP, unsigned DROP = 0, bool ASIGNED = false,
          bool BSIGNED = false>
class mul : public sc_core::sc_module, public timed_block {
    static_assert(WA <= 64 && WB <= 64 && WA + WB <= 126 && WP <= 64, "operand widths");
    static_assert(DROP + WP <= WA + WB + 1, "output wires beyond the product");

public:
    sc_core::sc_in<sc_dt::sc_uint<WA>> a{"a"};
    sc_core::sc_in<sc_dt::sc_uint<WB>> b{"b"};
    sc_core::sc_out<sc_dt::sc_uint<WP>> p{"p"};

    SC_HAS_PROCESS(mul);
    explicit mul(const sc_core::sc_module_name& name,
                 const sc_core::sc_time& delay = delay_default::multiplier)
        : sc_module(name), drv_(p, delay) {
        SC_METHOD(compute);
        sensitive << a << b;
    }

    const sc_core::sc_time& delay() const override { return drv_.delay(); }

    static __int128 operand(uint64_t bits, unsigned w, bool is_signed) {
        if (is_signed && ((bits >> (w - 1)) & 1u))
            return static_cast<__int128>(bits) - (static_cast<__int128>(1) << w);
        return static_cast<__int128>(bits);
    }

private:
    void compute() {
        const __int128 prod = operand(a.read().to_uint64(), WA, ASIGNED) *
                              operand(b.read().to_uint64(), WB, BSIGNED);
        drv_.drive(sc_dt::sc_uint<WP>(static_cast<uint64_t>(prod >> DROP)));
    }

    inertial_driver<sc_dt::sc_uint<WP>> drv_;
};

}  // namespace shading

// A wire between two nets: y follows x with no delay. SystemC cannot bind one net to a module's
// input and output pins at once (UA 60553, Fig. 3: output 29 is RG2's strobe itself), so a top
// joins them with this block, which the timing graph sees as a zero-delay step.
#pragma once

#include <systemc>

#include "core/timed_block.h"

namespace shading {

template <typename T>
class wire : public sc_core::sc_module, public timed_block {
public:
    sc_core::sc_in<T> x{"x"};
    sc_core::sc_out<T> y{"y"};

    SC_HAS_PROCESS(wire);
    explicit wire(const sc_core::sc_module_name& name) : sc_module(name) {
        SC_METHOD(follow);
        sensitive << x;
    }

    const sc_core::sc_time& delay() const override { return sc_core::SC_ZERO_TIME; }

private:
    void follow() { y.write(x.read()); }
};

}  // namespace shading

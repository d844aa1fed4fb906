// The pins of the forward-difference evaluator and of the raster-line interpolator built on it,
// their names and widths written once for the block models (fd_eval.h, interp_line_unit.h) and their
// fast pin-level models (fd_eval_fast.h, interp_line_unit_fast.h). A model derives from its bundle
// after sc_module, so the ports are the module's children, named as here and in this order. The
// bundles share their parts: the line unit hands the request and the pixel stream straight to its
// evaluator (interp_line_unit.h).
#pragma once

#include <systemc>

#include "formats/interp_formats.h"

namespace shading {

// An interval request for 2^M pixels (fd_ctrl.h's handshake).
template <unsigned M>
struct fd_request_pins {
    using len_t = sc_dt::sc_uint<interp::len_width(M)>;  // fd_ctrl<M>::len_t
    sc_core::sc_in<bool> clk{"clk"};
    sc_core::sc_in<bool> start{"start"};  // interval pending
    sc_core::sc_in<len_t> len{"len"};     // pixels of this interval, 1..2^M
};

// The evaluator's coefficients A..D, Q16.16 signed.
struct fd_coef_pins {
    using coef_t = sc_dt::sc_uint<interp::coef_fmt.width>;
    sc_core::sc_in<coef_t> a{"a"}, b{"b"}, c{"c"}, d{"d"};
};

// The line unit's samples I1..I4, Q8.8 unsigned.
struct line_sample_pins {
    using sample_t = sc_dt::sc_uint<interp::sample_fmt.width>;
    sc_core::sc_in<sample_t> i1{"i1"}, i2{"i2"}, i3{"i3"}, i4{"i4"};
};

// The pixel stream: one Q16.16 pixel on i_px while valid; last marks its interval's last pixel.
struct fd_pixel_pins {
    using px_t = sc_dt::sc_uint<interp::coef_fmt.width>;
    sc_core::sc_out<px_t> i_px{"i_px"};
    sc_core::sc_out<bool> valid{"valid"}, last{"last"};
};

// fd_eval<M> and fd_eval_fast<M>.
template <unsigned M>
struct fd_eval_pins : fd_request_pins<M>, fd_coef_pins, fd_pixel_pins {};

// interp_line_unit<M, ...> and interp_line_unit_fast<M, ...>.
template <unsigned M>
struct interp_line_pins : fd_request_pins<M>, line_sample_pins, fd_pixel_pins {
    sc_core::sc_out<bool> ready{"ready"};  // start is taken at the next rising edge
};

}  // namespace shading

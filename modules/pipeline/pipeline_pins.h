// The shading pipeline's buses and pins, written once for the block model (shading_pipeline.h) and its
// fast pin-level model (shading_pipeline_fast.h). A model derives from pipeline_pins after sc_module,
// so the ports are the module's children, named as here and in this order.
#pragma once

#include <systemc>

#include "formats/interp_formats.h"
#include "formats/pipeline_formats.h"
#include "formats/specular_formats.h"
#include "formats/ua60553_formats.h"

namespace shading {

namespace pipeline {
// The sample stage's buses, in the formats of src/floor/formats/pipeline_formats.h (the golden pipeline
// reads the same).
using kdi_t = sc_dt::sc_uint<kdi_fmt.width>;
using cos_t = sc_dt::sc_uint<spec::cos_fmt.width>;
using spec_t = sc_dt::sc_uint<spec::out_fmt.width>;
using sample_t = sc_dt::sc_uint<interp::sample_fmt.width>;
using coef_t = sc_dt::sc_uint<interp::coef_fmt.width>;
}  // namespace pipeline

struct pipeline_pins {
    using coord_t = sc_dt::sc_uint<16>;
    using len_t = sc_dt::sc_uint<16>;  // sample_ctrl::len_bits
    using m_t = sc_dt::sc_uint<4>;     // sample_ctrl::m_bits
    using bit_t = sc_dt::sc_uint<1>;
    using n_t = sc_dt::sc_uint<ua60553::n_fmt.width>;  // in16 of every device the pipeline takes
    using cos_t = pipeline::cos_t;
    using ksi_t = sc_dt::sc_uint<spec::ksi_fmt.width>;
    using kdi_t = pipeline::kdi_t;
    using sample_t = pipeline::sample_t;

    // From the geometry side: the clock, the handshake (sample_ctrl.h) and one job's registers.
    sc_core::sc_in<bool> clk{"clk"};
    sc_core::sc_in<bool> start{"start"}, load_frame{"load_frame"};
    sc_core::sc_out<bool> ready{"ready"};
    sc_core::sc_in<coord_t> in_y{"in_y"}, in_x0{"in_x0"};
    sc_core::sc_in<len_t> in_len{"in_len"};
    sc_core::sc_in<m_t> in_m{"in_m"};
    sc_core::sc_in<bit_t> in_deg2{"in_deg2"};
    sc_core::sc_in<cos_t> in_nh1{"in_nh1"}, in_nh2{"in_nh2"}, in_nh3{"in_nh3"}, in_nh4{"in_nh4"};
    sc_core::sc_in<cos_t> in_nl1{"in_nl1"}, in_nl2{"in_nl2"}, in_nl3{"in_nl3"}, in_nl4{"in_nl4"};
    // Frame constants.
    sc_core::sc_in<n_t> in_n{"in_n"};
    sc_core::sc_in<ksi_t> in_ksi_r{"in_ksi_r"}, in_ksi_g{"in_ksi_g"}, in_ksi_b{"in_ksi_b"};
    sc_core::sc_in<kdi_t> in_kdi_r{"in_kdi_r"}, in_kdi_g{"in_kdi_g"}, in_kdi_b{"in_kdi_b"};
    sc_core::sc_in<sample_t> in_amb_r{"in_amb_r"}, in_amb_g{"in_amb_g"}, in_amb_b{"in_amb_b"};
    // Pixel stream: px_r/g/b (Q8.8 codes) belong at (px_x, px_y) at a rising edge where px_valid = 1.
    sc_core::sc_out<bool> px_valid{"px_valid"};
    sc_core::sc_out<coord_t> px_x{"px_x"}, px_y{"px_y"};
    sc_core::sc_out<sample_t> px_r{"px_r"}, px_g{"px_g"}, px_b{"px_b"};
};

}  // namespace shading

// UA 60553, Fig. 1: the specular device's pins as bundles of signals, their names and widths written
// once. A bench, a platform or a co-simulation derives from a bundle (after sc_module, so the signals
// are the module's children and trace under its name) and connects any module with Fig. 1's port
// names - the device, its fast model, the squared-quadratic device, a stimulus, a monitor - with
// bind_fig1_inputs / bind_fig1_outputs.
#pragma once

#include <systemc>

#include "formats/specular_formats.h"
#include "formats/ua60553_formats.h"

namespace shading {

// Strobes 15, 17, 20, 22, 24 and the buses 16 (n), 18 (cos), 19, 21, 23 (KSI of R, G, B).
struct fig1_inputs {
    using n_t = sc_dt::sc_uint<ua60553::n_fmt.width>;
    using cos_t = sc_dt::sc_uint<spec::cos_fmt.width>;
    using ksi_t = sc_dt::sc_uint<spec::ksi_fmt.width>;
    sc_core::sc_signal<bool> ctl15{"ctl15"}, ctl17{"ctl17"}, ctl20{"ctl20"}, ctl22{"ctl22"}, ctl24{"ctl24"};
    sc_core::sc_signal<n_t> in16_n{"in16_n"};
    sc_core::sc_signal<cos_t> in18_cos{"in18_cos"};
    sc_core::sc_signal<ksi_t> in19_ksi_r{"in19_ksi_r"}, in21_ksi_g{"in21_ksi_g"}, in23_ksi_b{"in23_ksi_b"};
};

// Outputs 25, 26, 27 (the colour) and 29 (valid).
struct fig1_outputs {
    using out_t = sc_dt::sc_uint<spec::out_fmt.width>;
    sc_core::sc_signal<out_t> out25_r{"out25_r"}, out26_g{"out26_g"}, out27_b{"out27_b"};
    sc_core::sc_signal<bool> out29_valid{"out29_valid"};
};

struct fig1_signals : fig1_inputs, fig1_outputs {};

template <class M>
void bind_fig1_inputs(M& m, fig1_inputs& s) {
    m.ctl15(s.ctl15); m.ctl17(s.ctl17); m.ctl20(s.ctl20); m.ctl22(s.ctl22); m.ctl24(s.ctl24);
    m.in16_n(s.in16_n); m.in18_cos(s.in18_cos);
    m.in19_ksi_r(s.in19_ksi_r); m.in21_ksi_g(s.in21_ksi_g); m.in23_ksi_b(s.in23_ksi_b);
}

template <class M>
void bind_fig1_outputs(M& m, fig1_outputs& s) {
    m.out25_r(s.out25_r); m.out26_g(s.out26_g); m.out27_b(s.out27_b); m.out29_valid(s.out29_valid);
}

}  // namespace shading

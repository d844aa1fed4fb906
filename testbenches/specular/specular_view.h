// The number formats the GTKWave views of the specular devices (traces/ua60553.gtkw,
// traces/ua22802.gtkw) must give the datapath nets every device shares, from the format tables in
// src/floor/formats/specular_formats.h; each device's test adds its n -> a generator's nets.
#pragma once

#include "testbenches/common/vcd_names.h"
#include "formats/specular_formats.h"

namespace shading::tb {

inline view_formats specular_view_formats() {
    view_formats f;
    f["tb.in18_cos"] = f["tb.dut.rg2_cos"] = spec::cos_fmt;
    f["tb.dut.mul7_cos2"] = spec::cos2_fmt;
    f["tb.dut.inv8_not_cos"] = spec::inv8_fmt;
    f["tb.dut.add9_cos2_minus_cos"] = spec::d_fmt;
    f["tb.dut.mul10_a_x_diff"] = spec::mul10_fmt;
    f["tb.dut.add11_brdf"] = spec::brdf_fmt;
    for (const char* k : {"tb.in19_ksi_r", "tb.in21_ksi_g", "tb.in23_ksi_b", "tb.dut.rg3_ksi_r", "tb.dut.rg4_ksi_g",
                          "tb.dut.rg5_ksi_b"})
        f[k] = spec::ksi_fmt;
    for (const char* o : {"tb.out25_r", "tb.out26_g", "tb.out27_b"}) f[o] = spec::out_fmt;
    return f;
}

}  // namespace shading::tb

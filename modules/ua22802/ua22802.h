// UA 22802, the prototype UA 60553 names: the specular datapath with RG1
// addressing a ROM that holds a(n) (a_gen_rom.h). Construct as
// device_ua22802(name, mode, ROM words = the generated a(n) table, block delays); the ROM's access
// time is block_delays::rom. Link shading_ua22802 (the generated ROM content).
#pragma once

#include "specular/specular_device.h"
#include "specular/specular_fast.h"
#include "ua22802/a_gen_rom.h"

namespace shading {

using device_ua22802 = specular_device<a_gen_rom>;
// The fast pin-level abstraction (specular/specular_fast.h): same pins, timing and constructor.
using device_ua22802_fast = specular_fast<a_gen_rom>;

}  // namespace shading

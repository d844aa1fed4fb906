#include "arith/device_specular.h"

#include "arith/specular_arith.h"
#include "arith/sqmul_arith.h"
#include "arith/squared_arith.h"
#include "arith/ua22802_arith.h"
#include "arith/ua60553_tuned_arith.h"

namespace shading::scene {

std::array<uint64_t, 3> device_specular(const device_config& dev, unsigned n, uint32_t cos_code,
                                        const std::array<uint64_t, 3>& ksi) {
    switch (dev.device) {
        case specular_device::patent: return golden_ua60553(n, cos_code, ksi, dev.mode, ua60553::patent).out;
        case specular_device::minimax: return golden_ua60553_tuned(n, cos_code, ksi, dev.mode, ua60553::minimax).out;
        case specular_device::rom_matched:
            return golden_ua60553_tuned(n, cos_code, ksi, dev.mode, ua60553::rom_matched).out;
        case specular_device::ua22802: return golden_ua22802(n, cos_code, ksi, dev.mode).out;
        case specular_device::squared: return golden_squared(n, cos_code, ksi, dev.mode).out;
        case specular_device::sqmul: return golden_sqmul(n, cos_code, ksi, dev.mode).out;
    }
    return {0, 0, 0};
}

}  // namespace shading::scene

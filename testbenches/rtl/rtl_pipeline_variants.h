// The shading pipeline's three verilated variants (testbenches/rtl/pipeline.cmake) and the SystemC
// configuration matching each one's parameters, shared by test_rtl_pipeline and render_pipeline_rtl:
//   horner    EVAL 0          SET 0 (case 1)  DIV 0 (shift-add)  CARRY 1  SATURATE 1
//   fd_any    EVAL 1, FD_M 0  SET 1 (case 2)  DIV 1 (exact)      CARRY 0  SATURATE 0
//   fd_m4     EVAL 1, FD_M 4  SET 0 (case 1)  DIV 1 (exact)      CARRY 1  SATURATE 0
#pragma once

#include "testbenches/pipeline/pipeline_pair.h"
#include "testbenches/pipeline/pipeline_tops.h"
#include "sqmul/sqmul_device.h"

// The verilated pipelines (testbenches/rtl/pipeline.cmake).
#include "Vrtl_pipeline_fd_any.h"
#include "Vrtl_pipeline_fd_m4.h"
#include "Vrtl_pipeline_horner.h"

namespace shading::pipeline::rtl_variants {

// One verilated variant and the SystemC configuration that matches its parameters.
template <class Rtl, evaluator EVAL, unsigned FD_M, interp::sample_set SET, interp::div3_mode DIV, bool CARRY,
          overflow_mode MODE>
struct variant {
    using rtl = Rtl;
    static constexpr evaluator eval = EVAL;
    static constexpr unsigned fd_m = FD_M;  // forward differences: 0 any m per interval
    static constexpr interp::sample_set set = SET;
    static constexpr interp::div3_mode div = DIV;
    static constexpr bool carry = CARRY;
    static constexpr overflow_mode mode = MODE;

    // The plan configuration the variant runs: its evaluator, sample set, division by 3 and carry;
    // any m per interval (FD_M 0: the adaptive length) or the fixed 2^FD_M; the rest `base`'s.
    static plan_config plan_config_of(plan_config base = {}) {
        base.carry_samples = CARRY;
        base.eval = EVAL;
        base.length = FD_M == 0 ? length_policy::adaptive : length_policy::fixed;
        base.m = FD_M == 0 ? 4 : FD_M;
        base.set = SET;
        base.div = DIV;
        return base;
    }
    // The square-and-multiply device in the variant's overflow mode.
    static scene::device_config device() {
        scene::device_config dev;
        dev.device = scene::specular_device::sqmul;
        dev.mode = MODE;
        return dev;
    }
};

using horner = variant<Vrtl_pipeline_horner, evaluator::horner, 0, interp::sample_set::case1,
                       interp::div3_mode::shift_add, true, overflow_mode::saturate>;
using fd_any = variant<Vrtl_pipeline_fd_any, evaluator::fd, 0, interp::sample_set::case2, interp::div3_mode::exact,
                       false, overflow_mode::wrap>;
using fd_m4 = variant<Vrtl_pipeline_fd_m4, evaluator::fd, 4, interp::sample_set::case1, interp::div3_mode::exact,
                      true, overflow_mode::wrap>;

// The model and the variant's RTL side by side.
template <class V>
using rtl_pair = pair_bench<sqmul_device, V::eval, typename V::rtl>;

}  // namespace shading::pipeline::rtl_variants

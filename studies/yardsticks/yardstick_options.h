// yardstick_study's command line (yardstick_study.cpp) as a plain struct, and its parse function: the
// struct filled, an exit status returned when the program must stop (0 after --help, 2 for bad
// usage), nothing when it runs. render_pipeline's groups but the sweep (render_options.h: scene,
// device, plan without --length, simulation, output), and the yardsticks' own.
#pragma once

#include <optional>
#include <string>

#include "studies/yardsticks/optimum.h"
#include "testbenches/options/render_options.h"

namespace shading::yardsticks {

struct yardstick_options {
    // The render's settings. Its length policy is adaptive for either yardstick: the units are built
    // for any m in m_min..m_max per interval (fd_eval_var), and the perfect decisions are that policy's.
    render_program::options render;
    std::string length = "optimal";  // the yardstick: optimal (the optimum) or adaptive (perfect decisions)
    bool perfect_decisions = false;
    optimum_config optimum;
    yardstick_options() {
        render.out = "out/yardsticks";
        render.length = "adaptive";
    }
};

std::optional<int> parse_yardstick_study(int argc, char** argv, yardstick_options& o);

}  // namespace shading::yardsticks

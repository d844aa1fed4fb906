// yardstick_study's command line (yardstick_options.h) parsed with CLI11: render_pipeline's option
// groups (render_options.h), then the yardsticks'. Its own translation unit with CLI11, as the
// options library's sources (testbenches/options/cli_parse.h).
#include "studies/yardsticks/yardstick_options.h"

#include "testbenches/options/cli_parse.h"

namespace shading::yardsticks {

std::optional<int> parse_yardstick_study(int argc, char** argv, yardstick_options& o) {
    CLI::App app{"The yardsticks of the interpolation paper's shading system's plans: the optimum plan (--length optimal) "
                 "or the adaptive length policy with perfect decisions (--length adaptive --perfect-decisions), "
                 "rendered as render_pipeline renders a policy's plan (golden model and SystemC, against per-pixel "
                 "and Phong references); PNGs and a report."};
    render_program::add_scene_options(app, o.render);
    render_program::add_device_options(app, o.render);
    render_program::add_plan_options(app, o.render, false);
    const std::string g = "Yardstick";
    app.add_option("--length", o.length,
                   "the yardstick: optimal (the fewest geometry points for --optimal-nmse, knowing every colour) or "
                   "adaptive (the adaptive length policy with --perfect-decisions)")
        ->check(CLI::IsMember({"optimal", "adaptive"}))->required()->group(g);
    app.add_flag("--perfect-decisions", o.perfect_decisions,
                 "adaptive length: decide on the true RMS error of the pieces sent (at most --length-tol levels), "
                 "still paying every estimate and check point")->group(g);
    app.add_option("--optimal-nmse", o.optimum.nmse, "optimal length: the largest NMSE allowed (0..1)")
        ->check(CLI::Range(0.0, 1.0))->check(tb::not_nan())->group(g);
    std::string reference = "interpolation";
    app.add_option("--optimal-reference", reference,
                   "optimal length: the NMSE against interpolation (per-pixel shading through the device) or total "
                   "(exact Phong)")
        ->check(CLI::IsMember({"interpolation", "total"}))->group(g);
    app.add_flag("--optimal-greedy", o.optimum.greedy,
                 "optimal length: instead the adaptive policies' greedy structure with perfect estimates (the "
                 "certificate stays the optimum's)")->group(g);
    app.add_option("--optimal-from-above", o.optimum.from_above,
                   "optimal length: choose on the line above's errors (the largest over starts within W pixels), "
                   "not the line's own: what knowing every colour of the line above could reach (negative: off; "
                   "default -1)")
        ->check(CLI::Range(-1, static_cast<int>(window_max)))->group(g);
    render_program::add_simulation_options(app, o.render);
    render_program::add_output_options(app, o.render);
    SHADING_CLI_PARSE(app, argc, argv);  // help 0, a bad option 2 (common/exit_status.h)
    render_program::record_command_line(app, argc, argv, o.render);
    o.optimum.ref = reference == "total" ? optimum_config::reference::total : optimum_config::reference::interpolation;
    return std::nullopt;
}

}  // namespace shading::yardsticks

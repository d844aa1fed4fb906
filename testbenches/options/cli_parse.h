// CLI11's parse with the project's exit statuses (common/exit_status.h). Included only by the
// options library's own sources: CLI11 2.1 is header-only and costs every translation unit that
// includes it about 100 KB of code and many seconds of compile time, so it is compiled here once.
#pragma once

#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "testbenches/common/exit_status.h"

namespace shading::tb {

// --help exits 0 (the help printed), every parse or validation error 2 (CLI11's message printed).
inline int cli_exit(const CLI::App& app, const CLI::ParseError& e) {
    return app.exit(e) == 0 ? exit_success : exit_usage;
}

// A value CLI11 could not convert and did not report itself (std::out_of_range or
// std::invalid_argument from the standard library's conversions): bad usage, said on stderr.
inline int cli_value_exit(const std::logic_error& e) {
    std::fprintf(stderr, "a value on the command line cannot be converted (%s)\nRun with --help for more information.\n",
                 e.what());
    return exit_usage;
}

// CLI11's numeric checks (Range, PositiveNumber) compare, and every comparison with NaN is false, so
// "nan" passed them (found by fuzz_options); a value that is not a number is bad usage. Added after
// the range check of every floating-point option.
inline CLI::Validator not_nan() {
    return CLI::Validator(
        [](std::string& s) -> std::string {
            double v = 0;
            if (CLI::detail::lexical_cast(s, v) && std::isnan(v)) return "not a number: " + s;
            return {};
        },
        "", "NOT_NAN");
}

// An empty argument is bad usage unless it is the value of an option that takes one ("--md ''": no
// Markdown report). CLI11 2.1 drops an unexpected empty positional in an app with option groups, so
// `render_race ""` ran the race as if nothing had been given.
inline bool has_empty_argument(const CLI::App& app, int argc, const char* const* argv) {
    for (int i = 1; i < argc; ++i) {
        if (argv[i][0] != '\0') continue;
        const CLI::Option* before = i > 1 ? app.get_option_no_throw(argv[i - 1]) : nullptr;
        if (before != nullptr && before->get_type_size() != 0) continue;
        std::fprintf(stderr, "argument %d is empty\nRun with --help for more information.\n", i);
        return true;
    }
    return false;
}

}  // namespace shading::tb

// As CLI11_PARSE (which returns CLI11's own statuses), in a function returning the exit status
// (an int, or a std::optional<int> holding it). CLI11 2.1 lets std::stoll's exceptions out of a
// flag given a number no long long holds ("--no-sim=433433333334433333333", found by
// fuzz_options): bad usage too, not a terminate. A stray empty argument is refused first.
#define SHADING_CLI_PARSE(app, argc, argv)                          \
    do {                                                            \
        if (::shading::tb::has_empty_argument((app), (argc), (argv))) \
            return ::shading::tb::exit_usage;                        \
        try {                                                       \
            (app).parse((argc), (argv));                            \
        } catch (const CLI::ParseError& shading_parse_error_) {     \
            return ::shading::tb::cli_exit((app), shading_parse_error_); \
        } catch (const std::logic_error& shading_value_error_) {    \
            return ::shading::tb::cli_value_exit(shading_value_error_); \
        }                                                           \
    } while (0)

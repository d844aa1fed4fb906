// The exit statuses of every program of the project (testbenches, studies, tools):
//   0  success;
//   1  a failure: a mismatch against the golden model or reference, an unexpected SystemC report, or
//      input that could not be read or used (a missing or malformed file);
//   2  bad usage: the command line itself is wrong - an unknown option, a value that is not a number,
//      out of its documented range or not one of the names offered - found before any work is done.
// CLI11's own statuses (100 and up for parse errors) are mapped onto these by SHADING_CLI_PARSE.
// Each program has a ctest entry checking that bad usage exits 2 (shading_add_usage_test).
#pragma once

#include <CLI/CLI.hpp>
#include <stdexcept>
#include <string>

namespace shading::tb {

constexpr int exit_success = 0;
constexpr int exit_failure = 1;
constexpr int exit_usage = 2;

// Thrown by a program's own argument checks that CLI11 cannot express; caught in main() as exit 2.
struct usage_error : std::runtime_error {
    explicit usage_error(const std::string& what) : std::runtime_error(what) {}
};

// CLI11's parse with the project's statuses: --help exits 0 (the help printed), every parse or
// validation error 2 (CLI11's message printed).
inline int cli_exit(const CLI::App& app, const CLI::ParseError& e) {
    return app.exit(e) == 0 ? exit_success : exit_usage;
}

}  // namespace shading::tb

// As CLI11_PARSE (which returns CLI11's own statuses), in a function returning the exit status.
#define SHADING_CLI_PARSE(app, argc, argv)                          \
    do {                                                            \
        try {                                                       \
            (app).parse((argc), (argv));                            \
        } catch (const CLI::ParseError& shading_parse_error_) {     \
            return ::shading::tb::cli_exit((app), shading_parse_error_); \
        }                                                           \
    } while (0)

// The exit statuses of every program of the project (testbenches, studies, tools):
//   0  success;
//   1  a failure: a mismatch against the golden model or reference, an unexpected SystemC report, or
//      input that could not be read or used (a missing or malformed file);
//   2  bad usage: the command line itself is wrong - an unknown option, a value that is not a number,
//      out of its documented range or not one of the names offered - found before any work is done.
// The command lines are parsed by the options library (testbenches/options/), whose parse functions
// return these statuses; CLI11's own (100 and up for parse errors) are mapped onto them there
// (options/cli_parse.h), so no program compiles CLI11 itself.
// Each program has a ctest entry checking that bad usage exits 2 (shading_add_usage_test).
#pragma once

#include <stdexcept>
#include <string>

namespace shading::tb {

constexpr int exit_success = 0;
constexpr int exit_failure = 1;
constexpr int exit_usage = 2;

// Thrown by a program's own argument checks that the parser cannot express; caught in main() as exit 2.
struct usage_error : std::runtime_error {
    explicit usage_error(const std::string& what) : std::runtime_error(what) {}
};

}  // namespace shading::tb

# Helpers that add this project's programs.
#
# shading_add_bench(<name> SOURCES <files...> [LIBS <targets...>] [RANDOM <args>...])
#   A testbench program with its own sc_main (testbenches/common/bench_runner.h), in build/bin/.
#   It exits 0 only with zero mismatches and zero unexpected SystemC reports. Registers ctest
#   entries: bench.<name>.default (the default run, no VCD), bench.<name>.random[.<i>] (a short
#   random differential run; one per RANDOM argument string, e.g. "--mode wrap") and
#   bench.<name>.inject (a mismatch forced with --inject-mismatch must make it exit 1; .inject256
#   forces 256 in a short random run, the count that exited 0 when the status was the count).
# shading_add_gtest(<name> SOURCES <files...> [LIBS <targets...>] [TIMEOUT <s>])
#   A GoogleTest program whose main() runs the tests inside sc_elab_and_sim (testbenches/common): one
#   per folder, its suites' files compiled as one unit (SHADING_UNITY_SUITES below).
#   gtest_discover_tests registers every test as its own ctest entry, so each test that
#   simulates gets its own process (SystemC allows one elaboration per process). Run one with
#   `ctest --test-dir build -R <Suite.Test>` or `build/bin/<name> --gtest_filter=<Suite.Test>`.
#   SHADING_TRACE=<dir> makes the simulating tests write their VCDs there.
# Every test of a program carries the program's name as its ctest label (`ctest -L '^test_blocks$'`;
# scripts/systemc3.sh --subset selects by label).
# shading_add_skipped(<test> <label> <reason>)
#   A test that cannot run in this build (a tool missing, a version that cannot build it): it is still
#   registered, prints "skipped: <reason>" and ctest reports it as skipped (exit 77, SKIP_RETURN_CODE),
#   so a suite run never silently loses it.
function(shading_add_skipped test label reason)
  add_test(NAME ${test} COMMAND sh -c "echo \"skipped: $0\"; exit 77" "${reason}")
  set_tests_properties(${test} PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 10 LABELS ${label})
endfunction()

# shading_add_usage_test(<program> [ARGS <arguments...>])
#   usage.<program>: the program run with bad usage (default: an unknown option) must exit exactly 2,
#   the project's status for it (testbenches/common/exit_status.h: 0 success, 1 failure, 2 bad usage).
function(shading_add_usage_test prog)
  cmake_parse_arguments(ARG "" "" "ARGS" ${ARGN})
  if(NOT ARG_ARGS)
    set(ARG_ARGS --no-such-option)
  endif()
  add_test(NAME usage.${prog} COMMAND sh -c "\"$0\" \"$@\"; test $? -eq 2" $<TARGET_FILE:${prog}> ${ARG_ARGS}
           WORKING_DIRECTORY ${CMAKE_BINARY_DIR})
  set_tests_properties(usage.${prog} PROPERTIES TIMEOUT 30 LABELS ${prog}
                       ENVIRONMENT "SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1")
endfunction()

function(shading_add_bench name)
  cmake_parse_arguments(ARG "" "" "SOURCES;LIBS;RANDOM" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE shading_modules shading_golden shading_tb_common shading_options ${ARG_LIBS})
  set_target_properties(${name} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/bin)
  shading_add_usage_test(${name})
  set(tests bench.${name}.default bench.${name}.inject bench.${name}.inject256)
  add_test(NAME bench.${name}.default COMMAND ${name} --no-vcd WORKING_DIRECTORY ${CMAKE_BINARY_DIR})
  # Exit status exactly 1 (a crash would also be non-zero, and must not pass).
  add_test(NAME bench.${name}.inject
           COMMAND sh -c "\"$0\" --no-vcd --inject-mismatch 3; test $? -eq 1" $<TARGET_FILE:${name}>
           WORKING_DIRECTORY ${CMAKE_BINARY_DIR})
  add_test(NAME bench.${name}.inject256
           COMMAND sh -c "\"$0\" --random 300 --inject-mismatch 0 --inject-count 256; test $? -eq 1"
                   $<TARGET_FILE:${name}>
           WORKING_DIRECTORY ${CMAKE_BINARY_DIR})
  if(NOT ARG_RANDOM)
    set(ARG_RANDOM " ")
  endif()
  set(i 0)
  foreach(args IN LISTS ARG_RANDOM)
    separate_arguments(extra UNIX_COMMAND "${args}")
    set(test bench.${name}.random)
    list(LENGTH ARG_RANDOM n)
    if(n GREATER 1)
      set(test bench.${name}.random.${i})
    endif()
    add_test(NAME ${test} COMMAND ${name} --random 3000 --seed 1 ${extra} WORKING_DIRECTORY ${CMAKE_BINARY_DIR})
    list(APPEND tests ${test})
    math(EXPR i "${i} + 1")
  endforeach()
  # No summary rows from tests; SystemC's banner off.
  set_tests_properties(${tests} PROPERTIES TIMEOUT 120 LABELS ${name}
                       ENVIRONMENT "SHADING_SUMMARY=;SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1")
endfunction()

# SHADING_TEST_OPT_FLAGS: the GoogleTest suites' optimisation in a Release build. A cold build is
# dominated by the suites' code generation, not by parsing (user seconds, g++ 12: test_ua60553.cpp
# -O3 25.4, -O1 15.6-17.5, -Og 13.0, -O0 12.6; test_interp_line.cpp -O3 36.6, -Og 13.9; the
# headers' share, which the precompiled headers of cmake/pch.cmake take away, is 1-3 s a unit). The
# suites check results, never speed, and run as fast at -Og (mostly process start-up; the sanitizer
# build runs them at -Og too): they get this level in place of -O3. The libraries (shading_floor,
# shading_golden, ...) and the bench, render and perf programs whose speed figures are published keep
# -O3 (shading_test_opt below moves the others here). -O0 would save little more: test_cell_unit.cpp
# took 15.7 CPU s at -Og, 14.9 at -O0. No level enables -ffast-math or contracts a*b+c (C++17 without GNU extensions), so the
# suites compute bit for bit what they did at -O3. Other build types keep their own flags.
# Empty: -O3 for the suites too.
set(SHADING_TEST_OPT_FLAGS "-Og" CACHE STRING
    "Optimisation flags of the GoogleTest suites in a Release build (empty: the build type's -O3)")

# The same as compile options, for the suites and for their precompiled header (cmake/pch.cmake).
set(SHADING_GTEST_OPT)
if(SHADING_TEST_OPT_FLAGS)
  separate_arguments(_opt UNIX_COMMAND "${SHADING_TEST_OPT_FLAGS}")
  foreach(_o IN LISTS _opt)
    list(APPEND SHADING_GTEST_OPT $<$<CONFIG:Release>:${_o}>)
  endforeach()
endif()

# shading_test_opt(<targets...>): a program or library whose speed no page quotes (the fuzz targets'
# corpus replays, the options parsers, the integration example, timing_report) compiled at the
# suites' level too, with the same bit-for-bit results: fuzz_tlm.cpp took 47 CPU s at -O3, 23 at -Og.
# No precompiled header (cmake/pch.cmake keeps one per flag set; these are too few to pay for one
# of their own).
function(shading_test_opt)
  foreach(_t IN LISTS ARGN)
    target_compile_options(${_t} PRIVATE ${SHADING_GTEST_OPT})
    set_target_properties(${_t} PROPERTIES SHADING_PCH_SKIP ON)
  endforeach()
endfunction()

# SHADING_UNITY_SUITES: a test program's files compiled as one unit (CMake's UNITY_BUILD), each file's
# names in a namespace of its own. The suites instantiate the same SystemC modules, GoogleTest
# fixtures and checkers, and g++ generated that code again in every file: the default build from an
# empty folder took 816 CPU s with it and 937 without (docs/tests.md). OFF compiles file by file
# (quicker to rebuild after editing one suite).
option(SHADING_UNITY_SUITES "Compile each test program's files as one unit" ON)

function(shading_add_gtest name)
  cmake_parse_arguments(ARG "" "TIMEOUT" "SOURCES;LIBS" ${ARGN})
  if(NOT ARG_TIMEOUT)
    set(ARG_TIMEOUT 300)
  endif()
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE shading_modules shading_golden shading_gtest_main GTest::gtest ${ARG_LIBS})
  set_target_properties(${name} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/bin)
  # Tests read committed files (traces/*.gtkw) from the source tree.
  target_compile_definitions(${name} PRIVATE SHADING_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  # After the build type's -O3 on the command line, so it wins (g++: the last -O counts).
  target_compile_options(${name} PRIVATE ${SHADING_GTEST_OPT})
  set_target_properties(${name} PROPERTIES SHADING_PCH_KIND gtest)
  list(LENGTH ARG_SOURCES _n)
  if(SHADING_UNITY_SUITES AND _n GREATER 1)
    set_target_properties(${name} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 0)
  endif()
  gtest_discover_tests(${name}
    WORKING_DIRECTORY ${CMAKE_BINARY_DIR}
    DISCOVERY_TIMEOUT 60
    PROPERTIES TIMEOUT ${ARG_TIMEOUT} LABELS ${name})
endfunction()

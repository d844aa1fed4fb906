# Helpers that add this project's programs.
#
# shading_add_bench(<name> SOURCES <files...> [LIBS <targets...>])
#   A testbench program with its own sc_main, in build/bin/. It returns the number of errors and
#   warnings SystemC reported, so a caller (scripts/run.sh) sees a failure.
#
# shading_add_gtest(<name> SOURCES <files...> [LIBS <targets...>] [TIMEOUT <s>])
#   A GoogleTest suite whose main() runs the tests inside sc_elab_and_sim (testbenches/common).
#   gtest_discover_tests registers every test as its own ctest entry, so each test that
#   simulates gets its own process (SystemC allows one elaboration per process). Run one with
#   `ctest --test-dir build -R <Suite.Test>` or `build/bin/<name> --gtest_filter=<Suite.Test>`.
#   SHADING_TRACE=<dir> makes the simulating tests write their VCDs there.
function(shading_add_bench name)
  cmake_parse_arguments(ARG "" "" "SOURCES;LIBS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE shading_modules shading_golden shading_tb_common CLI11::CLI11 ${ARG_LIBS})
  set_target_properties(${name} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/bin)
endfunction()

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
  gtest_discover_tests(${name}
    WORKING_DIRECTORY ${CMAKE_BINARY_DIR}
    DISCOVERY_TIMEOUT 60
    PROPERTIES TIMEOUT ${ARG_TIMEOUT})
endfunction()

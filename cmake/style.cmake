# The style checks over the source tree, as ctest entries (scripts/, python3 standard library only):
#   style.function_lengths   no function longer than 120 lines in the model and the programs, 200 in
#                            the studies (scripts/function_lengths.py: file:line of each one over)
#   style.include_cycles     no cycle in the include graph, between files or between folders at any
#                            level (scripts/include_cycles.py: the includes that close each one)
# and a self-test of each on small trees written at test time that break the rule
# (scripts/style_selftest.py), so each check can fail and names what fails.
set(SHADING_FUNCTION_LIMITS src=120 modules=120 testbenches=120 fuzz=120 studies=200)

function(shading_add_style_tests)
  set(rules "")
  foreach(r IN LISTS SHADING_FUNCTION_LIMITS)
    list(APPEND rules --rule ${r})
  endforeach()
  add_test(NAME style.function_lengths
           COMMAND python3 ${PROJECT_SOURCE_DIR}/scripts/function_lengths.py --root ${PROJECT_SOURCE_DIR} ${rules})
  add_test(NAME style.function_lengths_catches_long
           COMMAND python3 ${PROJECT_SOURCE_DIR}/scripts/style_selftest.py function_lengths
                   ${PROJECT_BINARY_DIR}/style_selftest)
  add_test(NAME style.include_cycles
           COMMAND python3 ${PROJECT_SOURCE_DIR}/scripts/include_cycles.py --root ${PROJECT_SOURCE_DIR})
  add_test(NAME style.include_cycles_catches_cycles
           COMMAND python3 ${PROJECT_SOURCE_DIR}/scripts/style_selftest.py include_cycles
                   ${PROJECT_BINARY_DIR}/style_selftest)
  set_tests_properties(style.function_lengths style.function_lengths_catches_long style.include_cycles
                       style.include_cycles_catches_cycles PROPERTIES TIMEOUT 60 LABELS style)
endfunction()

# The SystemC shading pipeline (modules/pipeline/): simulate_frame() for the render program and the
# tests (pipeline_sim.h; the suites are in CMakeLists.txt).
if(TARGET shading_pipeline)
  add_library(shading_pipeline_sim STATIC ${CMAKE_CURRENT_SOURCE_DIR}/pipeline_sim.cpp
              ${CMAKE_CURRENT_SOURCE_DIR}/pipeline_sim_horner.cpp ${CMAKE_CURRENT_SOURCE_DIR}/pipeline_sim_fd.cpp
              ${CMAKE_CURRENT_SOURCE_DIR}/pipeline_sim_fast.cpp)
  target_link_libraries(shading_pipeline_sim PUBLIC shading_pipeline shading_modules shading_ua22802 shading_tb_common)
endif()
if(TARGET shading_pipeline_sim)
  # The cells rendered in SystemC (render_cells.cpp): exit 0 when the frame is the golden one.
  add_executable(render_cells ${CMAKE_CURRENT_SOURCE_DIR}/render_cells.cpp)
  target_link_libraries(render_cells PRIVATE shading_pipeline_sim shading_pipeline shading_options
                        shading_tb_common)
  set_target_properties(render_cells PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/bin)
  shading_test_opt(render_cells)  # a check of the cells' frame; no page quotes its speed (cmake/shading.cmake)
  add_test(NAME pipeline.render_cells COMMAND render_cells --size 96 --device squared --tol 1
           WORKING_DIRECTORY ${CMAKE_BINARY_DIR})
  set_tests_properties(pipeline.render_cells PROPERTIES TIMEOUT 300 LABELS render_cells
                       PASS_REGULAR_EXPRESSION "the frame is the golden model's")
  shading_add_usage_test(render_cells ARGS --size 8)
  # The race (render_race.cpp): every scheme on one frame; exit 0 when the cells' SystemC frame is
  # their golden one. A small head here; a sphere given as an OBJ file the program has never seen.
  add_executable(render_race ${CMAKE_CURRENT_SOURCE_DIR}/render_race.cpp)
  target_link_libraries(render_race PRIVATE shading_pipeline_sim shading_pipeline shading_options shading_tb_common)
  set_target_properties(render_race PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/bin)
  add_test(NAME pipeline.render_race
           COMMAND sh -c "log=$(\"$0\" \"$@\" 2>&1); rc=$?; printf '%s\\n' \"$log\"; test $rc -eq 0 && printf '%s' \"$log\" | grep -q \"is the golden model's\""
                   $<TARGET_FILE:render_race> --size 96 --out ${CMAKE_BINARY_DIR}/out/race_test
           WORKING_DIRECTORY ${CMAKE_BINARY_DIR})
  set_tests_properties(pipeline.render_race PROPERTIES TIMEOUT 300 LABELS render_race
                       ENVIRONMENT "SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1")
  shading_add_usage_test(render_race ARGS --size 8)
  # An empty argument beside a good line: bad usage (CLI11 alone would drop it and run the race).
  add_test(NAME usage.render_race.empty_argument
           COMMAND sh -c "\"$0\" --size 96 --out \"$1\" ''; test $? -eq 2"
                   $<TARGET_FILE:render_race> ${CMAKE_BINARY_DIR}/out/race_empty_argument
           WORKING_DIRECTORY ${CMAKE_BINARY_DIR})
  set_tests_properties(usage.render_race.empty_argument PROPERTIES TIMEOUT 60 LABELS render_race
                       ENVIRONMENT "SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1")
  # The race on models no program was tuned on, written at test time (make_test_obj): a folded blob
  # and a cluster of six blobs at different depths. Exit 0 and the cells' SystemC frame the golden
  # model's, both required (the program's output printed either way).
  foreach(_shape IN ITEMS blob cluster)
    set(_obj ${CMAKE_BINARY_DIR}/out/race_obj/${_shape}.obj)
    set(_race_test pipeline.render_race.obj)
    if(NOT _shape STREQUAL "blob")
      set(_race_test pipeline.render_race.obj_${_shape})
    endif()
    add_test(NAME ${_race_test}.make
             COMMAND sh -c "mkdir -p \"$(dirname \"$2\")\" && \"$0\" --shape \"$1\" --segments 64 --out \"$2\""
                     $<TARGET_FILE:make_test_obj> ${_shape} ${_obj})
    set_tests_properties(${_race_test}.make PROPERTIES TIMEOUT 60 LABELS render_race FIXTURES_SETUP race_obj_${_shape})
    add_test(NAME ${_race_test}
             COMMAND sh -c "log=$(\"$0\" \"$@\" 2>&1); rc=$?; printf '%s\\n' \"$log\"; test $rc -eq 0 && printf '%s' \"$log\" | grep -q \"is the golden model's\""
                     $<TARGET_FILE:render_race> --out ${CMAKE_BINARY_DIR}/out/race_obj/${_shape} --scene ${_obj}
                     --size 128 --n 20
             WORKING_DIRECTORY ${CMAKE_BINARY_DIR})
    set_tests_properties(${_race_test} PROPERTIES TIMEOUT 300 LABELS render_race FIXTURES_REQUIRED race_obj_${_shape}
                         ENVIRONMENT "SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1")
  endforeach()
endif()
# The soak of the fast pipeline (scripts/soak.sh; opt-in, no ctest entry: 1000 renders take minutes).
if(TARGET shading_pipeline_sim)
  add_executable(soak_pipeline ${CMAKE_CURRENT_SOURCE_DIR}/soak_pipeline.cpp)
  target_link_libraries(soak_pipeline PRIVATE shading_pipeline_sim shading_pipeline shading_options)
  target_compile_definitions(soak_pipeline PRIVATE SHADING_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  set_target_properties(soak_pipeline PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/bin)
endif()

# The shading pipeline's RTL twin (rtl/pipeline: the top shading_pipeline.v with the square-and-multiply
# device) co-simulated with the SystemC block model (test_rtl_pipeline.cpp), and lint of the top and
# its parts. Included by testbenches/rtl/CMakeLists.txt after interp.cmake (interp_terms.vh
# generated); without Verilator or its SystemC trace file the co-simulation is registered as
# skipped, with the reason.
set(SHADING_RTL_PIPELINE_DIRS ${SHADING_RTL_DIR}/pipeline ${SHADING_RTL_DIR}/interp ${SHADING_RTL_DIR}/sqmul
    ${SHADING_RTL_DIR}/blocks ${SHADING_RTL_GENERATED})
shading_rtl_ydirs(_pipe_ydirs ${SHADING_RTL_PIPELINE_DIRS})

# The three co-simulated variants (name; EVAL; FD_M; SET; DIV; CARRY; SATURATE): every parameter
# takes both its values in some variant (test_rtl_pipeline.cpp's table), each verilated model
# costing a build of its own. _shading_pipe_variant(<entry>) sets _name and _args (the -G list).
set(_pipe_variants "horner:0:0:0:0:1:1" "fd_any:1:0:1:1:0:0" "fd_m4:1:4:0:1:1:0")
macro(_shading_pipe_variant entry)
  string(REPLACE ":" ";" _f "${entry}")
  list(GET _f 0 _name)
  set(_args)
  set(_i 1)
  foreach(_p EVAL FD_M SET DIV CARRY SATURATE)
    list(GET _f ${_i} _value)
    list(APPEND _args -G${_p}=${_value})
    math(EXPR _i "${_i} + 1")
  endforeach()
endmacro()

# Lint: the co-simulated variants, and the forward-difference evaluator at every fixed m.
foreach(_v IN LISTS _pipe_variants)
  _shading_pipe_variant(${_v})
  shading_rtl_lint(pipeline.${_name} ${_args} --top-module shading_pipeline
                   ${SHADING_RTL_DIR}/pipeline/shading_pipeline.v ${_pipe_ydirs})
endforeach()
foreach(_m 2 3 5 6)
  shading_rtl_lint(pipeline.fd_m${_m} -GEVAL=1 -GFD_M=${_m} --top-module shading_pipeline
                   ${SHADING_RTL_DIR}/pipeline/shading_pipeline.v ${_pipe_ydirs})
endforeach()
# The parts at the parameter values the top does not reach: the sample channel's fourth cubic unit
# (case 2, shift-add) and the sample controller for UA 60553's unclocked device (output 29 =
# strobe 17), with and without the carry, for any m and for fixed m = 4.
shading_rtl_lint(pipeline.sample_channel.c2sa -GSET=1 -GDIV=0 --top-module sample_channel
                 ${SHADING_RTL_DIR}/pipeline/sample_channel.v ${_pipe_ydirs})
shading_rtl_lint(pipeline.sample_ctrl.unclocked -GCLOCKED=0 -GCARRY=1 --top-module sample_ctrl
                 ${SHADING_RTL_DIR}/pipeline/sample_ctrl.v ${_pipe_ydirs})
shading_rtl_lint(pipeline.sample_ctrl.unclocked_fd_m4 -GCLOCKED=0 -GFD_M=4 --top-module sample_ctrl
                 ${SHADING_RTL_DIR}/pipeline/sample_ctrl.v ${_pipe_ydirs})

# Whole planned frames through the RTL beside the model (render_pipeline_rtl): the head at 128 with
# each variant and both degrees, a sphere, the head at 512 and an OBJ model written at test time
# (make_test_obj). Each case: name, variant, scene, size, degree.
set(_frame_cases "head128.horner|horner|head|128|cubic" "head128.fd_any|fd_any|head|128|cubic"
    "head128.fd_m4|fd_m4|head|128|cubic" "head128.horner.quadratic|horner|head|128|quadratic"
    "head128.fd_any.quadratic|fd_any|head|128|quadratic" "sphere96|horner|sphere|96|cubic"
    "head512|fd_any|head|512|cubic" "obj_blob|fd_m4|${CMAKE_BINARY_DIR}/out/rtl_frame/blob.obj|128|cubic")
set(_frame_tests)
foreach(_c IN LISTS _frame_cases)
  string(REPLACE "|" ";" _f "${_c}")
  list(GET _f 0 _name)
  list(APPEND _frame_tests rtl.frame.${_name})
endforeach()

set(_skips rtl.cosim.pipeline test_rtl)
foreach(_t IN LISTS _frame_tests)
  list(APPEND _skips ${_t} render_pipeline_rtl)
endforeach()
shading_rtl_cosim_or_skip(_cosim ${_skips})
if(NOT _cosim)
  return()
endif()

# The three variants verilated once, into a library that the suite and render_pipeline_rtl both link
# (each model is megabytes of C++: compiling it once per program cost 20-40 CPU s a model), each
# through a unit of its own (ALONE), so the three compile in parallel. The Verilator macros its header
# reads (verilated.h: VM_SC, VM_TRACE) go to the programs with it.
add_library(shading_rtl_pipeline_models STATIC)
foreach(_v IN LISTS _pipe_variants)
  _shading_pipe_variant(${_v})
  shading_verilate_rtl(shading_rtl_pipeline_models Vrtl_pipeline_${_name} TOP shading_pipeline
                       SOURCE ${SHADING_RTL_DIR}/pipeline/shading_pipeline.v DIRS ${SHADING_RTL_PIPELINE_DIRS}
                       ARGS ${_args} ALONE)
endforeach()
target_compile_definitions(shading_rtl_pipeline_models PUBLIC VM_COVERAGE=0 VM_SC=1 VM_TRACE=1 VM_TRACE_FST=0
                           VM_TRACE_VCD=1)

# The suite, in test_rtl (CMakeLists.txt). The head's planned frame (AnotherSampleSetIsSeenOnAFrame)
# reads the scan in this tree's data/head/ (SHADING_SOURCE_DIR, as every suite).
target_sources(test_rtl PRIVATE test_rtl_pipeline.cpp)
target_link_libraries(test_rtl PRIVATE shading_pipeline shading_pipeline_sim shading_rtl_pipeline_models)

# render_pipeline_rtl: render_pipeline's scene options and setup (shading_render, which needs
# nlohmann-json), the three variants verilated into it.
if(NOT TARGET shading_render)
  foreach(_t IN LISTS _frame_tests)
    shading_add_skipped(${_t} render_pipeline_rtl "render_pipeline's library (shading_render) is not built")
  endforeach()
  return()
endif()
add_executable(render_pipeline_rtl ${CMAKE_CURRENT_SOURCE_DIR}/render_pipeline_rtl.cpp)
target_link_libraries(render_pipeline_rtl PRIVATE shading_render shading_rtl_pipeline_models)
target_compile_options(render_pipeline_rtl PRIVATE -Wno-unused-parameter)  # Verilator's headers
# A check (exit 0 only with 0 differences), not a rate: compiled like the suites (cmake/shading.cmake).
shading_test_opt(render_pipeline_rtl)
set_target_properties(render_pipeline_rtl PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/bin)
add_test(NAME rtl.frame.obj_blob.make
         COMMAND sh -c "mkdir -p \"$(dirname \"$1\")\" && \"$0\" --shape blob --segments 64 --out \"$1\""
                 $<TARGET_FILE:make_test_obj> ${CMAKE_BINARY_DIR}/out/rtl_frame/blob.obj)
set_tests_properties(rtl.frame.obj_blob.make PROPERTIES TIMEOUT 60 LABELS render_pipeline_rtl FIXTURES_SETUP rtl_frame_obj)
# Exit 0 and the verdict line, both required (the program's output printed either way).
foreach(_c IN LISTS _frame_cases)
  string(REPLACE "|" ";" _f "${_c}")
  list(GET _f 0 _name)
  list(GET _f 1 _variant)
  list(GET _f 2 _scene)
  list(GET _f 3 _size)
  list(GET _f 4 _degree)
  add_test(NAME rtl.frame.${_name}
           COMMAND sh -c "log=$(\"$0\" \"$@\" 2>&1); rc=$?; printf '%s\\n' \"$log\"; test $rc -eq 0 && printf '%s' \"$log\" | grep -q '^PASS: '"
                   $<TARGET_FILE:render_pipeline_rtl> --scene ${_scene} --size ${_size} --variant ${_variant}
                   --degree ${_degree}
           WORKING_DIRECTORY ${CMAKE_BINARY_DIR})
  set_tests_properties(rtl.frame.${_name} PROPERTIES TIMEOUT 300 LABELS render_pipeline_rtl
                       ENVIRONMENT "SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1")
endforeach()
set_tests_properties(rtl.frame.obj_blob PROPERTIES FIXTURES_REQUIRED rtl_frame_obj)
# Bad input: a clear message and exit 2 (an unknown scene, an OBJ file that is not there, a size out of range).
foreach(_bad "unknown_scene|--scene teapot" "missing_obj|--scene ${CMAKE_BINARY_DIR}/no_such_file.obj"
        "too_large|--size 100000")
  string(REPLACE "|" ";" _f "${_bad}")
  list(GET _f 0 _name)
  list(GET _f 1 _args)
  separate_arguments(_args)
  add_test(NAME rtl.frame.bad.${_name} COMMAND sh -c "\"$0\" \"$@\"; test $? -eq 2" $<TARGET_FILE:render_pipeline_rtl> ${_args})
  set_tests_properties(rtl.frame.bad.${_name} PROPERTIES TIMEOUT 60 LABELS render_pipeline_rtl)
endforeach()
shading_add_usage_test(render_pipeline_rtl)

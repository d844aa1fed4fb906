# The shading pipeline's RTL twin (rtl/pipeline: the top shading_pipeline.v with the square-and-multiply
# device) co-simulated with the SystemC block model (test_rtl_pipeline.cpp), and lint of the top and
# its parts. Included by testbenches/rtl/CMakeLists.txt after interp.cmake (interp_terms.vh
# generated); without Verilator or its SystemC trace file the co-simulation is registered as
# skipped, with the reason.
set(SHADING_RTL_PIPELINE_DIRS ${SHADING_RTL_DIR}/pipeline ${SHADING_RTL_DIR}/interp ${SHADING_RTL_DIR}/sqmul
    ${SHADING_RTL_DIR}/blocks ${SHADING_RTL_GENERATED})
set(_pipe_ydirs)
foreach(_d IN LISTS SHADING_RTL_PIPELINE_DIRS)
  list(APPEND _pipe_ydirs -y ${_d})
endforeach()

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

if(NOT SHADING_RTL)
  shading_add_skipped(rtl.cosim.pipeline test_rtl_pipeline "${SHADING_RTL_SKIP_REASON}")
  return()
elseif(NOT SHADING_RTL_TRACE)
  shading_add_skipped(rtl.cosim.pipeline test_rtl_pipeline "${SHADING_RTL_TRACE_SKIP_REASON}")
  return()
endif()

shading_add_gtest(test_rtl_pipeline SOURCES test_rtl_pipeline.cpp LIBS shading_pipeline TIMEOUT 300)
# The head's planned frame (AnotherSampleSetIsSeenOnAFrame): the scan in this tree's data/head/.
target_compile_definitions(test_rtl_pipeline PRIVATE SHADING_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
foreach(_v IN LISTS _pipe_variants)
  _shading_pipe_variant(${_v})
  shading_verilate_rtl(test_rtl_pipeline Vrtl_pipeline_${_name} TOP shading_pipeline
                       SOURCE ${SHADING_RTL_DIR}/pipeline/shading_pipeline.v DIRS ${SHADING_RTL_PIPELINE_DIRS}
                       ARGS ${_args})
endforeach()

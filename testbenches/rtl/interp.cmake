# The interpolation paper's units as RTL (rtl/interp: coef_unit_cubic, horner_unit + horner_ctrl; and
# our forward-difference evaluators fd_eval + fd_ctrl, fd_eval_var + fd_ctrl_var)
# co-simulated with the SystemC units through verilator --sc. Included by testbenches/rtl/CMakeLists.txt;
# without Verilator (cmake/verilator.cmake) its tests are registered as skipped, with the reason.
set(SHADING_RTL_INTERP_DIRS ${SHADING_RTL_DIR}/interp ${SHADING_RTL_DIR}/blocks ${SHADING_RTL_GENERATED})
shading_rtl_ydirs(_interp_ydirs ${SHADING_RTL_INTERP_DIRS})
# Lint: every variant under verilator --lint-only -Wall (a warning fails the test).
foreach(_v IN ITEMS "c1sa;0;0" "c1ex;0;1" "c2sa;1;0" "c2ex;1;1")
  list(GET _v 0 _name)
  list(GET _v 1 _set)
  list(GET _v 2 _div)
  shading_rtl_lint(coef_unit_cubic.${_name} -GSET=${_set} -GDIV=${_div} --top-module coef_unit_cubic
                   ${SHADING_RTL_DIR}/interp/coef_unit_cubic.v ${_interp_ydirs})
endforeach()
shading_rtl_lint(horner_unit --top-module horner_unit ${SHADING_RTL_DIR}/interp/horner_unit.v ${_interp_ydirs})
# The forward-difference evaluators: built for each interval length, and for any m per interval.
foreach(_m 2 3 4 5 6)
  shading_rtl_lint(fd_eval.m${_m} -GM=${_m} --top-module fd_eval ${SHADING_RTL_DIR}/interp/fd_eval.v ${_interp_ydirs})
endforeach()
shading_rtl_lint(fd_eval_var --top-module fd_eval_var ${SHADING_RTL_DIR}/interp/fd_eval_var.v ${_interp_ydirs})
if(NOT SHADING_RTL)
  shading_add_skipped(rtl.cosim.interp test_rtl_interp "${SHADING_RTL_SKIP_REASON}")
  shading_add_skipped(rtl.cosim.fd test_rtl_interp "${SHADING_RTL_SKIP_REASON}")
  shading_add_skipped(synth.smoke synth "the synthesis flow reads RTL generated with the RTL targets: ${SHADING_RTL_SKIP_REASON}")
  return()
endif()

# interp_terms.vh (the Horner controller's select codes, the coefficient networks' term tables, the
# forward-difference select codes and set-up tables, the pixel controllers' widths)
# must exist when CMake configures, because verilate() runs Verilator then. Its generator reads
# SystemC headers, so it is compiled against libsystemc here; a change to it or to the headers it
# reads re-runs CMake.
set(_interp_gen_src ${CMAKE_CURRENT_SOURCE_DIR}/gen_interp_rtl.cpp)
set(_interp_gen_dir ${PROJECT_BINARY_DIR}/CMakeFiles/gen_interp_rtl_configure)
try_compile(_interp_gen_ok ${_interp_gen_dir} SOURCES ${_interp_gen_src}
            CMAKE_FLAGS "-DINCLUDE_DIRECTORIES=${PROJECT_SOURCE_DIR}/src;${PROJECT_SOURCE_DIR}/src/floor;${PROJECT_SOURCE_DIR}/modules"
            LINK_LIBRARIES ${SHADING_SYSTEMC_TARGET}
            CXX_STANDARD 17 CXX_STANDARD_REQUIRED ON
            OUTPUT_VARIABLE _interp_gen_log COPY_FILE ${_interp_gen_dir}/gen_interp_rtl)
if(NOT _interp_gen_ok)
  message(FATAL_ERROR "testbenches/rtl/gen_interp_rtl.cpp did not compile:\n${_interp_gen_log}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E env SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1
                        ${_interp_gen_dir}/gen_interp_rtl ${_interp_gen_dir}/interp_terms.vh
                RESULT_VARIABLE _interp_gen_rc)
if(_interp_gen_rc)
  message(FATAL_ERROR "gen_interp_rtl failed (${_interp_gen_rc})")
endif()
file(MAKE_DIRECTORY ${SHADING_RTL_GENERATED})
file(COPY_FILE ${_interp_gen_dir}/interp_terms.vh ${SHADING_RTL_GENERATED}/interp_terms.vh ONLY_IF_DIFFERENT)
set_property(DIRECTORY ${PROJECT_SOURCE_DIR} APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${_interp_gen_src}
             ${PROJECT_SOURCE_DIR}/modules/interp/coef_unit_cubic.h ${PROJECT_SOURCE_DIR}/modules/interp/horner_ctrl.h
             ${PROJECT_SOURCE_DIR}/modules/interp/coef_unit_quad.h
             ${PROJECT_SOURCE_DIR}/modules/blocks/shift_add_network.h ${PROJECT_SOURCE_DIR}/modules/interp/fd_ctrl.h
             ${PROJECT_SOURCE_DIR}/modules/interp/fd_count.h ${PROJECT_SOURCE_DIR}/modules/interp/fd_setup.h
             ${PROJECT_SOURCE_DIR}/modules/interp/horner_steps.h ${PROJECT_SOURCE_DIR}/modules/pipeline/pipeline_pins.h
             ${PROJECT_SOURCE_DIR}/modules/pipeline/horner_pixel_ctrl.h
             ${PROJECT_SOURCE_DIR}/modules/pipeline/fd_pixel_ctrl.h)

# shading_verilate_interp(<target> <prefix> <top> [<-Gparam=value>...]): one RTL unit as the SystemC
# module <prefix>, pins as sc_uint<W> like our units' (--pins-sc-uint); -Wall warnings fail the build.
function(shading_verilate_interp target prefix top)
  verilate(${target} SYSTEMC
           PREFIX ${prefix}
           TOP_MODULE ${top}
           SOURCES ${SHADING_RTL_DIR}/interp/${top}.v
           INCLUDE_DIRS ${SHADING_RTL_INTERP_DIRS}
           VERILATOR_ARGS -Wall --pins-sc-uint ${ARGN})
  shading_verilated_finish(${target} ${prefix})  # cmake/verilator.cmake: the runtime once, the model as one unit
endfunction()

# The co-simulation suites, one program: the RTL coefficient unit (4 variants) and Horner unit beside
# ours (test_rtl_interp.cpp: 3-6 s a test idle, x3-5 under sanitizers), and the forward-difference
# evaluators' (test_rtl_fd.cpp, below).
shading_add_gtest(test_rtl_interp SOURCES test_rtl_interp.cpp test_rtl_fd.cpp TIMEOUT 300)
target_link_libraries(test_rtl_interp PRIVATE Threads::Threads)
shading_verilate_interp(test_rtl_interp Vrtl_coef_c1sa coef_unit_cubic -GSET=0 -GDIV=0)
shading_verilate_interp(test_rtl_interp Vrtl_coef_c1ex coef_unit_cubic -GSET=0 -GDIV=1)
shading_verilate_interp(test_rtl_interp Vrtl_coef_c2sa coef_unit_cubic -GSET=1 -GDIV=0)
shading_verilate_interp(test_rtl_interp Vrtl_coef_c2ex coef_unit_cubic -GSET=1 -GDIV=1)
shading_verilate_interp(test_rtl_interp Vrtl_horner_unit horner_unit)

# The forward-difference evaluators' RTL beside ours: fd_eval at every M, fd_eval_var for m in 2..6.
foreach(_m 2 3 4 5 6)
  shading_verilate_interp(test_rtl_interp Vrtl_fd_eval_m${_m} fd_eval -GM=${_m})
endforeach()
shading_verilate_interp(test_rtl_interp Vrtl_fd_eval_var fd_eval_var)

# Synthesis smoke test (scripts/synth.sh, docs/synthesis.md): the flow runs on the
# smallest unit (UA 60553's generator), and yosys, reading the generated ROM case tables as memories,
# counts exactly the ROM size of the format tables (16 384 bits at F = 6, and F = 2). Skipped (exit 3)
# when yosys is not installed.
add_test(NAME synth.smoke
         COMMAND ${PROJECT_SOURCE_DIR}/scripts/synth.sh --build ${PROJECT_BINARY_DIR}
                 --out ${CMAKE_CURRENT_BINARY_DIR}/synth_smoke --jobs 1 --only "^(gen_linear|rom_f2_bits|rom_f6_bits)$")
set_tests_properties(synth.smoke PROPERTIES SKIP_RETURN_CODE 3 TIMEOUT 120 LABELS synth)

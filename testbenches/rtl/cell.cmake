# The cell unit's RTL twin (rtl/pipeline/cell_unit.v with cell_channel.v, cell_ctrl.v and
# rtl/blocks/ram.v) co-simulated with the SystemC cell unit (test_rtl_cell_unit.cpp), and lint of the
# top and its parts. Included by testbenches/rtl/CMakeLists.txt after interp.cmake (interp_terms.vh
# generated); without Verilator or its SystemC trace file the co-simulation is registered as
# skipped, with the reason.
set(SHADING_RTL_CELL_DIRS ${SHADING_RTL_DIR}/pipeline ${SHADING_RTL_DIR}/interp ${SHADING_RTL_DIR}/blocks
    ${SHADING_RTL_GENERATED})
shading_rtl_ydirs(_cell_ydirs ${SHADING_RTL_CELL_DIRS})

# Lint: the top, its parts, and the memory block at a depth that leaves addresses naming no word.
foreach(_top cell_unit cell_channel cell_ctrl)
  shading_rtl_lint(cell.${_top} --top-module ${_top} ${SHADING_RTL_DIR}/pipeline/${_top}.v ${_cell_ydirs})
endforeach()
shading_rtl_lint(blocks.ram -GDEPTH=64 --top-module ram ${SHADING_RTL_DIR}/blocks/ram.v)
shading_rtl_lint(blocks.ram_partial -GDEPTH=48 --top-module ram ${SHADING_RTL_DIR}/blocks/ram.v)

shading_rtl_cosim_or_skip(_cosim rtl.cosim.cell_unit test_rtl)
if(NOT _cosim)
  return()
endif()

# The suite, in test_rtl (CMakeLists.txt).
target_sources(test_rtl PRIVATE test_rtl_cell_unit.cpp)
target_link_libraries(test_rtl PRIVATE shading_pipeline_sim shading_pipeline)
# The largest verilated model (its C++ took 44 CPU s at -O1, 35 at -Og in the build, the mean of two
# back-to-back compiles on the shared machine; -O0 made its tests run 3.3 times as long, -Og 1.2
# times, about 0.4 CPU s): -Og, like the suites.
shading_verilate_rtl(test_rtl Vrtl_cell_unit TOP cell_unit SOURCE ${SHADING_RTL_DIR}/pipeline/cell_unit.v
                     DIRS ${SHADING_RTL_CELL_DIRS} OPT "${SHADING_TEST_OPT_FLAGS}")

# The memories' RTL (rtl/blocks/ram.v, rtl/pipeline/frame_buffer.v, walker_store.v, band_buffer.v)
# co-simulated with the SystemC blocks (test_rtl_memories.cpp), and lint of each at the frames we
# render. Included by
# testbenches/rtl/CMakeLists.txt; without Verilator or its SystemC trace file the co-simulation is
# registered as skipped, with the reason.
set(SHADING_RTL_MEM_DIRS ${SHADING_RTL_DIR}/pipeline ${SHADING_RTL_DIR}/blocks ${SHADING_RTL_GENERATED})
shading_rtl_ydirs(_mem_ydirs ${SHADING_RTL_MEM_DIRS})
foreach(_size 64 512 1024)
  shading_rtl_lint(frame_buffer.${_size} -GWIDTH=${_size} -GHEIGHT=${_size} --top-module frame_buffer
                   ${SHADING_RTL_DIR}/pipeline/frame_buffer.v ${_mem_ydirs})
endforeach()
foreach(_size 512 1024)
  shading_rtl_lint(band_buffer.${_size} -GWIDTH=${_size} --top-module band_buffer
                   ${SHADING_RTL_DIR}/pipeline/band_buffer.v ${_mem_ydirs})
endforeach()
shading_rtl_lint(walker_store --top-module walker_store ${SHADING_RTL_DIR}/pipeline/walker_store.v ${_mem_ydirs})
shading_rtl_lint(frame_buffer.48x40 -GWIDTH=48 -GHEIGHT=40 --top-module frame_buffer
                 ${SHADING_RTL_DIR}/pipeline/frame_buffer.v ${_mem_ydirs})

shading_rtl_cosim_or_skip(_cosim rtl.cosim.memories test_rtl)
if(NOT _cosim)
  return()
endif()

# The suite, in test_rtl (CMakeLists.txt).
target_sources(test_rtl PRIVATE test_rtl_memories.cpp)
target_link_libraries(test_rtl PRIVATE shading_pipeline)
shading_verilate_rtl(test_rtl Vrtl_ram TOP ram SOURCE ${SHADING_RTL_DIR}/blocks/ram.v
                     DIRS ${SHADING_RTL_MEM_DIRS} ARGS -GW=16 -GDEPTH=48 -GAW=6)
shading_verilate_rtl(test_rtl Vrtl_frame_buffer TOP frame_buffer
                     SOURCE ${SHADING_RTL_DIR}/pipeline/frame_buffer.v DIRS ${SHADING_RTL_MEM_DIRS}
                     ARGS -GWIDTH=48 -GHEIGHT=40)
# The cells' stores at the format's capacities, the band buffer of a 512-pixel frame (the head at 512).
shading_verilate_rtl(test_rtl Vrtl_walker_store TOP walker_store
                     SOURCE ${SHADING_RTL_DIR}/pipeline/walker_store.v DIRS ${SHADING_RTL_MEM_DIRS})
shading_verilate_rtl(test_rtl Vrtl_band_buffer TOP band_buffer
                     SOURCE ${SHADING_RTL_DIR}/pipeline/band_buffer.v DIRS ${SHADING_RTL_MEM_DIRS} ARGS -GWIDTH=512)

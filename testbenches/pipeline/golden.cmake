# The golden pipeline (src/golden_pipeline/golden_pipeline.cpp, metrics.cpp): the sample stage, one interval,
# whole frames and the error measures, against hand-worked values, the real-valued interpolation
# reference and the scene's per-pixel references. Plain C++, no simulation: tests may share a process.
shading_add_gtest(test_pipeline_golden SOURCES test_pipeline_golden.cpp test_pipeline_frame.cpp LIBS shading_pipeline shading_golden TIMEOUT 120)
# The bit-accurate cells (src/golden_pipeline/cells.h): hand-worked values, a flat square hand-counted,
# the planner's map of taken pixels, and on the head at 512 the frame and the interpolation target.
shading_add_gtest(test_golden_cells SOURCES test_golden_cells.cpp LIBS shading_pipeline TIMEOUT 300)
# The race (src/golden_pipeline/race.h): the one-triangle scene's Phong 1975 row by hand, rounded() on
# hand values, on the head at 128 every row's image from its scheme called directly, the frozen
# configuration as race.cpp states it, bad input refused, and the procedural OBJ read back as written.
shading_add_gtest(test_race SOURCES test_race.cpp LIBS shading_pipeline TIMEOUT 300)

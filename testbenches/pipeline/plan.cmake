# The geometry side (src/golden_pipeline/plan.cpp) and the head's zone map (zones.cpp): plans checked against
# the rasteriser's spans and discontinuities and the geometry recomputed at the documented pixels.
# Plain C++, no simulation: tests may share a process. ZoneMapOfTheHead writes out/pipeline/zones_head.png
# in the build tree (the zone map over the shaded head, to look at).
shading_add_gtest(test_pipeline_plan SOURCES test_pipeline_plan.cpp test_pipeline_zones.cpp test_pipeline_refine.cpp LIBS shading_pipeline TIMEOUT 120)
# The geometry side's stepped and from-scratch units, and the geometry-only policies (plan.cpp).
shading_add_gtest(test_pipeline_baselines SOURCES test_pipeline_baselines.cpp LIBS shading_pipeline TIMEOUT 60)

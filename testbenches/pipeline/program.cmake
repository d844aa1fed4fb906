# The render program (render_pipeline): a scene through the interpolation paper's shading system, golden model and
# (when the SystemC pipeline is built, sim.cmake) the SystemC pipeline, PNGs and a report; --sweep.
if(TARGET shading_pipeline)
  find_package(nlohmann_json 3 QUIET)
  if(NOT nlohmann_json_FOUND)
    message(WARNING "render_pipeline needs nlohmann-json (Debian: nlohmann-json3-dev; scripts/setup.sh installs it): not built")
    return()
  endif()
  # Its parts but main (render_program.h) as a library: a study renders with them in place of
  # make_plan's plan (studies/yardsticks/yardstick_study). SHADING_PIPELINE_SIM tells them, and the
  # programs' sc_main, whether the SystemC pipeline is built in.
  add_library(shading_render STATIC ${CMAKE_CURRENT_SOURCE_DIR}/render_setup.cpp ${CMAKE_CURRENT_SOURCE_DIR}/render_run.cpp
              ${CMAKE_CURRENT_SOURCE_DIR}/render_report.cpp ${CMAKE_CURRENT_SOURCE_DIR}/render_images.cpp
              ${CMAKE_CURRENT_SOURCE_DIR}/render_sweep.cpp)
  target_link_libraries(shading_render PUBLIC shading_pipeline shading_tb_common shading_render_options nlohmann_json::nlohmann_json)
  if(TARGET shading_pipeline_sim)
    target_link_libraries(shading_render PUBLIC shading_pipeline_sim)
    target_compile_definitions(shading_render PUBLIC SHADING_PIPELINE_SIM=1)
  else()
    message(STATUS "render_pipeline: no SystemC pipeline (shading_pipeline_sim) yet: --sim unavailable")
  endif()
  add_executable(render_pipeline ${CMAKE_CURRENT_SOURCE_DIR}/render_pipeline.cpp)
  target_link_libraries(render_pipeline PRIVATE shading_render)
  # The default --data-dir: this source tree (the head scan lives in data/head/).
  target_compile_definitions(render_pipeline PRIVATE SHADING_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  set_target_properties(render_pipeline PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/bin)

  set(rp_out ${CMAKE_BINARY_DIR}/out/pipeline_test)
  set(rp_tests)
  # End to end on a small head through both pipelines: exit 0 (the SystemC frame equal to the golden
  # one bit for bit), then the report must hold the measured pairs, the operation counts and the files.
  # The renders name their device (UA 60553 with the patent's constants), not the program's default,
  # so that each test keeps testing the same pipeline.
  set(rp_sim --sim)
  if(NOT TARGET shading_pipeline_sim)
    set(rp_sim --no-sim)
  endif()
  add_test(NAME pipeline.render.head48
           COMMAND sh -c "rm -rf \"$1\" && \"$0\" --scene head --size 48 --device patent $2 --out \"$1\""
                   $<TARGET_FILE:render_pipeline> ${rp_out}/head48 ${rp_sim})
  add_test(NAME pipeline.render.head48.report
           COMMAND sh -c "for f in phong hardware per_pixel error_interp error_total degree_map interval_map zone_map sheet; do test -s \"$0/$f.png\" || exit 1; done; for k in '\"interpolation\"' '\"total\"' '\"brdf\"' '\"nmse\"' '\"phong_long_over_hardware_long\"' '\"scanline_phong_long_over_hardware_long\"' '\"displayed_8bit\"' '\"phong_scanline\"' '\"clocks_per_pixel\"' '\"forehead\"' '\"pixels_over\"'; do grep -q \"$k\" \"$0/report.json\" || { echo missing $k; exit 1; }; done; test -s \"$0/report.md\""
                   ${rp_out}/head48)
  set_tests_properties(pipeline.render.head48.report PROPERTIES DEPENDS pipeline.render.head48)
  list(APPEND rp_tests pipeline.render.head48 pipeline.render.head48.report)
  # The lit guard from the command line, on a head lit from the side: the SystemC frame equal to the
  # golden one (exit 0) and the option in the report's configuration.
  add_test(NAME pipeline.render.lit_guard
           COMMAND sh -c "rm -rf \"$1\" && \"$0\" --scene head --size 96 --device patent --light=-40,25 --n 5 --length adaptive --degree cubic --split-at-check --carry-samples --lit-guard --eval fd --no-images $2 --out \"$1\" && grep -q '\"lit_guard\": true' \"$1/report.json\""
                   $<TARGET_FILE:render_pipeline> ${rp_out}/lit_guard ${rp_sim})
  list(APPEND rp_tests pipeline.render.lit_guard)
  if(TARGET shading_pipeline_sim)
    # The bit-exact check can fail: one golden pixel corrupted (hidden --inject-mismatch) must give
    # exit 1 and no report.
    add_test(NAME pipeline.render.inject_mismatch
             COMMAND sh -c "rm -rf \"$1\"; \"$0\" --scene head --size 32 --device patent --sim --inject-mismatch --out \"$1\"; test $? -eq 1 && test ! -e \"$1/report.json\""
                     $<TARGET_FILE:render_pipeline> ${rp_out}/inject)
    # --vcd writes the SystemC pipeline's trace.
    add_test(NAME pipeline.render.vcd
             COMMAND sh -c "rm -rf \"$1\" && \"$0\" --scene sphere --size 16 --device patent --sim --no-images --vcd \"$1/pipeline.vcd\" --out \"$1\" && test -s \"$1/pipeline.vcd\""
                     $<TARGET_FILE:render_pipeline> ${rp_out}/vcd)
    list(APPEND rp_tests pipeline.render.inject_mismatch pipeline.render.vcd)
  endif()
  # A tiny sweep (one device, the small grid: 48 configurations, 2 processes) merges one CSV row per
  # configuration under the header.
  add_test(NAME pipeline.sweep.tiny
           COMMAND sh -c "\"$0\" --sweep --scene head --size 32 --device patent --jobs 2 --out \"$1\" && test $(wc -l < \"$1/sweep.csv\") -eq 49"
                   $<TARGET_FILE:render_pipeline> ${rp_out}/sweep)
  # The exponents grid: one device x 8 exponents.
  add_test(NAME pipeline.sweep.exponents
           COMMAND sh -c "\"$0\" --sweep --grid exponents --scene head --size 24 --device minimax --jobs 2 --out \"$1\" && test $(wc -l < \"$1/sweep.csv\") -eq 9 && grep -q ',500,minimax,' \"$1/sweep.csv\""
                   $<TARGET_FILE:render_pipeline> ${rp_out}/sweep_n)
  # The claims grid, tiny (2 scenes x 1 light x 1 n x 1 size x 1 device x 16 policies, 24 pixels):
  # two shards merged (rows sorted by the config column) equal one run row for row; --emit-jobs
  # prints one command line per configuration; a bad shard is bad input.
  set(rp_claims --sweep --grid claims --scenes sphere torus --lights 0,30 --ns 20 --sizes 24 --device squared --jobs 2)
  add_test(NAME pipeline.sweep.claims_shards
           COMMAND sh -c "set -e; b=\"$0\"; o=\"$1\"; shift; rm -rf \"$o\"; \"$b\" \"$@\" --out \"$o/all\"; \"$b\" \"$@\" --shard 1/2 --out \"$o/s1\"; \"$b\" \"$@\" --shard 2/2 --out \"$o/s2\"; test $(wc -l < \"$o/all/sweep.csv\") -eq 33; (tail -n +2 \"$o/s1/sweep.csv\"; tail -n +2 \"$o/s2/sweep.csv\") | sort -t, -k1,1n > \"$o/merged\"; tail -n +2 \"$o/all/sweep.csv\" | cmp - \"$o/merged\"; grep -q ',geometry,.*,yes,0,0$' \"$o/all/sweep.csv\"; grep -q ',adaptive,.*,no,0,0$' \"$o/all/sweep.csv\"; grep -q ',adaptive,.*,no,1,1$' \"$o/all/sweep.csv\"; grep -q ',geometry,.*,yes,1,1$' \"$o/all/sweep.csv\""
                   $<TARGET_FILE:render_pipeline> ${rp_out}/claims ${rp_claims})
  add_test(NAME pipeline.sweep.emit_jobs
           COMMAND sh -c "b=\"$0\"; test $(\"$b\" \"$@\" --emit-jobs --out /nonexistent | grep -c -- '--shard [0-9]*/32 --csv') -eq 32"
                   $<TARGET_FILE:render_pipeline> ${rp_claims})
  add_test(NAME pipeline.sweep.bad_shard
           COMMAND sh -c "b=\"$0\"; o=\"$1\"; shift; \"$b\" \"$@\" --shard 3/2 --out \"$o\"; test $? -eq 2"
                   $<TARGET_FILE:render_pipeline> ${rp_out}/bad_shard ${rp_claims})
  list(APPEND rp_tests pipeline.sweep.tiny pipeline.sweep.exponents pipeline.sweep.claims_shards pipeline.sweep.emit_jobs
       pipeline.sweep.bad_shard)
  # Bad input: a clear message, nothing written, and the project's status (common/exit_status.h): 2 for
  # bad usage (a value out of range, an unknown name, a plan the units cannot run), 1 for an OBJ file
  # that cannot be read or used. Each case: name, arguments, status.
  set(rp_bad
      "m0|--m 0|2"
      "m7|--m 7|2"
      "adaptive_range|--length adaptive --m-min 2 --m-max 9|2"
      "unknown_scene|--scene teapot|2"
      "too_large|--size 100000|2"
      "n0|--n 0|2"
      "n1001|--n 1001|2"
      "n_not_a_number|--n ten|2"
      "missing_obj|--scene ${CMAKE_BINARY_DIR}/no_such_file.obj|1"
      "malformed_obj|--scene ${CMAKE_CURRENT_SOURCE_DIR}/data/malformed.obj|1"
      "empty_obj|--scene ${CMAKE_CURRENT_SOURCE_DIR}/data/empty.obj|1"
      "unknown_device|--device phong|2"
      "device_all|--device all|2"
      "bad_light|--light 30|2"
      "fd_adaptive_range|--eval fd --length adaptive --m-min 1|2")
  foreach(case IN LISTS rp_bad)
    string(REPLACE "|" ";" parts "${case}")
    list(GET parts 0 name)
    list(GET parts 1 args)
    list(GET parts 2 rc)
    add_test(NAME pipeline.render.bad.${name}
             COMMAND sh -c "rm -rf \"$1\"; \"$0\" --no-sim ${args} --out \"$1\"; rc=$?; test $rc -eq ${rc} && test ! -e \"$1/report.json\""
                     $<TARGET_FILE:render_pipeline> ${rp_out}/bad_${name})
    list(APPEND rp_tests pipeline.render.bad.${name})
  endforeach()
  set_tests_properties(${rp_tests} PROPERTIES TIMEOUT 120 LABELS render_pipeline
                       ENVIRONMENT "SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1")
  shading_add_usage_test(render_pipeline)
endif()

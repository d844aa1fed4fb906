# The RTL twin (rtl/) and its co-simulation with the SystemC model through `verilator --sc`
# (rtl/README.md). Optional: without Verilator (Debian's `verilator`,
# scripts/setup.sh installs it) there are no RTL targets, and the RTL tests are registered as skipped
# with the reason (testbenches/rtl).
#
# Sets SHADING_RTL (ON/OFF: Verilator found and SHADING_VERILATE on), SHADING_RTL_SKIP_REASON (why not, when OFF),
# SHADING_RTL_TRACE (ON/OFF: Verilator's SystemC trace file, which the co-simulations of the specular
# devices record their RTL waveform with, builds against the chosen SystemC) and
# SHADING_RTL_TRACE_SKIP_REASON, SHADING_RTL_DIR (rtl/ in the source tree), SHADING_RTL_GENERATED (the
# generated Verilog in the build tree: shading_formats.vh, ua22802_a_rom.v, rom_sweep/, sqmul_word/) and
# SHADING_RTL_INCLUDE_DIRS (every folder the specular devices' modules are found in),
# SHADING_RTL_SQUARED_DIRS (the same for the squared-quadratic device and its comparison designs),
# and defines shading_verilate_rtl, shading_verilate_specular and shading_verilate_squared (below).
# A project that pulls the model in with add_subdirectory() gets the SystemC modules alone.
set(SHADING_RTL_DIR ${PROJECT_SOURCE_DIR}/rtl)
set(SHADING_RTL_GENERATED ${PROJECT_BINARY_DIR}/generated/rtl)
set(SHADING_RTL_INCLUDE_DIRS ${SHADING_RTL_DIR}/blocks ${SHADING_RTL_DIR}/specular ${SHADING_RTL_DIR}/ua60553
    ${SHADING_RTL_DIR}/ua22802 ${SHADING_RTL_DIR}/tuned ${SHADING_RTL_GENERATED})
# The squared-quadratic device, its series variant and the square-and-multiply baseline.
set(SHADING_RTL_SQUARED_DIRS ${SHADING_RTL_DIR}/blocks ${SHADING_RTL_DIR}/squared ${SHADING_RTL_DIR}/sqmul
    ${SHADING_RTL_GENERATED})
set(SHADING_RTL OFF)
set(SHADING_RTL_TRACE OFF)
if(NOT SHADING_TOP_LEVEL)
  return()
endif()
# scripts/test.sh --sanitize turns this off: Verilator's generated models are not ours (compiled
# uninstrumented even there) and the normal run co-simulates every one, so the instrumented build
# spends its time on the project's own code; the RTL tests are then registered as skipped.
option(SHADING_VERILATE "Verilate the RTL twin and co-simulate it with the model (needs verilator)" ON)
if(NOT SHADING_VERILATE)
  set(SHADING_RTL_SKIP_REASON "the RTL is not verilated in this build (SHADING_VERILATE=OFF: scripts/test.sh --sanitize leaves the co-simulation to the normal run)")
  message(STATUS "${SHADING_RTL_SKIP_REASON}")
  return()
endif()
find_package(verilator QUIET HINTS $ENV{VERILATOR_ROOT})
if(NOT verilator_FOUND)
  set(SHADING_RTL_SKIP_REASON "verilator not found (Debian: apt-get install verilator, or scripts/setup.sh)")
  message(STATUS "${SHADING_RTL_SKIP_REASON}: the RTL tests are registered as skipped")
  return()
endif()
# Verilator's verilate() links the SystemC it finds itself (SYSTEMC_* variables, /usr/include, then
# the SystemCLanguage package) unless Verilator::systemc exists: make it the project's choice, so a
# build against another SystemC (SHADING_SYSTEMC_PREFIX) never mixes two kernels in one program.
if(NOT TARGET Verilator::systemc)
  add_library(Verilator::systemc INTERFACE IMPORTED)
  set_target_properties(Verilator::systemc PROPERTIES INTERFACE_LINK_LIBRARIES ${SHADING_SYSTEMC_TARGET})
endif()
set(SHADING_RTL ON)
message(STATUS "verilator ${verilator_VERSION}: RTL twin co-simulated with the SystemC model")

# Verilator's SystemC trace file (verilated_vcd_sc.h) registers with sc_simcontext::add_trace_file,
# which SystemC 3.0 removed (Verilator 5.006, Debian 12's, predates 3.0). Compiled once here against
# the chosen SystemC; when it does not build, the co-simulations that record the RTL's waveform are
# registered as skipped with this reason, and everything else of the RTL still runs.
set(_trace_dir ${PROJECT_BINARY_DIR}/CMakeFiles/verilator_sc_trace_check)
file(WRITE ${_trace_dir}/check.cpp "#include <verilated_vcd_sc.h>\nvoid shading_check() { VerilatedVcdSc t; }\n")
# Compiled only (a static library: nothing to link, no sc_main), and again at every configure, so a
# change of SystemC or Verilator is seen.
unset(_shading_rtl_trace_ok CACHE)
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)
try_compile(_shading_rtl_trace_ok ${_trace_dir}/build SOURCES ${_trace_dir}/check.cpp
            CMAKE_FLAGS "-DINCLUDE_DIRECTORIES=${VERILATOR_ROOT}/include;${VERILATOR_ROOT}/include/vltstd"
            LINK_LIBRARIES ${SHADING_SYSTEMC_TARGET}
            CXX_STANDARD 17 CXX_STANDARD_REQUIRED ON
            OUTPUT_VARIABLE _trace_log)
unset(CMAKE_TRY_COMPILE_TARGET_TYPE)
set(SHADING_RTL_TRACE ${_shading_rtl_trace_ok})
unset(_shading_rtl_trace_ok CACHE)
if(NOT SHADING_RTL_TRACE)
  string(CONCAT SHADING_RTL_TRACE_SKIP_REASON "verilator ${verilator_VERSION}'s SystemC trace file (verilated_vcd_sc.h) "
                "does not build against SystemC ${SHADING_SYSTEMC_VERSION} (it calls add_trace_file, which "
                "SystemC 3.0 removed)")
  message(STATUS "${SHADING_RTL_TRACE_SKIP_REASON}: the specular devices' co-simulations are registered as skipped")
endif()
find_package(Threads REQUIRED)

# Verilator's runtime, compiled once: verilate() adds verilated.cpp, verilated_threads.cpp and (with
# TRACE) verilated_vcd_c.cpp to every program that verilates a model (test_rtl, test_rtl_interp,
# perf_models), 15-18 CPU seconds at -O3 each time; the shading_verilate_* functions take them out
# of the program again and link this library. These sources read VM_TRACE only to define WAVES,
# which nothing reads, so one object serves the models without tracing (test_rtl_interp) too. -O3
# like the rest of the build (perf_models' RTL row).
set(SHADING_VERILATED_RUNTIME ${VERILATOR_ROOT}/include/verilated.cpp ${VERILATOR_ROOT}/include/verilated_threads.cpp
    ${VERILATOR_ROOT}/include/verilated_vcd_c.cpp)
add_library(shading_verilated STATIC ${SHADING_VERILATED_RUNTIME})
target_include_directories(shading_verilated PUBLIC ${VERILATOR_ROOT}/include ${VERILATOR_ROOT}/include/vltstd)
target_compile_definitions(shading_verilated PRIVATE VM_COVERAGE=0 VM_SC=1 VM_TRACE=1 VM_TRACE_VCD=1 VM_TRACE_FST=0)
target_compile_features(shading_verilated PRIVATE cxx_std_11)
target_link_libraries(shading_verilated PUBLIC Verilator::systemc Threads::Threads)
target_compile_options(shading_verilated PRIVATE -Wno-unused-parameter)
set_target_properties(shading_verilated PROPERTIES SHADING_PCH_SKIP ON)  # Verilator's sources, its own way
if(SHADING_SANITIZE)  # not ours: uninstrumented, as shading_verilate_rtl says
  target_compile_options(shading_verilated PRIVATE -fno-sanitize=all -g0)
endif()

# SHADING_RTL_OPT_FLAGS: the optimisation of the verilated models' C++ in a Release build. Verilator
# writes megabytes of C++ per model (the pipeline's fd_any: 6.9 MB), which g++ compiles in 39 CPU s at
# -O3, 23 at -O1, 12 at -O0. The co-simulations only check; -O0 made the longest one (rtl.frame.head512)
# run 3 times as long, so -O1. The perf_models row keeps -O3 (SPEED below).
set(SHADING_RTL_OPT_FLAGS "-O1" CACHE STRING
    "Optimisation flags of the verilated models' C++ in a Release build (perf_models' row keeps -O3)")

# shading_verilated_finish(<target> <prefix> [SPEED] [OPT <flags>] [ALONE]), after verilate() of model
# <prefix> into <target>:
# - the runtime sources verilate() added replaced by shading_verilated. A runtime file the library
#   lacks (another Verilator) stops the configure.
# - the model's generated files compiled through one translation unit (what Verilator's own makefile
#   does with its __ALL.cpp): each small file spends most of its time reading SystemC's and
#   Verilator's headers (Vrtl_squared_saturate's 10 files: 38.8 CPU s one by one, 5.3 s as one).
#   The models of one target at one level share that unit, <target>.dir/rtl_models<level>__unity.cpp,
#   for the same reason: the squared-quadratic and square-and-multiply devices' eight models took
#   29.6 CPU s as eight units and 6.2 s as one. ALONE: a unit of its own, <prefix>__unity.cpp (a
#   large model, the pipeline's 2-7 MB of C++, whose headers are a small share and which then
#   compiles beside the others).
# - that unit compiled at SHADING_RTL_OPT_FLAGS (below) in a Release build, or at -O3 with SPEED (the
#   perf_models row, whose rate docs/speed.md quotes), or at OPT's flags.
function(shading_verilated_finish target prefix)
  cmake_parse_arguments(ARG "SPEED;ALONE" "" "OPT" ${ARGN})
  get_target_property(_sources ${target} SOURCES)
  set(_kept)
  set(_model)
  foreach(_s IN LISTS _sources)
    if(_s MATCHES "/include/verilated[^/]*\\.cpp$")
      if(NOT _s IN_LIST SHADING_VERILATED_RUNTIME)
        message(FATAL_ERROR "verilate() added ${_s} to ${target}: add it to SHADING_VERILATED_RUNTIME")
      endif()
      continue()
    endif()
    if(_s MATCHES "/${prefix}\\.dir/[^/]+\\.cpp$" AND NOT _s MATCHES "__unity\\.cpp$")
      list(APPEND _model ${_s})
    endif()
    list(APPEND _kept ${_s})
  endforeach()
  if(NOT _model)
    message(FATAL_ERROR "verilate() added no C++ file of ${prefix} to ${target}")
  endif()
  if(ARG_SPEED)
    set(_opt -O3)
  elseif(ARG_OPT)
    separate_arguments(_opt UNIX_COMMAND "${ARG_OPT}")
  else()
    separate_arguments(_opt UNIX_COMMAND "${SHADING_RTL_OPT_FLAGS}")
  endif()
  list(GET _model 0 _first)
  get_filename_component(_dir ${_first} DIRECTORY)
  # By names relative to the unit (which sits beside or above the model's folder): the same text in
  # every build tree, so ccache can share it.
  set(_includes)
  foreach(_s IN LISTS _model)
    get_filename_component(_name ${_s} NAME)
    list(APPEND _includes "${prefix}.dir/${_name}")
  endforeach()
  if(ARG_ALONE)
    set(_unity ${_dir}/${prefix}__unity.cpp)
    set(_content "// Generated by cmake/verilator.cmake: the files Verilator wrote for ${prefix}, one unit.\n")
    foreach(_i IN LISTS _includes)
      string(REGEX REPLACE "^[^/]+/" "" _i "${_i}")
      string(APPEND _content "#include \"${_i}\"\n")
    endforeach()
    set(_depends ${_model})
    file(GENERATE OUTPUT ${_unity} CONTENT "${_content}")
  else()
    # Each model's .cpp defines a static trace_init() (Verilator 5): renamed per model, so that
    # several models' files can share the unit. Any other name they shared would stop the build.
    get_filename_component(_group_dir ${_dir} DIRECTORY)
    string(MAKE_C_IDENTIFIER "${_opt}" _level)
    set(_unity ${_group_dir}/rtl_models${_level}__unity.cpp)
    get_property(_content TARGET ${target} PROPERTY SHADING_RTL_UNIT${_level})
    get_property(_depends TARGET ${target} PROPERTY SHADING_RTL_UNIT_DEPENDS${_level})
    if(NOT _content)
      set(_content "// Generated by cmake/verilator.cmake: the files Verilator wrote for the models of ${target}, one unit.\n")
      # Written once, at generate time, from the property as the last model left it: a re-configure
      # leaves an unchanged unit as it was, so nothing is rebuilt.
      file(GENERATE OUTPUT ${_unity} CONTENT "$<TARGET_PROPERTY:${target},SHADING_RTL_UNIT${_level}>")
    endif()
    string(APPEND _content "#define trace_init ${prefix}__trace_init\n")
    foreach(_i IN LISTS _includes)
      string(APPEND _content "#include \"${_i}\"\n")
    endforeach()
    string(APPEND _content "#undef trace_init\n")
    list(APPEND _depends ${_model})
    set_property(TARGET ${target} PROPERTY SHADING_RTL_UNIT${_level} "${_content}")
    set_property(TARGET ${target} PROPERTY SHADING_RTL_UNIT_DEPENDS${_level} "${_depends}")
  endif()
  # Still sources of the target, so Verilator's command that writes them runs; compiled only through
  # the unit, which is rebuilt when one of them changes.
  set_source_files_properties(${_model} PROPERTIES HEADER_FILE_ONLY ON)
  set_source_files_properties(${_unity} PROPERTIES GENERATED ON OBJECT_DEPENDS "${_depends}")
  if(NOT _unity IN_LIST _kept)
    foreach(_o IN LISTS _opt)
      set_property(SOURCE ${_unity} APPEND PROPERTY COMPILE_OPTIONS $<$<CONFIG:Release>:${_o}>)
    endforeach()
    list(APPEND _kept ${_unity})
  endif()
  set_property(TARGET ${target} PROPERTY SOURCES ${_kept})
  target_link_libraries(${target} PRIVATE shading_verilated)
endfunction()

# The generated Verilog must exist when CMake configures: verilate() runs Verilator then, to learn the
# C++ files it writes. So src/tools/gen_rtl.cpp is compiled and run here, and any change to it or to
# the format tables re-runs CMake (the build then re-verilates, as the Verilog it reads changed).
# It reads the floor's format tables (the squaring stage's select codes among them) and ref::a_exact,
# whose one definition is the floor's a(n) (arith/ua22802_arith.cpp); never a module.
set(_gen_sources ${PROJECT_SOURCE_DIR}/src/tools/gen_rtl.cpp ${PROJECT_SOURCE_DIR}/src/reference/brdf_reference.cpp
                 ${PROJECT_SOURCE_DIR}/src/floor/arith/ua22802_arith.cpp ${PROJECT_SOURCE_DIR}/src/floor/arith/specular_arith.cpp)
set(_gen_dir ${PROJECT_BINARY_DIR}/CMakeFiles/gen_rtl_configure)
try_compile(_gen_ok ${_gen_dir} SOURCES ${_gen_sources}
            CMAKE_FLAGS "-DINCLUDE_DIRECTORIES=${PROJECT_SOURCE_DIR}/src;${PROJECT_SOURCE_DIR}/src/floor"
            CXX_STANDARD 17 CXX_STANDARD_REQUIRED ON
            OUTPUT_VARIABLE _gen_log COPY_FILE ${_gen_dir}/gen_rtl)
if(NOT _gen_ok)
  message(FATAL_ERROR "src/tools/gen_rtl.cpp did not compile:\n${_gen_log}")
endif()
file(GLOB _format_headers ${PROJECT_SOURCE_DIR}/src/floor/formats/*.h)
set_property(DIRECTORY ${PROJECT_SOURCE_DIR} APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${_gen_sources}
             ${PROJECT_SOURCE_DIR}/src/reference/brdf_reference.h ${PROJECT_SOURCE_DIR}/src/floor/arith/ua22802_arith.h
             ${PROJECT_SOURCE_DIR}/src/floor/arith/specular_arith.h ${_format_headers})

# _shading_gen_rtl(<file in SHADING_RTL_GENERATED> <gen_rtl mode> <arguments after the output>):
# runs the generator, then copies only a changed file, so a re-configure does not re-verilate.
function(_shading_gen_rtl dest mode)
  set(_tmp ${_gen_dir}/out.tmp)
  execute_process(COMMAND ${_gen_dir}/gen_rtl ${mode} ${_tmp} ${ARGN} RESULT_VARIABLE _rc)
  if(_rc)
    message(FATAL_ERROR "gen_rtl ${mode} ${dest} ${ARGN} failed (${_rc})")
  endif()
  get_filename_component(_dir ${SHADING_RTL_GENERATED}/${dest} DIRECTORY)
  file(MAKE_DIRECTORY ${_dir})
  file(COPY_FILE ${_tmp} ${SHADING_RTL_GENERATED}/${dest} ONLY_IF_DIFFERENT)
endfunction()
_shading_gen_rtl(shading_formats.vh formats)
_shading_gen_rtl(ua22802_a_rom.v rom)  # the device's ROM: ua22802::a_fmt
# The ROM at the sizes of the accuracy study's fraction-bit sweep (rom_fraction_sweep.csv, F = 2..10),
# module ua22802_a_rom_f<F> in rom_sweep/, for the synthesis flow.
foreach(_f RANGE 2 10)
  _shading_gen_rtl(rom_sweep/ua22802_a_rom_f${_f}.v rom ${_f} ua22802_a_rom_f${_f})
endforeach()
# The formats with the square-and-multiply designs' P word at the word-length study's sizes
# (studies/accuracy, sqmul_study: Q1.15 .. Q1.20), sqmul_word/p<F>/shading_formats.vh, for the
# synthesis flow (its folder first on the include path).
foreach(_f RANGE 15 20)
  _shading_gen_rtl(sqmul_word/p${_f}/shading_formats.vh formats ${_f})
endforeach()

# The same generator as a build target, for scripts that want other fraction-bit counts.
add_executable(gen_rtl ${PROJECT_SOURCE_DIR}/src/tools/gen_rtl.cpp)
target_link_libraries(gen_rtl PRIVATE shading_golden)

# shading_verilate_rtl(<target> <prefix> TOP <module> SOURCE <file.v> DIRS <dirs...> [ARGS <verilator args...>]
#                      [SPEED] [OPT <flags>] [ALONE])
#   Verilates one RTL top into <target> as the SystemC module <prefix> (header <prefix>.h): pins of
#   2..64 wires as sc_uint<W> (--pins-sc-uint), the SystemC model's own pin types, so both bind to
#   the same signals; 1-wire pins as bool. Lint warnings (-Wall) fail the build; tracing is compiled in.
#   SPEED: the model's C++ at -O3 (a program whose rate a page quotes) instead of SHADING_RTL_OPT_FLAGS;
#   OPT "<flags>": at those flags instead (a Release build's, one string as SHADING_RTL_OPT_FLAGS), for a
#   model whose compile outweighs its run; ALONE: a translation unit of its own (shading_verilated_finish).
function(shading_verilate_rtl target prefix)
  cmake_parse_arguments(ARG "SPEED;ALONE" "TOP;SOURCE" "DIRS;ARGS;OPT" ${ARGN})
  # A previous run's list of the files Verilator read (<prefix>_copy.cmake in the build tree): if one
  # of them is gone since (a Verilog header folded into shading_formats.vh), the list is dropped, so
  # verilate() runs Verilator again instead of stopping the configure on the missing file.
  set(_vcopy ${CMAKE_CURRENT_BINARY_DIR}/CMakeFiles/${target}.dir/${prefix}.dir/${prefix}_copy.cmake)
  if(EXISTS ${_vcopy})
    file(STRINGS ${_vcopy} _deps REGEX "^set\\(${prefix}_DEPS ")
    string(REGEX MATCHALL "\"[^\"]+\"" _files "${_deps}")
    foreach(_f IN LISTS _files)
      string(REPLACE "\"" "" _f "${_f}")
      if(NOT EXISTS "${_f}")
        file(REMOVE ${_vcopy})
        break()
      endif()
    endforeach()
  endif()
  verilate(${target} SYSTEMC TRACE
           PREFIX ${prefix}
           TOP_MODULE ${ARG_TOP}
           SOURCES ${ARG_SOURCE}
           INCLUDE_DIRS ${ARG_DIRS}
           VERILATOR_ARGS -Wall --pins-sc-uint ${ARG_ARGS})
  set(_speed)
  if(ARG_SPEED)
    set(_speed SPEED)
  elseif(ARG_OPT)
    set(_speed OPT "${ARG_OPT}")
  endif()
  if(ARG_ALONE)
    list(APPEND _speed ALONE)
  endif()
  shading_verilated_finish(${target} ${prefix} ${_speed})
  target_link_libraries(${target} PRIVATE Threads::Threads)
  # Verilator's own headers and generated code leave parameters unused (verilated_vcd_sc.h).
  target_compile_options(${target} PRIVATE -Wno-unused-parameter)
  # Under the sanitizers only the project's own code is instrumented: Verilator's generated model
  # and its runtime are not ours, so they are compiled without -fsanitize and without debug
  # information, which keeps the sanitizer build short. The harness that drives them
  # (testbenches/rtl) is instrumented like the rest. (Instrumented, Verilator 5.006's VCD buffer
  # trips UBSan's alignment check: verilated_trace_imp.h stores 64-bit values at 4-byte alignment.)
  if(SHADING_SANITIZE)
    get_target_property(_sources ${target} SOURCES)
    foreach(_s IN LISTS _sources)
      if(_s MATCHES "/${prefix}\\.dir/|/rtl_models[^/]*__unity\\.cpp$|/verilated[^/]*\\.cpp$")
        set_property(SOURCE ${_s} APPEND PROPERTY COMPILE_OPTIONS -fno-sanitize=all -g0)
      endif()
    endforeach()
  endif()
endfunction()

# shading_verilate_specular(<target> <prefix> AGEN <0|1|2> SATURATE <0|1> [SPEED])
#   rtl/specular/specular_device.v with that generator (0 UA 60553, 1 UA 22802, 2 tuned) and
#   overflow mode; SPEED as for shading_verilate_rtl.
function(shading_verilate_specular target prefix)
  cmake_parse_arguments(ARG "SPEED" "AGEN;SATURATE" "" ${ARGN})
  set(_speed)
  if(ARG_SPEED)
    set(_speed SPEED)
  endif()
  shading_verilate_rtl(${target} ${prefix} TOP specular_device SOURCE ${SHADING_RTL_DIR}/specular/specular_device.v
                       ${_speed} DIRS ${SHADING_RTL_INCLUDE_DIRS} ARGS -GAGEN=${ARG_AGEN} -GSATURATE=${ARG_SATURATE})
endfunction()

# shading_verilate_squared(<target> <prefix> TOP <squared_device|squared_series_device|sqmul_device|sqmul_r2l_device>
#                          SATURATE <0|1> [WORD <F>])
#   The squared-quadratic device (rtl/squared), its series variant or a square-and-multiply design
#   (rtl/sqmul: the left-to-right baseline, the right-to-left one), in that overflow mode; WORD: a
#   square-and-multiply design at the P word Q1.F (the formats of sqmul_word/p<F>/ found first).
function(shading_verilate_squared target prefix)
  cmake_parse_arguments(ARG "" "TOP;SATURATE;WORD" "" ${ARGN})
  set(_dir squared)
  if(ARG_TOP MATCHES "^sqmul")
    set(_dir sqmul)
  endif()
  set(_dirs ${SHADING_RTL_SQUARED_DIRS})
  if(ARG_WORD)
    set(_dirs ${SHADING_RTL_GENERATED}/sqmul_word/p${ARG_WORD} ${_dirs})
  endif()
  shading_verilate_rtl(${target} ${prefix} TOP ${ARG_TOP} SOURCE ${SHADING_RTL_DIR}/${_dir}/${ARG_TOP}.v
                       DIRS ${_dirs} ARGS -GSATURATE=${ARG_SATURATE})
endfunction()

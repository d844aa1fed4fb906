# Precompiled headers (SHADING_PCH; default ON, but OFF in the sanitizer build): the heavy system
# headers every translation unit parses again (<systemc>, <gtest/gtest.h>: 1-3 CPU s of a unit's
# compile) are compiled once per build into a small donor library, and each program, suite and
# library with the same compile flags reuses it (REUSE_FROM). Release, user+sys CPU s a unit
# without/with: test_interp_line.cpp 15.4/12.6, test_blocks.cpp 5.5/4.3, program_options.cpp
# 18.0/15.7, frame_setup.cpp 1.8/1.2; the three headers cost 21 s to make. Only system headers go
# in, never the project's, so an edit never rebuilds one. The layer check reads the sources' own
# #include lines, which a precompiled header does not change.
#
# g++ takes a precompiled header only when the flags match: it refuses one compiled without a macro
# the consumer defines and the header tests (SC_INCLUDE_DYNAMIC_PROCESSES), and g++ 12 has crashed
# using one compiled at -Og in a unit built at -O3. So each donor carries exactly its consumers'
# flags: one for the GoogleTest suites (SHADING_TEST_OPT_FLAGS in a Release build), one for the
# SystemC programs, one for the plain C++ targets; a target or source file with compile options of
# its own (the Verilated models' -O3 or -fno-sanitize=all, -fPIC of the installed libraries) is left
# without. shading_apply_pch() assigns them once every target exists.
#
# ccache (the scripts' launcher) caches a unit that uses a precompiled header only with the
# sloppiness below (ccache(1), PRECOMPILED HEADERS); the targets that use one get it through their
# launcher, so a ccache run elsewhere keeps its own settings.
# Off by default in the sanitizer build: there the instrumented code generation dominates and a
# unit using the precompiled header took as long or up to 3 CPU s longer (test_blocks.cpp 11.1 s
# without, 13.5 s with; test_interp_fd.cpp 27.9 and 30.9).
if(SHADING_SANITIZE)
  set(_shading_pch_default OFF)
else()
  set(_shading_pch_default ON)
endif()
option(SHADING_PCH "Precompile the system headers (<systemc>, <gtest/gtest.h>, the standard library)"
       ${_shading_pch_default})

set(_shading_pch_std <algorithm> <array> <cmath> <cstdint> <cstdlib> <functional> <iostream> <map>
                     <memory> <sstream> <string> <utility> <vector>)

# _shading_links_modules(<target> <out>): whether <target> links shading_modules (SystemC), directly
# or through the libraries it links.
function(_shading_links_modules target out)
  set(_seen)
  set(_todo ${target})
  set(_found OFF)
  while(_todo)
    list(POP_FRONT _todo _t)
    if(_t IN_LIST _seen OR NOT TARGET ${_t})
      continue()
    endif()
    list(APPEND _seen ${_t})
    if(_t STREQUAL "shading_modules")
      set(_found ON)
      break()
    endif()
    get_target_property(_type ${_t} TYPE)
    set(_libs)
    if(NOT _type STREQUAL "INTERFACE_LIBRARY")
      get_target_property(_libs ${_t} LINK_LIBRARIES)
    endif()
    get_target_property(_ilibs ${_t} INTERFACE_LINK_LIBRARIES)
    foreach(_l IN LISTS _libs _ilibs)
      string(REGEX REPLACE "^\\$<(BUILD_INTERFACE|LINK_ONLY):(.*)>$" "\\2" _l "${_l}")
      if(_l AND NOT _l MATCHES "NOTFOUND$" AND NOT _l MATCHES "^\\$<")
        list(APPEND _todo ${_l})
      endif()
    endforeach()
  endwhile()
  set(${out} ${_found} PARENT_SCOPE)
endfunction()

# _shading_collect_targets(<dir> <out>): the targets defined in <dir> and its subdirectories.
function(_shading_collect_targets dir out)
  get_property(_targets DIRECTORY ${dir} PROPERTY BUILDSYSTEM_TARGETS)
  get_property(_subdirs DIRECTORY ${dir} PROPERTY SUBDIRECTORIES)
  foreach(_d IN LISTS _subdirs)
    _shading_collect_targets(${_d} _sub)
    list(APPEND _targets ${_sub})
  endforeach()
  set(${out} ${_targets} PARENT_SCOPE)
endfunction()

# shading_apply_pch(): after every target is defined (the end of the top CMakeLists.txt).
function(shading_apply_pch)
  if(NOT SHADING_PCH)
    return()
  endif()
  set(_donor_cpp ${PROJECT_BINARY_DIR}/pch/donor.cpp)
  file(CONFIGURE OUTPUT ${_donor_cpp} CONTENT "// The precompiled headers' donors compile this empty unit.\n")
  # The donors: OBJECT libraries of one empty unit with their consumers' flags and macros (SystemC's
  # usage requirements, shading_modules' definitions), linking nothing of the project's, so a
  # consumer waits for the header alone.
  set(_sc_defs $<TARGET_PROPERTY:shading_modules,INTERFACE_COMPILE_DEFINITIONS>)
  add_library(shading_pch_plain OBJECT ${_donor_cpp})
  target_precompile_headers(shading_pch_plain PRIVATE ${_shading_pch_std})
  add_library(shading_pch_systemc OBJECT ${_donor_cpp})
  target_link_libraries(shading_pch_systemc PRIVATE ${SHADING_SYSTEMC_TARGET})
  target_compile_definitions(shading_pch_systemc PRIVATE ${_sc_defs})
  target_precompile_headers(shading_pch_systemc PRIVATE <systemc> ${_shading_pch_std})
  set(_donors shading_pch_plain shading_pch_systemc)
  if(TARGET GTest::gtest)
    add_library(shading_pch_gtest OBJECT ${_donor_cpp})
    target_link_libraries(shading_pch_gtest PRIVATE ${SHADING_SYSTEMC_TARGET} GTest::gtest)
    target_compile_definitions(shading_pch_gtest PRIVATE ${_sc_defs})
    target_compile_options(shading_pch_gtest PRIVATE ${SHADING_GTEST_OPT})
    target_precompile_headers(shading_pch_gtest PRIVATE <systemc> <gtest/gtest.h> ${_shading_pch_std})
    list(APPEND _donors shading_pch_gtest)
  endif()
  set(_launcher)
  foreach(_l IN LISTS CMAKE_CXX_COMPILER_LAUNCHER)
    get_filename_component(_name "${_l}" NAME)
    if(_name STREQUAL "ccache")
      set(_launcher env CCACHE_SLOPPINESS=pch_defines,time_macros,include_file_mtime,include_file_ctime
                    ${CMAKE_CXX_COMPILER_LAUNCHER})
    endif()
  endforeach()
  if(_launcher)
    set_target_properties(${_donors} PROPERTIES CXX_COMPILER_LAUNCHER "${_launcher}")
  endif()

  _shading_collect_targets(${PROJECT_SOURCE_DIR} _targets)
  foreach(_t IN LISTS _targets)
    get_target_property(_type ${_t} TYPE)
    if(_t IN_LIST _donors OR NOT _type MATCHES "^(EXECUTABLE|STATIC_LIBRARY|OBJECT_LIBRARY)$")
      continue()
    endif()
    get_target_property(_pic ${_t} POSITION_INDEPENDENT_CODE)
    get_target_property(_skip ${_t} SHADING_PCH_SKIP)
    get_target_property(_opts ${_t} COMPILE_OPTIONS)
    get_target_property(_kind ${_t} SHADING_PCH_KIND)
    if(_pic OR _skip)
      continue()
    endif()
    # Warning switches do not change the code; any other option of the target's own does.
    if(_opts)
      list(REMOVE_ITEM _opts ${SHADING_GTEST_OPT})
      list(FILTER _opts EXCLUDE REGEX "^-W")
      if(_opts)
        continue()
      endif()
    endif()
    if(_kind STREQUAL "gtest")
      set(_donor shading_pch_gtest)
    else()
      _shading_links_modules(${_t} _sc)
      if(_sc)
        set(_donor shading_pch_systemc)
      else()
        set(_donor shading_pch_plain)
      endif()
    endif()
    if(NOT TARGET ${_donor})
      continue()
    endif()
    target_precompile_headers(${_t} REUSE_FROM ${_donor})
    if(_launcher)
      set_target_properties(${_t} PROPERTIES CXX_COMPILER_LAUNCHER "${_launcher}")
    endif()
    # A source with options of its own (the Verilated model's unit at -O3, or uninstrumented in
    # the sanitizer build) is compiled without the precompiled header.
    get_target_property(_sources ${_t} SOURCES)
    foreach(_s IN LISTS _sources)
      get_property(_sopts SOURCE ${_s} TARGET_DIRECTORY ${_t} PROPERTY COMPILE_OPTIONS)
      get_property(_sflags SOURCE ${_s} TARGET_DIRECTORY ${_t} PROPERTY COMPILE_FLAGS)
      get_property(_sdefs SOURCE ${_s} TARGET_DIRECTORY ${_t} PROPERTY COMPILE_DEFINITIONS)
      if(_sopts OR _sflags OR _sdefs)
        set_property(SOURCE ${_s} TARGET_DIRECTORY ${_t} PROPERTY SKIP_PRECOMPILE_HEADERS ON)
      endif()
    endforeach()
  endforeach()
endfunction()

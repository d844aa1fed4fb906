# The layers' include rules (docs/layers.md), checked over a source tree:
#   modules/**          may include modules/, the floor (formats/, arith/), SystemC and the standard
#                       library, and the generated ROM content (ua22802_a_rom.h); never a golden
#                       model, a reference, the scene or the golden pipeline (src/pipeline)
#   src/floor/**        the floor only (formats/, arith/) and the standard library: no SystemC, no GLM
#   src/reference/**    the floor and the references (never a golden model: it is what one is
#                       checked against)
#   src/golden/**       the floor, the references and the golden models
# An include name says its layer by its first folder: formats/ and arith/ are the floor's (include
# root src/floor), golden/, reference/, scene/ are src/'s, pipeline/ is the module folder
# modules/pipeline unless the name is a src/pipeline header and no modules/pipeline one. A quoted
# name is first looked up beside the including file, as the compiler does.
#
# Two uses:
#   include(cmake/layers.cmake) from CMakeLists.txt: checks the source tree when CMake configures
#     (a violation stops the configure), and defines the target shading_layers (re-checks at build
#     time when any checked file changes) and shading_add_layers_tests() (ctest layers.*);
#   cmake -DSHADING_LAYERS_ROOT=<tree> -P cmake/layers.cmake: checks <tree>; exits non-zero naming
#     every file and include that breaks a rule (ctest layers.check, and the self-test's trees).
# Plain file(STRINGS) over about two hundred headers: well under a second.

if(CMAKE_SCRIPT_MODE_FILE)
  cmake_minimum_required(VERSION 3.18)  # the project's policies (IN_LIST) in script mode too
endif()
set(SHADING_LAYERS_SCRIPT ${CMAKE_CURRENT_LIST_FILE})

# The layer an include names, from the including file's layer-relative folder `dir` (absolute), the
# include's name and its delimiter (quote or angle). Sets out to floor, modules, reference, golden,
# scene, src_pipeline, systemc, glm, generated, unknown (quoted, found nowhere) or system.
function(_shading_include_layer root dir name delim out)
  set(layer system)
  set(first "")
  set(rest "")
  if(name MATCHES "^([^/]+)/(.+)$")
    set(first "${CMAKE_MATCH_1}")
    set(rest "${CMAKE_MATCH_2}")
  endif()
  if(delim STREQUAL "\"" AND EXISTS "${dir}/${name}" AND NOT IS_DIRECTORY "${dir}/${name}")
    # Beside the including file: the same layer as the file's own folder.
    get_filename_component(resolved "${dir}/${name}" ABSOLUTE)
    file(RELATIVE_PATH rel "${root}" "${resolved}")
    _shading_file_layer("${rel}" layer)
    if(layer STREQUAL "")
      set(layer unknown)
    endif()
  elseif(first STREQUAL "formats" OR first STREQUAL "arith")
    set(layer floor)
  elseif(first STREQUAL "golden" OR first STREQUAL "reference" OR first STREQUAL "scene")
    set(layer ${first})
  elseif(first STREQUAL "pipeline" AND rest AND EXISTS "${root}/src/pipeline/${rest}"
         AND NOT EXISTS "${root}/modules/pipeline/${rest}")
    set(layer src_pipeline)
  elseif(EXISTS "${root}/modules/${name}")
    set(layer modules)
  elseif(name MATCHES "^(systemc|systemc\\.h|tlm|tlm\\.h|sysc/|tlm_core/|tlm_utils/)")
    set(layer systemc)
  elseif(name MATCHES "^glm/")
    set(layer glm)
  elseif(name STREQUAL "ua22802_a_rom.h")
    set(layer generated)  # the UA 22802 ROM content, written into the build tree by gen_a_rom
  elseif(delim STREQUAL "\"")
    set(layer unknown)
  endif()
  set(${out} ${layer} PARENT_SCOPE)
endfunction()

# The layer of a file by its path relative to the root ("" for a file outside the checked layers).
function(_shading_file_layer rel out)
  set(layer "")
  if(rel MATCHES "^modules/")
    set(layer modules)
  elseif(rel MATCHES "^src/floor/")
    set(layer floor)
  elseif(rel MATCHES "^src/reference/")
    set(layer reference)
  elseif(rel MATCHES "^src/golden/")
    set(layer golden)
  elseif(rel MATCHES "^src/scene/")
    set(layer scene)
  elseif(rel MATCHES "^src/pipeline/")
    set(layer src_pipeline)
  endif()
  set(${out} ${layer} PARENT_SCOPE)
endfunction()

# The files the rules cover, absolute paths.
function(_shading_layer_files root out)
  file(GLOB_RECURSE files LIST_DIRECTORIES false
       "${root}/modules/*.h" "${root}/modules/*.hpp" "${root}/modules/*.cpp"
       "${root}/src/floor/*.h" "${root}/src/floor/*.cpp"
       "${root}/src/reference/*.h" "${root}/src/reference/*.cpp"
       "${root}/src/golden/*.h" "${root}/src/golden/*.cpp")
  list(SORT files)
  set(${out} ${files} PARENT_SCOPE)
endfunction()

# Checks every file under root; message(FATAL_ERROR) listing each violation.
function(shading_check_layers root)
  get_filename_component(root "${root}" ABSOLUTE)
  if(NOT IS_DIRECTORY "${root}/modules" OR NOT IS_DIRECTORY "${root}/src/floor")
    message(FATAL_ERROR "layers: ${root} has no modules/ or src/floor/: not a source tree")
  endif()
  # What each layer may include, besides the standard library ("system").
  set(allowed_modules modules floor systemc generated system)
  set(allowed_floor floor system)
  set(allowed_reference floor reference system)
  set(allowed_golden floor reference golden system)
  set(what_modules "a module may include modules/, the floor (formats/, arith/) and SystemC only")
  set(what_floor "the floor may include the floor (formats/, arith/) and the standard library only")
  set(what_reference "a reference may include the floor and the references only, never a golden model")
  set(what_golden "a golden model may include the floor, the references and golden models only")
  _shading_layer_files("${root}" files)
  set(problems "")
  set(count 0)
  foreach(f IN LISTS files)
    file(RELATIVE_PATH rel "${root}" "${f}")
    _shading_file_layer("${rel}" from)
    get_filename_component(dir "${f}" DIRECTORY)
    file(STRINGS "${f}" lines REGEX "^[ \t]*#[ \t]*include[ \t]*[\"<]")
    foreach(line IN LISTS lines)
      if(NOT line MATCHES "^[ \t]*#[ \t]*include[ \t]*([\"<])([^\">]+)[\">]")
        continue()
      endif()
      set(delim "${CMAKE_MATCH_1}")
      set(name "${CMAKE_MATCH_2}")
      _shading_include_layer("${root}" "${dir}" "${name}" "${delim}" to)
      if(NOT to IN_LIST allowed_${from})
        set(close "\"")
        if(delim STREQUAL "<")
          set(close ">")
        endif()
        string(APPEND problems "\n  ${rel}: #include ${delim}${name}${close} (${to}): ${what_${from}}")
        math(EXPR count "${count} + 1")
      endif()
    endforeach()
  endforeach()
  if(count GREATER 0)
    message(FATAL_ERROR "layers: ${count} include(s) break the layers (docs/layers.md):${problems}")
  endif()
endfunction()

if(CMAKE_SCRIPT_MODE_FILE)
  if(NOT SHADING_LAYERS_ROOT)
    message(FATAL_ERROR "usage: cmake -DSHADING_LAYERS_ROOT=<source tree> -P ${CMAKE_CURRENT_LIST_FILE}")
  endif()
  shading_check_layers("${SHADING_LAYERS_ROOT}")
  return()
endif()

# ---- Included from CMakeLists.txt ----
shading_check_layers("${PROJECT_SOURCE_DIR}")
# At build time too, whenever a checked file (or this script) changes: a bad include added after
# configuring stops the build (shading_floor, which every model links, waits for this target).
_shading_layer_files("${PROJECT_SOURCE_DIR}" _shading_layer_inputs)
file(GLOB_RECURSE _shading_layer_glob CONFIGURE_DEPENDS LIST_DIRECTORIES false
     ${PROJECT_SOURCE_DIR}/modules/* ${PROJECT_SOURCE_DIR}/src/floor/*
     ${PROJECT_SOURCE_DIR}/src/reference/* ${PROJECT_SOURCE_DIR}/src/golden/*)  # re-configure on a new file
add_custom_command(
  OUTPUT ${PROJECT_BINARY_DIR}/layers.stamp
  COMMAND ${CMAKE_COMMAND} -DSHADING_LAYERS_ROOT=${PROJECT_SOURCE_DIR} -P ${SHADING_LAYERS_SCRIPT}
  COMMAND ${CMAKE_COMMAND} -E touch ${PROJECT_BINARY_DIR}/layers.stamp
  DEPENDS ${_shading_layer_inputs} ${SHADING_LAYERS_SCRIPT}
  COMMENT "Checking the layers' includes (cmake/layers.cmake)")
add_custom_target(shading_layers ALL DEPENDS ${PROJECT_BINARY_DIR}/layers.stamp)

# ctest layers.check (this tree) and layers.check_catches_bad_trees (cmake/layers_selftest.cmake:
# trees that break each rule must fail, naming the file and the include; a clean tree must pass).
function(shading_add_layers_tests)
  add_test(NAME layers.check
           COMMAND ${CMAKE_COMMAND} -DSHADING_LAYERS_ROOT=${PROJECT_SOURCE_DIR} -P ${SHADING_LAYERS_SCRIPT})
  add_test(NAME layers.check_catches_bad_trees
           COMMAND ${CMAKE_COMMAND} -DSHADING_LAYERS_SCRIPT=${SHADING_LAYERS_SCRIPT}
                   -DSHADING_LAYERS_WORK=${PROJECT_BINARY_DIR}/layers_selftest
                   -P ${PROJECT_SOURCE_DIR}/cmake/layers_selftest.cmake)
  set_tests_properties(layers.check layers.check_catches_bad_trees PROPERTIES TIMEOUT 60 LABELS layers)
endfunction()

# The layers' include rules (docs/layers.md), checked over a source tree:
#   modules/**          may include modules/, the floor (formats/, arith/), SystemC and the standard
#                       library, and the generated ROM content (ua22802_a_rom.h); never a golden
#                       model, a reference, the scene or the golden pipeline (src/golden_pipeline)
#   src/floor/**        the floor only (formats/, arith/) and the standard library: no SystemC, no GLM
#   src/reference/**    the floor and the references (never a golden model: it is what one is
#                       checked against)
#   src/golden/**       the floor, the references and the golden models
#   src/scene/**        the layers above and GLM; src/golden_pipeline/** those and the scene
#   src/tools/**, testbenches/**, fuzz/**: any layer, named by its prefix, but a study
#   studies/** (and testbenches/study/**, studies still waiting to move there): any layer and the
#                       studies ("studies/..."); the model and the programs never include a study
# An include names its layer by its first folder, and each first folder belongs to one layer only:
# formats/ and arith/ are the floor's (include root src/floor); golden/, reference/, scene/,
# golden_pipeline/ are src/'s; every folder of modules/ (core/, specular/, pipeline/, ...) is the
# modules'; testbenches/ is the testbenches', studies/ the studies' (include root: the project root).
# A name whose first folder is none of these ("common/x.h" for testbenches/common/x.h), or is a path
# ("src/golden/g.h", "modules/core/x.h"), breaks the rule; so does a folder name used under two roots
# (the check's first step). A quoted name is first looked up beside the including file, as the
# compiler does.
#
# Two uses:
#   include(cmake/layers.cmake) from CMakeLists.txt: checks the source tree when CMake configures
#     (a violation stops the configure), and defines the target shading_layers (re-checks at build
#     time when any checked file changes) and shading_add_layers_tests() (ctest layers.*);
#   cmake -DSHADING_LAYERS_ROOT=<tree> -P cmake/layers.cmake: checks <tree>; exits non-zero naming
#     every file and include that breaks a rule (ctest layers.check, and the self-test's trees).
# Plain file(STRINGS) over about three hundred files: about a second.

if(CMAKE_SCRIPT_MODE_FILE)
  cmake_minimum_required(VERSION 3.18)  # the project's policies (IN_LIST) in script mode too
endif()
set(SHADING_LAYERS_SCRIPT ${CMAKE_CURRENT_LIST_FILE})

# The layer an include names, from the including file's folder `dir` (absolute), the include's name
# and its delimiter (quote or angle). Sets out to floor, modules, reference, golden, scene,
# src_pipeline, tools, testbenches, studies, systemc, glm, generated, path (a path from the project root, not
# a layer's prefix), unknown (quoted, found nowhere) or system.
function(_shading_include_layer root dir name delim out)
  set(layer system)
  set(first "")
  if(name MATCHES "^([^/]+)/.+$")
    set(first "${CMAKE_MATCH_1}")
  endif()
  if(delim STREQUAL "\"" AND EXISTS "${dir}/${name}" AND NOT IS_DIRECTORY "${dir}/${name}")
    # Beside the including file: the same layer as the file's own folder.
    get_filename_component(resolved "${dir}/${name}" ABSOLUTE)
    file(RELATIVE_PATH rel "${root}" "${resolved}")
    _shading_file_layer("${rel}" layer)
    if(layer STREQUAL "")
      set(layer unknown)
    endif()
  elseif((first STREQUAL "formats" OR first STREQUAL "arith") AND EXISTS "${root}/src/floor/${name}")
    set(layer floor)
  elseif((first STREQUAL "golden" OR first STREQUAL "reference" OR first STREQUAL "scene")
         AND EXISTS "${root}/src/${name}")
    set(layer ${first})
  elseif(first STREQUAL "golden_pipeline" AND EXISTS "${root}/src/${name}")
    set(layer src_pipeline)
  elseif(first STREQUAL "testbenches" AND EXISTS "${root}/${name}")
    set(layer testbenches)
  elseif(first STREQUAL "studies" AND EXISTS "${root}/${name}")
    set(layer studies)
  elseif(first STREQUAL "src" OR first STREQUAL "modules" OR first STREQUAL "fuzz")
    set(layer path)
  elseif(first AND EXISTS "${root}/modules/${name}")
    set(layer modules)
  elseif(name MATCHES "^(systemc|systemc\\.h|tlm|tlm\\.h|sysc/|tlm_core/|tlm_utils/)")
    set(layer systemc)
  elseif(name MATCHES "^glm/")
    set(layer glm)
  elseif(name STREQUAL "ua22802_a_rom.h" OR name MATCHES "^(V[A-Za-z0-9_]+|verilated[a-z_]*)\\.h$")
    # The UA 22802 ROM content (gen_a_rom) and Verilator's models and runtime, in the build tree.
    set(layer generated)
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
  elseif(rel MATCHES "^src/golden_pipeline/")
    set(layer src_pipeline)
  elseif(rel MATCHES "^src/tools/")
    set(layer tools)
  elseif(rel MATCHES "^(studies|testbenches/study)/")
    set(layer studies)
  elseif(rel MATCHES "^(testbenches|fuzz)/")
    set(layer testbenches)
  endif()
  set(${out} ${layer} PARENT_SCOPE)
endfunction()

# The files the rules cover, absolute paths.
function(_shading_layer_files root out)
  set(globs "")
  foreach(d modules src testbenches fuzz studies)
    list(APPEND globs "${root}/${d}/*.h" "${root}/${d}/*.hpp" "${root}/${d}/*.cpp")
  endforeach()
  file(GLOB_RECURSE files LIST_DIRECTORIES false ${globs})
  list(SORT files)
  set(${out} ${files} PARENT_SCOPE)
endfunction()

# Each first folder of an include belongs to one layer: the folders of src/floor, src and modules,
# and the names the project root lends (testbenches, src, modules, fuzz), must all differ. Appends
# each clash to problems_var and counts it.
function(_shading_check_prefixes root problems_var count_var)
  set(problems "${${problems_var}}")
  set(count ${${count_var}})
  set(seen testbenches src modules fuzz studies)
  foreach(e IN LISTS seen)
    set(where_${e} "${e}/")
  endforeach()
  foreach(r src/floor src modules)
    file(GLOB entries LIST_DIRECTORIES true RELATIVE "${root}/${r}" "${root}/${r}/*")
    list(SORT entries)
    foreach(e IN LISTS entries)
      if(NOT IS_DIRECTORY "${root}/${r}/${e}" OR (r STREQUAL "src" AND e STREQUAL "floor"))
        continue()
      endif()
      if(e IN_LIST seen)
        string(APPEND problems "\n  ${where_${e}} and ${r}/${e}/: one folder name under two include "
               "roots: an include \"${e}/...\" would not say its layer")
        math(EXPR count "${count} + 1")
      else()
        list(APPEND seen "${e}")
        set(where_${e} "${r}/${e}/")
      endif()
    endforeach()
  endforeach()
  set(${problems_var} "${problems}" PARENT_SCOPE)
  set(${count_var} ${count} PARENT_SCOPE)
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
  set(allowed_scene floor reference golden scene glm system)
  set(allowed_src_pipeline floor reference golden scene src_pipeline glm system)
  set(allowed_tools floor reference golden modules systemc generated system)
  set(allowed_testbenches floor reference golden scene src_pipeline modules testbenches systemc glm
      generated system)
  set(allowed_studies ${allowed_testbenches} studies)
  set(what_modules "a module may include modules/, the floor (formats/, arith/) and SystemC only")
  set(what_floor "the floor may include the floor (formats/, arith/) and the standard library only")
  set(what_reference "a reference may include the floor and the references only, never a golden model")
  set(what_golden "a golden model may include the floor, the references and golden models only")
  set(what_scene "the scene may include the floor, references, golden models, the scene and GLM only")
  set(what_src_pipeline "the golden pipeline may include the layers of src/ and GLM, never a module")
  set(what_tools "a build tool may include the floor, references, golden models and modules only")
  set(what_testbenches "a testbench names a layer by its prefix (formats/, arith/, reference/, "
      "golden/, scene/, golden_pipeline/, a modules/ folder, testbenches/) or a file beside it")
  string(JOIN "" what_testbenches ${what_testbenches})
  set(what_studies "${what_testbenches}, or a study (studies/)")
  set(what_path "an include names its layer's prefix, not a path from the project root")
  set(what_unknown "the name is found neither beside the file nor under a layer's prefix")
  set(problems "")
  set(count 0)
  _shading_check_prefixes("${root}" problems count)
  _shading_layer_files("${root}" files)
  foreach(f IN LISTS files)
    file(RELATIVE_PATH rel "${root}" "${f}")
    _shading_file_layer("${rel}" from)
    if(from STREQUAL "")
      continue()
    endif()
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
        set(why "${what_${from}}")
        if(to STREQUAL "path" OR to STREQUAL "unknown")
          set(why "${what_${to}}")
        endif()
        string(APPEND problems "\n  ${rel}: #include ${delim}${name}${close} (${to}): ${why}")
        math(EXPR count "${count} + 1")
      endif()
    endforeach()
  endforeach()
  if(count GREATER 0)
    message(FATAL_ERROR "layers: ${count} problem(s) with the layers (docs/layers.md):${problems}")
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
     ${PROJECT_SOURCE_DIR}/modules/*.h ${PROJECT_SOURCE_DIR}/src/*.h ${PROJECT_SOURCE_DIR}/src/*.cpp
     ${PROJECT_SOURCE_DIR}/testbenches/*.h ${PROJECT_SOURCE_DIR}/fuzz/*.h
     ${PROJECT_SOURCE_DIR}/studies/*.h)  # re-configure on a new file
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

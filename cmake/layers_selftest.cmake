# ctest layers.check_catches_bad_trees: the layers check (cmake/layers.cmake) run on small trees
# written here, each breaking one rule, must fail and name the file and the include; the same tree
# with only allowed includes must pass. So the check can fail, and fails for the right reason.
# Usage: cmake -DSHADING_LAYERS_SCRIPT=<cmake/layers.cmake> -DSHADING_LAYERS_WORK=<scratch dir> -P <this>
cmake_minimum_required(VERSION 3.18)
if(NOT SHADING_LAYERS_SCRIPT OR NOT SHADING_LAYERS_WORK)
  message(FATAL_ERROR "usage: cmake -DSHADING_LAYERS_SCRIPT=<layers.cmake> -DSHADING_LAYERS_WORK=<dir> -P ${CMAKE_CURRENT_LIST_FILE}")
endif()

# A tree every layer of which is present and whose includes are all allowed: a module including the
# floor, SystemC, a module beside it and modules/pipeline; the floor including itself; a reference
# the floor; a golden model a reference; the golden pipeline the scene; a testbench a file beside it,
# another folder's testbench header by its prefix, a module and Verilator's generated model; a study
# a file beside it, another folder's study by its prefix, a testbench and a golden model.
function(_write_good_tree root)
  file(REMOVE_RECURSE "${root}")
  file(WRITE "${root}/src/floor/formats/f.h" "#pragma once\n#include <cstdint>\n")
  file(WRITE "${root}/src/floor/arith/a.h" "#pragma once\n#include \"formats/f.h\"\n")
  file(WRITE "${root}/src/floor/arith/a.cpp" "#include \"arith/a.h\"\n")
  file(WRITE "${root}/src/reference/r.h" "#pragma once\n#include \"formats/f.h\"\n")
  file(WRITE "${root}/src/golden/g.h" "#pragma once\n#include \"arith/a.h\"\n#include \"reference/r.h\"\n")
  file(WRITE "${root}/src/scene/s.h" "#pragma once\n#include \"golden/g.h\"\n")
  file(WRITE "${root}/src/golden_pipeline/pipeline.h" "#pragma once\n#include \"scene/s.h\"\n")
  file(WRITE "${root}/modules/pipeline/pipe.h" "#pragma once\n")
  file(WRITE "${root}/modules/m/beside.h" "#pragma once\n")
  file(WRITE "${root}/modules/m/unit.h"
       "#pragma once\n#include <systemc>\n#include \"arith/a.h\"\n#include \"formats/f.h\"\n"
       "#include \"beside.h\"\n#include \"pipeline/pipe.h\"\n#include \"ua22802_a_rom.h\"\n"
       "// #include \"golden/g.h\"  (a comment, not an include)\n")
  file(WRITE "${root}/testbenches/t/helper.h" "#pragma once\n#include \"m/unit.h\"\n")
  file(WRITE "${root}/testbenches/t/near.h" "#pragma once\n")
  file(WRITE "${root}/testbenches/u/test.cpp"
       "#include \"testbenches/t/helper.h\"\n#include \"golden_pipeline/pipeline.h\"\n"
       "#include \"Vrtl_unit.h\"\n#include <glm/glm.hpp>\n")
  file(WRITE "${root}/testbenches/t/test.cpp" "#include \"near.h\"\n#include \"pipeline/pipe.h\"\n")
  file(WRITE "${root}/studies/s/study.h" "#pragma once\n#include \"golden/g.h\"\n")
  file(WRITE "${root}/studies/v/study.cpp"
       "#include \"studies/s/study.h\"\n#include \"beside.h\"\n#include \"testbenches/t/helper.h\"\n"
       "#include \"golden/g.h\"\n#include \"golden_pipeline/pipeline.h\"\n")
  file(WRITE "${root}/studies/v/beside.h" "#pragma once\n#include \"testbenches/t/near.h\"\n")
endfunction()

set(failures "")
set(cases 0)
# _case(<name> <file relative to the tree> <line appended to it> <expected: pass or fail> [<words the
# report must contain>, instead of the file and the include])
function(_case name file line expect)
  math(EXPR n "${cases} + 1")
  set(cases ${n} PARENT_SCOPE)
  set(root "${SHADING_LAYERS_WORK}/${name}")
  _write_good_tree("${root}")
  if(file)
    file(APPEND "${root}/${file}" "${line}\n")
  endif()
  execute_process(COMMAND ${CMAKE_COMMAND} -DSHADING_LAYERS_ROOT=${root} -P ${SHADING_LAYERS_SCRIPT}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  string(REPLACE "\n" " " err_line "${err}")
  if(expect STREQUAL "pass")
    if(NOT rc EQUAL 0)
      set(failures "${failures}\n  ${name}: the check failed on allowed includes: ${err_line}" PARENT_SCOPE)
    endif()
  else()
    # The line's include name, as the report prints it.
    string(REGEX REPLACE "^#include " "" shown "${line}")
    if(rc EQUAL 0)
      set(failures "${failures}\n  ${name}: the check passed ${file} with ${line}" PARENT_SCOPE)
    elseif(ARGC GREATER 4)  # the expected words of the report, given
      string(FIND "${err_line}" "${ARGV4}" at)
      if(at LESS 0)
        set(failures "${failures}\n  ${name}: failed without saying ${ARGV4}: ${err_line}" PARENT_SCOPE)
      endif()
    elseif(NOT err MATCHES "layers: 1 problem" OR NOT err_line MATCHES "${file}: ")
      set(failures "${failures}\n  ${name}: failed, but not naming ${file} alone: ${err_line}" PARENT_SCOPE)
    else()
      string(FIND "${err}" "${shown}" at)
      if(at LESS 0)
        set(failures "${failures}\n  ${name}: failed without naming ${shown}: ${err_line}" PARENT_SCOPE)
      endif()
    endif()
  endif()
  file(REMOVE_RECURSE "${root}")
endfunction()

_case(good "" "" pass)
_case(module_golden modules/m/unit.h "#include \"golden/g.h\"" fail)
_case(module_reference modules/m/unit.h "#include \"reference/r.h\"" fail)
_case(module_scene modules/m/unit.h "#include \"scene/s.h\"" fail)
_case(module_src_pipeline modules/m/unit.h "#include \"golden_pipeline/pipeline.h\"" fail)
_case(module_golden_angle modules/m/unit.h "#include <golden/g.h>" fail)
_case(module_glm modules/m/unit.h "#include <glm/glm.hpp>" fail)
_case(floor_golden src/floor/arith/a.h "#include \"golden/g.h\"" fail)
_case(floor_reference src/floor/arith/a.cpp "#include \"reference/r.h\"" fail)
_case(floor_module src/floor/formats/f.h "#include \"m/unit.h\"" fail)
_case(floor_systemc src/floor/arith/a.h "#include <systemc>" fail)
_case(reference_golden src/reference/r.h "#include \"golden/g.h\"" fail)
_case(golden_scene src/golden/g.h "#include \"scene/s.h\"" fail)
_case(scene_module src/scene/s.h "#include \"m/unit.h\"" fail)
_case(pipeline_module src/golden_pipeline/pipeline.h "#include \"pipeline/pipe.h\"" fail)
_case(testbench_unprefixed testbenches/u/test.cpp "#include \"t/near.h\"" fail)
_case(testbench_path testbenches/u/test.cpp "#include \"src/golden/g.h\"" fail)
_case(testbench_modules_path testbenches/u/test.cpp "#include \"modules/m/unit.h\"" fail)
# Only a study includes a study: a program (a testbench), a fuzz target, a module and the golden
# pipeline must not.
_case(testbench_study testbenches/u/test.cpp "#include \"studies/s/study.h\"" fail)
_case(fuzz_study fuzz/f.cpp "#include \"studies/s/study.h\"" fail)
_case(module_study modules/m/unit.h "#include \"studies/s/study.h\"" fail)
_case(src_pipeline_study src/golden_pipeline/pipeline.h "#include \"studies/s/study.h\"" fail)
# ... and says why.
_case(testbench_study_says testbenches/u/test.cpp "#include \"studies/v/beside.h\"" fail
      "testbenches/u/test.cpp: #include \"studies/v/beside.h\" (studies): only a study may include a study")
# A study names its layers by their prefixes, as a testbench does.
_case(study_unprefixed studies/v/study.cpp "#include \"t/near.h\"" fail)
# A folder name under two include roots: "m/" in src/ and in modules/; "studies/", which the project
# root lends, in src/.
_case(shared_prefix src/m/other.h "#pragma once" fail "src/m/ and modules/m/: one folder name under two")
_case(shared_prefix_studies src/studies/other.h "#pragma once" fail "studies/ and src/studies/: one folder name under two")

if(failures)
  message(FATAL_ERROR "layers self-test:${failures}")
endif()
math(EXPR bad "${cases} - 1")
message(STATUS "layers self-test: 1 clean tree passed, ${bad} trees with one bad include or folder each failed naming it")

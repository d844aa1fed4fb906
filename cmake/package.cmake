# The installed package: `cmake --install <build> --prefix <p>` gives
#   <p>/include/shading/...          the include root, as modules/, src/floor and src/ are in the tree
#                                    ("ua60553/ua60553.h", "squared/squared_device.h", "formats/x.h",
#                                    "arith/x.h", "golden/x.h"): every device, block, monitor and TLM
#                                    wrapper
#   <p>/lib/libshading_floor.a       the floor's shared arithmetic (no SystemC): each device's bit-exact
#                                    function (UA 60553, its tuned generators, UA 22802, the
#                                    squared-quadratic and square-and-multiply devices, the
#                                    interpolation units, the sample stage), which the fast models and
#                                    the TLM wrappers call
#   <p>/lib/libshading_golden.a      the references and the golden models' checks and studies (the
#                                    Horner unit's steps; the rest of each golden model is the floor)
#   <p>/lib/cmake/shading/           find_package(shading CONFIG): shading::modules, ::golden, ...
#   <p>/lib/pkgconfig/shading.pc     pkg-config: Requires: systemc
#   <p>/lib/libshading_scene.a, libshading_pipeline.a, shading-scene.pc   when built (tinyobjloader,
#                                    libpng): the scenes, rasteriser and the interpolation paper's
#                                    golden pipeline, shading::scene and shading::pipeline (export
#                                    set shadingSceneTargets)
#   <p>/share/shading/data/head/     the head scan with its attribution (CC BY 3.0), for the scenes
# Every installed path is relative to <p>, so the tree can be moved. scripts/check_package.sh
# (ctest package.install_and_consume) installs into a temporary prefix and builds a consumer.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(SHADING_INSTALL_INCLUDEDIR ${CMAKE_INSTALL_INCLUDEDIR}/shading)
set(SHADING_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/shading)
# The data root scene::builtin_scene() takes (it reads <root>/data/head/...): share/shading.
set(SHADING_INSTALL_DATAROOT ${CMAKE_INSTALL_DATADIR}/shading)

# Exported names: shading::formats, shading::floor (the formats and the shared arithmetic),
# shading::golden, shading::modules (links shading::floor), shading::ua22802 (the same as
# shading::modules now that the ROM header sits in the include root), shading::tlm. The same
# names as aliases in the build tree, so add_subdirectory() users can write them too.
set_target_properties(shading_formats PROPERTIES EXPORT_NAME formats)
set_target_properties(shading_floor PROPERTIES EXPORT_NAME floor POSITION_INDEPENDENT_CODE ON)
set_target_properties(shading_golden PROPERTIES EXPORT_NAME golden POSITION_INDEPENDENT_CODE ON)
set_target_properties(shading_modules PROPERTIES EXPORT_NAME modules)
set_target_properties(shading_ua22802 PROPERTIES EXPORT_NAME ua22802)
set(SHADING_EXPORTED shading_formats shading_floor shading_golden shading_modules shading_ua22802)
# --- TLM-2.0 wrappers (modules/tlm): exported as shading::tlm once the target exists.
# Its headers are under modules/ and installed below with the rest; its include directories must be
# wrapped in $<BUILD_INTERFACE:...> (or come from shading_modules) for the export to succeed.
if(TARGET shading_tlm)
  set_target_properties(shading_tlm PROPERTIES EXPORT_NAME tlm)
  list(APPEND SHADING_EXPORTED shading_tlm)
endif()
# --- The scene library and the interpolation paper's golden pipeline (src/scene, src/golden_pipeline), when their Debian
# packages were found: shading::scene, shading::pipeline, in their own export set so that a consumer
# without tinyobjloader or libpng still gets the rest. Their public headers include GLM.
set(SHADING_SCENE_EXPORTED)
if(TARGET shading_scene)
  set_target_properties(shading_scene PROPERTIES EXPORT_NAME scene)
  target_link_libraries(shading_scene PUBLIC $<INSTALL_INTERFACE:glm::glm>)
  list(APPEND SHADING_SCENE_EXPORTED shading_scene)
  if(TARGET shading_pipeline)
    set_target_properties(shading_pipeline PROPERTIES EXPORT_NAME pipeline)
    list(APPEND SHADING_SCENE_EXPORTED shading_pipeline)
  endif()
endif()
foreach(t IN LISTS SHADING_EXPORTED SHADING_SCENE_EXPORTED)
  get_target_property(name ${t} EXPORT_NAME)
  if(NOT TARGET shading::${name})
    add_library(shading::${name} ALIAS ${t})
  endif()
endforeach()

# Install rules by default only for the top project (an add_subdirectory() user keeps its own).
option(SHADING_INSTALL "Install the headers, libraries and the shading package" ${SHADING_TOP_LEVEL})
if(NOT SHADING_INSTALL)
  return()
endif()

install(TARGETS ${SHADING_EXPORTED} EXPORT shadingTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${SHADING_INSTALL_INCLUDEDIR})

# Public headers: modules/** (every block, monitor, device and wrapper), the floor (the number
# formats and the shared arithmetic), the golden models and references, scene.h (compiled into
# shading_golden) and the generated ROM, all in one include root. By directory, so a new device's
# headers (modules/squared, modules/sqmul, formats/sqmul_formats.h, ...) come along; scripts/check_package.sh
# checks a list of them.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/modules/ DESTINATION ${SHADING_INSTALL_INCLUDEDIR}
        FILES_MATCHING PATTERN "*.h")
install(DIRECTORY ${PROJECT_SOURCE_DIR}/src/floor/formats ${PROJECT_SOURCE_DIR}/src/floor/arith
        DESTINATION ${SHADING_INSTALL_INCLUDEDIR} FILES_MATCHING PATTERN "*.h")
install(DIRECTORY ${PROJECT_SOURCE_DIR}/src/golden ${PROJECT_SOURCE_DIR}/src/reference
        DESTINATION ${SHADING_INSTALL_INCLUDEDIR} FILES_MATCHING PATTERN "*.h")
install(FILES ${PROJECT_SOURCE_DIR}/src/scene/scene.h DESTINATION ${SHADING_INSTALL_INCLUDEDIR}/scene)
install(FILES ${UA22802_ROM_HEADER} DESTINATION ${SHADING_INSTALL_INCLUDEDIR})

install(EXPORT shadingTargets NAMESPACE shading:: DESTINATION ${SHADING_INSTALL_CMAKEDIR})

if(SHADING_SCENE_EXPORTED)
  install(TARGETS ${SHADING_SCENE_EXPORTED} EXPORT shadingSceneTargets
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
          INCLUDES DESTINATION ${SHADING_INSTALL_INCLUDEDIR})
  install(EXPORT shadingSceneTargets NAMESPACE shading:: DESTINATION ${SHADING_INSTALL_CMAKEDIR})
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/src/scene ${PROJECT_SOURCE_DIR}/src/golden_pipeline
          DESTINATION ${SHADING_INSTALL_INCLUDEDIR} FILES_MATCHING PATTERN "*.h")
  # The head scan goes with its attribution (data/head/README.md: "Infinite, 3D Head Scan" by Lee
  # Perry-Smith, CC BY 3.0): the licence asks for it wherever the file is redistributed.
  install(FILES ${PROJECT_SOURCE_DIR}/data/head/lee_perry_smith_head.obj ${PROJECT_SOURCE_DIR}/data/head/README.md
          DESTINATION ${SHADING_INSTALL_DATAROOT}/data/head)
  set(SHADING_PC_SCENE_LIBS "-lshading_scene")
  if(TARGET shading_pipeline)
    set(SHADING_PC_SCENE_LIBS "-lshading_pipeline -lshading_scene")
  endif()
endif()

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/shadingConfig.cmake.in
  ${PROJECT_BINARY_DIR}/package/shadingConfig.cmake
  INSTALL_DESTINATION ${SHADING_INSTALL_CMAKEDIR}
  PATH_VARS SHADING_INSTALL_DATAROOT)
# 0.x: SameMajorVersion, so a consumer asking for 0.9 accepts 0.9.y and 0.10 but not 1.0.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/package/shadingConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMajorVersion)
install(FILES ${PROJECT_BINARY_DIR}/package/shadingConfig.cmake
              ${PROJECT_BINARY_DIR}/package/shadingConfigVersion.cmake
        DESTINATION ${SHADING_INSTALL_CMAKEDIR})

# shading.pc: prefix relative to the .pc file's own folder (${pcfiledir}), so it stays relocatable.
if(IS_ABSOLUTE "${CMAKE_INSTALL_LIBDIR}")
  message(FATAL_ERROR "shading.pc needs a relative CMAKE_INSTALL_LIBDIR (got ${CMAKE_INSTALL_LIBDIR})")
endif()
file(RELATIVE_PATH SHADING_PC_UP "/p/${CMAKE_INSTALL_LIBDIR}/pkgconfig" "/p")
string(REGEX REPLACE "/$" "" SHADING_PC_UP "${SHADING_PC_UP}")  # "../..", not "../../"
configure_file(${PROJECT_SOURCE_DIR}/cmake/shading.pc.in ${PROJECT_BINARY_DIR}/package/shading.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/package/shading.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
if(SHADING_SCENE_EXPORTED)
  configure_file(${PROJECT_SOURCE_DIR}/cmake/shading-scene.pc.in ${PROJECT_BINARY_DIR}/package/shading-scene.pc @ONLY)
  install(FILES ${PROJECT_BINARY_DIR}/package/shading-scene.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
endif()

# The check CI runs: install this build into a temporary prefix, build and run the consumer project
# (testbenches/example/installed) against it with find_package, and one file with pkg-config.
if(SHADING_BUILD_TESTBENCHES)
  add_test(NAME package.install_and_consume
           COMMAND ${PROJECT_SOURCE_DIR}/scripts/check_package.sh ${PROJECT_BINARY_DIR})
  set_tests_properties(package.install_and_consume PROPERTIES TIMEOUT 600 LABELS package
    ENVIRONMENT "CXX=${CMAKE_CXX_COMPILER};SHADING_CXX_LAUNCHER=${CMAKE_CXX_COMPILER_LAUNCHER};SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1;SHADING_SYSTEMC_PREFIX=${SHADING_SYSTEMC_PREFIX}")
endif()

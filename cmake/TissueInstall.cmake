# TissueInstall: the install rules and the CMake package of tissue, so that a host can
#   find_package(tissue 0.1 REQUIRED)
#   target_link_libraries(app PRIVATE tissue::tissue)   # #include <tissue/tissue.h>
# after `cmake --install <build> --prefix P`, which installs
#   P/include/tissue/...       the public headers (libtissue/include, sim/include, sim/scenario/include,
#                              sim/materials/include), less the three that include glad
#   P/lib/libtissue_*.a        the static modules (position independent, see docs/DECISIONS.md)
#   P/lib/cmake/tissue/        tissueConfig.cmake, tissueConfigVersion.cmake (SameMinorVersion while
#                              0.x), tissueTargets.cmake, tissueGlfwTargets.cmake (the window backend)
#
# Adding a target to the export is one line: put its alias into the tissue_install_targets(...)
# list of the top-level CMakeLists.txt, e.g. `tissue::tissue_c` for
#   add_library(tissue_c SHARED ...)  add_library(tissue::tissue_c ALIAS tissue_c)
# The exported name is the alias's (a host links tissue::tissue_c as the tree does); a plain target
# name works too (tissue_glad -> tissue::glad). What the target must satisfy (the package test,
# tests/package/, checks it):
#   - PUBLIC include directories as $<BUILD_INTERFACE:dir> $<INSTALL_INTERFACE:include>;
#   - its public headers under one of the installed include trees below (a new tree: one
#     install(DIRECTORY) line in tissue_install_package);
#   - third-party dependencies PRIVATE. Header-only ones (TISSUE_HEADER_ONLY_DEPENDENCIES) are then
#     dropped from the installed link interface; a new library one needs its find in
#     cmake/tissueConfig.cmake.in (a static module's PRIVATE libraries are link dependencies of
#     the host: $<LINK_ONLY:...>);
#   - a shared library (tissue_c) links the static modules privately and installs into lib/ with
#     the same line; its RPATH comes from CMAKE_INSTALL_RPATH where a host wants one.
# A target that needs an optional dependency (a window: GLFW) goes into its own export file:
#   tissue_install_targets(EXPORT tissueGlfwTargets tissue::context_glfw)
# which tissueConfig.cmake loads when that dependency is found (or the component is asked for).

include(CMakePackageConfigHelpers)

set(TISSUE_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/tissue)

# Header-only third-party targets the modules use in their sources only: a static library's
# PRIVATE link items are exported as $<LINK_ONLY:item>, which would make a host find these
# packages (and have their headers installed) for nothing, since they add nothing to a link line.
set(TISSUE_HEADER_ONLY_DEPENDENCIES Eigen3::Eigen glm::glm nlohmann_json::nlohmann_json CLI11::CLI11)

# Export sets named so far (tissue_install_package installs each once).
set_property(GLOBAL PROPERTY TISSUE_EXPORT_SETS "")

# _tissue_hide_header_only(<target>): wraps the header-only PRIVATE dependencies of a static
# library in $<BUILD_INTERFACE:...> so that they vanish from the installed link interface; fails
# when one is PUBLIC (a public header would then include third-party headers).
function(_tissue_hide_header_only target)
  get_target_property(type ${target} TYPE)
  get_target_property(libs ${target} INTERFACE_LINK_LIBRARIES)
  if(NOT libs)
    return()
  endif()
  set(out "")
  foreach(lib IN LISTS libs)
    foreach(dep IN LISTS TISSUE_HEADER_ONLY_DEPENDENCIES)
      if(lib STREQUAL "$<LINK_ONLY:${dep}>" AND type STREQUAL "STATIC_LIBRARY")
        set(lib "$<LINK_ONLY:$<BUILD_INTERFACE:${dep}>>")
      elseif(lib STREQUAL dep)
        message(FATAL_ERROR "${target} links ${dep} PUBLIC (or INTERFACE): a host of the installed tissue would "
                            "need its headers. Link it PRIVATE and keep it out of the public headers.")
      endif()
    endforeach()
    list(APPEND out "${lib}")
  endforeach()
  set_property(TARGET ${target} PROPERTY INTERFACE_LINK_LIBRARIES "${out}")
endfunction()

# tissue_install_targets([EXPORT <set>] <alias-or-target>...): installs the targets' libraries
# into lib/ and adds them to export set <set> (default tissueTargets, the file that
# tissueConfig.cmake always loads), exported as tissue::<name> (see the top of this file).
function(tissue_install_targets)
  cmake_parse_arguments(I "" "EXPORT" "" ${ARGN})
  if(NOT I_EXPORT)
    set(I_EXPORT tissueTargets)
  endif()
  set(targets "")
  foreach(item IN LISTS I_UNPARSED_ARGUMENTS)
    if(NOT TARGET ${item})
      message(FATAL_ERROR "tissue_install_targets: no target ${item} (is its module built in this configuration?)")
    endif()
    get_target_property(real ${item} ALIASED_TARGET)
    if(real)
      string(REGEX REPLACE "^tissue::" "" name ${item})
    else()
      set(real ${item})
      string(REGEX REPLACE "^tissue_" "" name ${item})
    endif()
    set_target_properties(${real} PROPERTIES EXPORT_NAME ${name})
    _tissue_hide_header_only(${real})
    list(APPEND targets ${real})
  endforeach()
  install(
    TARGETS ${targets}
    EXPORT ${I_EXPORT}
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
    RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  get_property(sets GLOBAL PROPERTY TISSUE_EXPORT_SETS)
  if(NOT I_EXPORT IN_LIST sets)
    set_property(GLOBAL APPEND PROPERTY TISSUE_EXPORT_SETS ${I_EXPORT})
  endif()
endfunction()

# tissue_install_package(): the headers, the export files and the package config. Call once,
# after every tissue_install_targets.
function(tissue_install_package)
  # Public headers. The glad-including GL headers are internal to the renderer and the contexts:
  # no installed header includes them (the package test checks that the installed tree includes
  # no third-party header it does not ship).
  install(
    DIRECTORY ${PROJECT_SOURCE_DIR}/libtissue/include/tissue
    DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
    FILES_MATCHING
    PATTERN "*.h"
    PATTERN "gl/gl_api.h" EXCLUDE
    PATTERN "gl/objects.h" EXCLUDE
    PATTERN "gl/program.h" EXCLUDE)
  foreach(dir sim/include sim/scenario/include sim/materials/include)
    install(DIRECTORY ${PROJECT_SOURCE_DIR}/${dir}/tissue DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} FILES_MATCHING
            PATTERN "*.h")
  endforeach()

  get_property(sets GLOBAL PROPERTY TISSUE_EXPORT_SETS)
  foreach(set IN LISTS sets)
    install(EXPORT ${set} NAMESPACE tissue:: DESTINATION ${TISSUE_INSTALL_CMAKEDIR} FILE ${set}.cmake)
  endforeach()

  # What tissueConfig.cmake must find for the link (the values of this configuration).
  set(TISSUE_CONFIG_WITH_VTK ${TISSUE_WITH_VTK})
  set(TISSUE_CONFIG_VTK_COMPONENTS ${TISSUE_VTK_VOLUME_COMPONENTS} ${TISSUE_VTK_INSPECT_COMPONENTS})
  list(REMOVE_DUPLICATES TISSUE_CONFIG_VTK_COMPONENTS)
  configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/tissueConfig.cmake.in
                                ${PROJECT_BINARY_DIR}/cmake/tissueConfig.cmake INSTALL_DESTINATION ${TISSUE_INSTALL_CMAKEDIR})
  # 0.x: a minor version may break the API, so 0.1 accepts 0.1.*, not 0.2.
  write_basic_package_version_file(${PROJECT_BINARY_DIR}/cmake/tissueConfigVersion.cmake
                                   VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
  install(FILES ${PROJECT_BINARY_DIR}/cmake/tissueConfig.cmake ${PROJECT_BINARY_DIR}/cmake/tissueConfigVersion.cmake
          DESTINATION ${TISSUE_INSTALL_CMAKEDIR})
endfunction()

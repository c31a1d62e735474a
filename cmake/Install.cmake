# SPDX-License-Identifier: MIT
# Install rules: headers, libzline.a, the CMake package (zlineConfig.cmake,
# zlineConfigVersion.cmake, the exported targets) and pkg-config's zline.pc.
#
#   cmake --install build --prefix /opt/zline
#   find_package(zline 0.1 CONFIG REQUIRED)            -> zline::zline
#   find_package(zline 0.1 CONFIG REQUIRED COMPONENTS host)  -> zline::host too
#   find_package(zline 0.1 CONFIG REQUIRED COMPONENTS panel) -> zline::panel (SPI panel drivers)
#   find_package(zline 0.1 CONFIG REQUIRED COMPONENTS tools) -> zline::obj2c, zline::img2c, zline::size
#   pkg-config --cflags --libs zline   (and zline-host, zline-panel)
#
# The panel drivers (port/display) are the `panel` component, installed by
# every build, cross ones included. The converters are the `tools`
# component, host builds only (bin/zline-obj2c, bin/zline-img2c, bin/zline-size, exported
# as zlineToolsTargets); zlineAssets.cmake, installed beside the package,
# gives every find_package user zline_add_mesh() and zline_add_texture().
#
# The host port (OBJ loader, PNM writer) is its own export set and install
# component, `host`: a cross build never installs it, and firmware that
# finds zline never sees it.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(ZLINE_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/zline CACHE STRING
    "Where zlineConfig.cmake goes, relative to the prefix")

install(DIRECTORY ${PROJECT_SOURCE_DIR}/core/include/zline
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} COMPONENT core
        FILES_MATCHING PATTERN "*.h")
install(FILES ${PROJECT_SOURCE_DIR}/port/fpu/include/zline/zl_float.h
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/zline COMPONENT core)
# The configuration the library was built with (core/CMakeLists.txt, ZLINE_CONFIG).
install(FILES ${ZLINE_BUILD_CONFIG_DIR}/zline/zl_build_config.h
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/zline COMPONENT core)
install(TARGETS zline EXPORT zlineTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT core
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(EXPORT zlineTargets NAMESPACE zline:: DESTINATION ${ZLINE_INSTALL_CMAKEDIR}
        COMPONENT core)

if(TARGET zline_host)
  install(FILES ${PROJECT_SOURCE_DIR}/port/host/zl_obj.h ${PROJECT_SOURCE_DIR}/port/host/zl_pnm.h
                ${PROJECT_SOURCE_DIR}/port/host/zl_output.h
          DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/zline/host COMPONENT host)
  install(TARGETS zline_host EXPORT zlineHostTargets
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT host)
  install(EXPORT zlineHostTargets NAMESPACE zline:: DESTINATION ${ZLINE_INSTALL_CMAKEDIR}
          COMPONENT host)
endif()

if(TARGET zline_panel)
  install(FILES ${PROJECT_SOURCE_DIR}/port/display/zl_spi_panel.h ${PROJECT_SOURCE_DIR}/port/display/zl_grey4.h
          DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/zline/panel COMPONENT panel)
  install(TARGETS zline_panel EXPORT zlinePanelTargets
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT panel)
  install(EXPORT zlinePanelTargets NAMESPACE zline:: DESTINATION ${ZLINE_INSTALL_CMAKEDIR}
          COMPONENT panel)
endif()

if(TARGET zline-obj2c AND TARGET zline-img2c AND TARGET zline-size)
  install(TARGETS zline-obj2c zline-img2c zline-size EXPORT zlineToolsTargets
          RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT tools)
  install(EXPORT zlineToolsTargets NAMESPACE zline:: DESTINATION ${ZLINE_INSTALL_CMAKEDIR}
          COMPONENT tools)
endif()

if(NOT ZLINE_HOST_HAS_PNG)
  set(ZLINE_HOST_HAS_PNG FALSE)
endif()
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/zlineConfig.cmake.in
  ${PROJECT_BINARY_DIR}/zlineConfig.cmake
  INSTALL_DESTINATION ${ZLINE_INSTALL_CMAKEDIR})
# Same major version: 0.1 finds 0.1.x, 0.2, ... (0.x is still the first API).
write_basic_package_version_file(${PROJECT_BINARY_DIR}/zlineConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMajorVersion)
install(FILES ${PROJECT_BINARY_DIR}/zlineConfig.cmake ${PROJECT_BINARY_DIR}/zlineConfigVersion.cmake
              ${CMAKE_CURRENT_LIST_DIR}/zlineAssets.cmake
        DESTINATION ${ZLINE_INSTALL_CMAKEDIR} COMPONENT core)

# pkg-config: the prefix found from the .pc file's own folder (pcfiledir), so
# `cmake --install --prefix` anywhere, or moving the tree, keeps it right.
file(RELATIVE_PATH ZLINE_PC_TO_PREFIX /${CMAKE_INSTALL_LIBDIR}/pkgconfig /)
string(REGEX REPLACE "/$" "" ZLINE_PC_TO_PREFIX "${ZLINE_PC_TO_PREFIX}")
set(ZLINE_PC_LIBDIR ${CMAKE_INSTALL_LIBDIR})
set(ZLINE_PC_INCLUDEDIR ${CMAKE_INSTALL_INCLUDEDIR})
configure_file(${CMAKE_CURRENT_LIST_DIR}/zline.pc.in ${PROJECT_BINARY_DIR}/zline.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/zline.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig
        COMPONENT core)
if(TARGET zline_panel)
  configure_file(${CMAKE_CURRENT_LIST_DIR}/zline-panel.pc.in ${PROJECT_BINARY_DIR}/zline-panel.pc @ONLY)
  install(FILES ${PROJECT_BINARY_DIR}/zline-panel.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig
          COMPONENT panel)
endif()
if(TARGET zline_host)
  set(ZLINE_PC_HOST_LIBS "")
  if(ZLINE_HOST_HAS_PNG)
    set(ZLINE_PC_HOST_LIBS "-lpng")
  endif()
  if(ZLINE_HAVE_LIBM)
    string(APPEND ZLINE_PC_HOST_LIBS " -lm")
  endif()
  configure_file(${CMAKE_CURRENT_LIST_DIR}/zline-host.pc.in ${PROJECT_BINARY_DIR}/zline-host.pc @ONLY)
  install(FILES ${PROJECT_BINARY_DIR}/zline-host.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig
          COMPONENT host)
endif()

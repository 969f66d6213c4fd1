# install.cmake - what `cmake --install` puts where (included by the top CMakeLists.txt).
#
#   bin/ssgraph                            the command line
#   lib/libssgraph.so.0, lib/libssgraph.a  the library, shared and static
#   lib/ssgraph/libssgraph_oiio.so         the OpenImageIO module (opened on the first image;
#                                          core/io/imageio_load.c looks for it there, relative
#                                          to the library or the program)
#   include/ssgraph/ssgraph.h, ssgraph_tools.h, errors.def  the public C interface: #include <ssgraph/ssgraph.h>
#   lib/pkgconfig/ssgraph.pc               pkg-config (Libs.private: the static library's needs)
#   lib/cmake/ssgraph/                     find_package(ssgraph): ssgraph::ssgraph (shared)
#                                          and ssgraph::ssgraph_static
#   share/ssgraph/graphs, examples         the bundled graphs and scenes (their relative paths
#                                          kept, so the graphs find their scenes)
#   share/doc/ssgraph/                     README, LICENSE and docs/
include(CMakePackageConfigHelpers)

# The header's SSG_VERSION and the project's version are one number: refuse to build if not.
file(STRINGS ${PROJECT_SOURCE_DIR}/core/ssgraph.h SSG_HEADER_VERSION
     REGEX "^#define SSG_VERSION \"[0-9.]+\"")
string(REGEX REPLACE ".*\"([0-9.]+)\".*" "\\1" SSG_HEADER_VERSION "${SSG_HEADER_VERSION}")
if(NOT SSG_HEADER_VERSION STREQUAL PROJECT_VERSION)
  message(FATAL_ERROR "core/ssgraph.h says SSG_VERSION ${SSG_HEADER_VERSION}, "
                      "CMakeLists.txt says ${PROJECT_VERSION}: make them agree")
endif()

set(SSG_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/ssgraph)
install(TARGETS ${SSG_LIBRARIES} EXPORT ssgraphTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(TARGETS ssgraph_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS ssgraph_oiio LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}/ssgraph)
install(FILES core/ssgraph.h core/ssgraph_tools.h core/errors.def DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/ssgraph)
install(EXPORT ssgraphTargets NAMESPACE ssgraph:: DESTINATION ${SSG_CMAKE_DIR})

configure_package_config_file(cmake/ssgraphConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/ssgraphConfig.cmake INSTALL_DESTINATION ${SSG_CMAKE_DIR})
# 0.x: a minor version may change the interface.
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/ssgraphConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/ssgraphConfig.cmake
              ${CMAKE_CURRENT_BINARY_DIR}/ssgraphConfigVersion.cmake
        DESTINATION ${SSG_CMAKE_DIR})

# pkg-config: relative to the .pc file's own place, so an installed tree can be moved.
file(RELATIVE_PATH SSG_PC_TO_PREFIX ${CMAKE_INSTALL_FULL_LIBDIR}/pkgconfig ${CMAKE_INSTALL_PREFIX})
string(REGEX REPLACE "/$" "" SSG_PC_TO_PREFIX "${SSG_PC_TO_PREFIX}")
# The static library's image libraries (CMakeLists.txt finds them by path): -lNAME each.
set(SSG_PC_IMAGE_LIBS "")
foreach(lib ${SSG_EXRCORE_LIB} ${PNG_LIBRARIES} ${SSG_PC_DEFLATE})
  get_filename_component(name ${lib} NAME_WE)
  string(REGEX REPLACE "^lib" "" name "${name}")
  string(APPEND SSG_PC_IMAGE_LIBS " -l${name}")
endforeach()
configure_file(cmake/ssgraph.pc.in ${CMAKE_CURRENT_BINARY_DIR}/ssgraph.pc @ONLY)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/ssgraph.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)

install(DIRECTORY graphs examples DESTINATION ${CMAKE_INSTALL_DATADIR}/ssgraph)
install(FILES README.md LICENSE DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR})

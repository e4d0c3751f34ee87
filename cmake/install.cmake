# `cmake --install build --prefix P`: the program, the libraries, their headers under
# P/include/hertzdash/<layer>/, the data tables under P/share/hertzdash/data (where the
# library looks for them, simulation/paper/paper_parameters.hpp), and the CMake package
# P/lib/cmake/hertzdash, so a project of yours can
#   find_package(hertzdash CONFIG REQUIRED)
#   target_link_libraries(my_program PRIVATE hertzdash::hertzdash)
# tests/install_consumer/ is such a project; the test `install_consumer` builds it
# against an installation into a scratch prefix.
include(CMakePackageConfigHelpers)
set(HERTZDASH_CMAKE_DIR "${CMAKE_INSTALL_LIBDIR}/cmake/hertzdash")

install(TARGETS hertzdash RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})

get_property(hertzdash_libraries GLOBAL PROPERTY HERTZDASH_LIBRARY_TARGETS)
install(TARGETS ${hertzdash_libraries} EXPORT hertzdashTargets
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
# Headers of an optional part that was left out, and the internal headers of a library's own
# sources (simulation/CMakeLists.txt), are not installed.
set(hertzdash_headers_not_built)
foreach(header IN LISTS HERTZDASH_HEADERS_NOT_BUILT HERTZDASH_INTERNAL_HEADERS HERTZDASH_INTERNAL_INTEGRATOR_HEADERS)
  list(APPEND hertzdash_headers_not_built REGEX "/${header}$" EXCLUDE)
endforeach()
foreach(layer IN LISTS HERTZDASH_LAYERS)
  install(DIRECTORY "${PROJECT_SOURCE_DIR}/${layer}/" DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}/hertzdash/${layer}"
    FILES_MATCHING PATTERN "*.hpp" ${hertzdash_headers_not_built})
endforeach()
install(FILES "${HERTZDASH_INCLUDE_DIR}/hertzdash/registered_law_list.hpp"
  DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}/hertzdash")
install(DIRECTORY "${PROJECT_SOURCE_DIR}/data/" DESTINATION "${CMAKE_INSTALL_DATADIR}/hertzdash/data")

install(EXPORT hertzdashTargets NAMESPACE hertzdash:: DESTINATION "${HERTZDASH_CMAKE_DIR}")
configure_package_config_file(cmake/hertzdashConfig.cmake.in "${PROJECT_BINARY_DIR}/hertzdashConfig.cmake"
  INSTALL_DESTINATION "${HERTZDASH_CMAKE_DIR}")
write_basic_package_version_file("${PROJECT_BINARY_DIR}/hertzdashConfigVersion.cmake" COMPATIBILITY SameMinorVersion)
install(FILES "${PROJECT_BINARY_DIR}/hertzdashConfig.cmake" "${PROJECT_BINARY_DIR}/hertzdashConfigVersion.cmake"
  DESTINATION "${HERTZDASH_CMAKE_DIR}")

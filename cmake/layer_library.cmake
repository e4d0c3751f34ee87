# hertzdash_layer_library(<target> <export name>): a layer's include directories (the build
# tree's build/include, an installation's include/), the C++ standard its headers need (C++20:
# concepts; a requirement of every target that links it, so a project that sets no standard
# compiles them), its library version, and its name in
# the installed package, hertzdash::<export name>. cmake/install.cmake installs every target
# registered here.
function(hertzdash_layer_library target export_name)
  get_target_property(type ${target} TYPE)
  if(type STREQUAL "INTERFACE_LIBRARY")
    set(scope INTERFACE)
  else()
    set(scope PUBLIC)
  endif()
  target_include_directories(${target} ${scope}
    $<BUILD_INTERFACE:${HERTZDASH_INCLUDE_DIR}> $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_compile_features(${target} ${scope} cxx_std_20)
  if(NOT type STREQUAL "INTERFACE_LIBRARY")
    # Installed, a layer finds the layers it links in its own directory. In the build tree all
    # sit in build/lib, below build/share/hertzdash/data as an installation's lib/ is below its
    # share/ (simulation/paper/paper_parameters.cpp, default_data_dir).
    set_target_properties(${target} PROPERTIES VERSION ${PROJECT_VERSION} SOVERSION ${PROJECT_VERSION_MAJOR}
      INSTALL_RPATH "$ORIGIN" LIBRARY_OUTPUT_DIRECTORY "${PROJECT_BINARY_DIR}/lib"
      ARCHIVE_OUTPUT_DIRECTORY "${PROJECT_BINARY_DIR}/lib")
  endif()
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${export_name})
  set_property(GLOBAL APPEND PROPERTY HERTZDASH_LIBRARY_TARGETS ${target})
endfunction()

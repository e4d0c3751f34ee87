# hertzdash_layer_library(<target> <export name>): a layer's include directories (the build
# tree's build/include, an installation's include/), its library version, and its name in
# the installed package, hertzdash::<export name>. cmake/install.cmake installs every target
# registered here.
function(hertzdash_layer_library target export_name)
  get_target_property(type ${target} TYPE)
  if(type STREQUAL "INTERFACE_LIBRARY")
    target_include_directories(${target} INTERFACE
      $<BUILD_INTERFACE:${HERTZDASH_INCLUDE_DIR}> $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  else()
    target_include_directories(${target} PUBLIC
      $<BUILD_INTERFACE:${HERTZDASH_INCLUDE_DIR}> $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
    # Installed, a layer finds the layers it links in its own directory.
    set_target_properties(${target} PROPERTIES VERSION ${PROJECT_VERSION} SOVERSION ${PROJECT_VERSION_MAJOR}
      INSTALL_RPATH "$ORIGIN")
  endif()
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${export_name})
  set_property(GLOBAL APPEND PROPERTY HERTZDASH_LIBRARY_TARGETS ${target})
endfunction()

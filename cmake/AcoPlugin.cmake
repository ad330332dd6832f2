# aco_add_plugin(<slot> <name> <sources>...)
# Builds one plugin as its own shared library, aco_<slot>_<name>.so. Plugins hide every symbol
# but the Boost.DLL descriptor alias. Used by this project and, after installation, by
# out-of-tree plugin projects (find_package(aco) provides it).
function(aco_add_plugin slot name)
  set(target aco_${slot}_${name})
  add_library(${target} MODULE ${ARGN})
  target_link_libraries(${target} PRIVATE aco::aco)
  if(DEFINED ACO_BUILD_PLUGIN_DIR)
    set(output ${ACO_BUILD_PLUGIN_DIR})
  else()
    set(output ${CMAKE_BINARY_DIR}/plugins)
  endif()
  set_target_properties(${target} PROPERTIES
    PREFIX ""
    CXX_VISIBILITY_PRESET hidden
    VISIBILITY_INLINES_HIDDEN ON
    LIBRARY_OUTPUT_DIRECTORY ${output}
    INSTALL_RPATH "$ORIGIN/../..")
  install(TARGETS ${target} LIBRARY DESTINATION lib/aco/plugins)
  set_property(GLOBAL APPEND PROPERTY ACO_PLUGIN_TARGETS ${target})
endfunction()

# aco_add_plugin(<kind> <name> <sources>...)
# Builds one plugin as its own shared library, aco_<kind>_<name>.so, in the build tree's
# plugin folder. Plugins hide every symbol but the Boost.DLL descriptor alias.
function(aco_add_plugin kind name)
  set(target aco_${kind}_${name})
  add_library(${target} MODULE ${ARGN})
  target_link_libraries(${target} PRIVATE aco::aco)
  set_target_properties(${target} PROPERTIES
    PREFIX ""
    CXX_VISIBILITY_PRESET hidden
    VISIBILITY_INLINES_HIDDEN ON
    LIBRARY_OUTPUT_DIRECTORY ${ACO_BUILD_PLUGIN_DIR}
    INSTALL_RPATH "$ORIGIN/../..")
  install(TARGETS ${target} LIBRARY DESTINATION ${ACO_INSTALL_PLUGIN_DIR})
endfunction()

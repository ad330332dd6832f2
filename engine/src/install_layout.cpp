#include "aco/engine/install_layout.hpp"

#include <boost/dll/runtime_symbol_info.hpp>

namespace aco {

const InstallLayout& install_layout() {
  static const InstallLayout layout = [] {
    namespace fs = std::filesystem;
    boost::dll::fs::error_code ec;
    const fs::path library = boost::dll::this_line_location(ec);  // this libaco file
    if (ec) return InstallLayout{};  // nowhere to look: no bundled plugins, no bundled data
    std::error_code fs_ec;
    if (fs::equivalent(library.parent_path(), ACO_BUILD_LIBRARY_DIR, fs_ec))
      return InstallLayout{false, ACO_BUILD_PLUGIN_DIR, ACO_SOURCE_DATA_DIR};
    // Loaded through an RPATH such as $ORIGIN/../lib: <prefix>/bin/../lib/../share reads better
    // as <prefix>/share.
    const fs::path libdir = library.parent_path();
    return InstallLayout{true, (libdir / ACO_PLUGINS_FROM_LIBDIR).lexically_normal(),
                         (libdir / ACO_DATA_FROM_LIBDIR).lexically_normal()};
  }();
  return layout;
}

}  // namespace aco

#pragma once
// Where the framework finds the plugins and data that came with it. An installed libaco uses
// the ones installed with it (<prefix>/lib/aco/plugins, <prefix>/share/aco); a libaco run from
// its build tree uses the build tree's plugins and the source tree's data. Neither looks in the
// other's: an installed host must not pick up whatever a build tree holds.
#include <filesystem>

namespace aco {

struct InstallLayout {
  bool installed = false;
  std::filesystem::path plugins;  // the bundled plugins
  std::filesystem::path data;  // the bundled maps and scenarios (data/ of the source tree)
};

// Found from where the running libaco file is.
const InstallLayout& install_layout();

}  // namespace aco

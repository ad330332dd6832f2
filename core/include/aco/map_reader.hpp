#pragma once
// Slot "map": a reader of one map file format, so that a format nobody bundles is a plugin
// (ACO_PLUGIN(map, NAME, ...)) rather than a change to the framework. Hosts pick the reader by
// the file's extension, or by name with --map-format NAME (the plugin's NAME, or a built-in
// format's: aco/engine/map_formats.hpp).
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "aco/map.hpp"
#include "aco/strategies.hpp"
#include "aco/terrain.hpp"

namespace aco {

class BOOST_SYMBOL_VISIBLE MapReader : public Strategy {
 public:
  ~MapReader() override;
  // The map in `file`. A file it cannot read is an aco::Error naming the file (and the line) and
  // what is wrong. `terrain` holds the run's max-slope, height-scale and cell-size, for formats
  // with heights; a 2D format ignores it. The Map's code stays loaded for the process (hosts
  // never unload a plugin library), so the Map may outlive the reader.
  virtual std::unique_ptr<Map> read(const std::filesystem::path& file, const TerrainOptions& terrain) const = 0;
  // The endings of the file names it reads, with the dot (".shapes"); none: it is chosen by name
  // only (--map-format NAME). Two readers claiming one ending is an error that names both.
  virtual std::vector<std::string> extensions() const { return {}; }
  // A small file in its format (the contents, for a file ending in its first extension), which
  // aco-plugin-check reads; "" if none.
  virtual std::string sample() const { return {}; }
};

}  // namespace aco

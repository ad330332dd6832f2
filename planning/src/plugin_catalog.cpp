#include "aco/planning/plugin_catalog.hpp"

#include <algorithm>
#include <sstream>

#include "aco/error.hpp"
#include "aco/engine/map_formats.hpp"
#include "aco/map_reader.hpp"
#include "aco/parameters.hpp"
#include "aco/engine/pipeline.hpp"

namespace aco {
namespace {

// Files this plugin hides, one line each (indented like the plugin's own file line).
std::string shadow_lines(const aco::PluginFile& plugin) {
  std::string lines;
  for (const auto& hidden : plugin.shadowed)
    lines += "      shadows " + hidden.string() + " (not used: the file above comes first in the search order)\n";
  return lines;
}

// "claims .yaml .yml" or what a format claiming nothing is read for, and a newline.
std::string extensions_line(const std::vector<std::string>& extensions) {
  if (extensions.empty()) return "claims no file ending (--map-format NAME)\n";
  std::string line = "claims";
  for (const auto& e : extensions) line += " " + e;
  return line + "\n";
}

}  // namespace

// From the plugin records alone: listing runs no plugin code.
std::string list_plugins(aco::PluginRegistry& registry) {
  std::ostringstream out;
  out << "plugins (slot/name, version, summary, file):\n";
  for (const aco::SlotInfo& info : aco::kSlotTable) {
    const std::string slot = info.name;
    if (slot == "map")
      for (const auto& format : aco::builtin_map_formats())
        out << "  map/" << format.name << "  built-in  " << format.summary << "\n      "
            << extensions_line(format.extensions);
    for (const auto& name : registry.names(slot)) {
      const auto& plugin = registry.get(slot, name);
      out << "  " << slot << "/" << name;
      if (plugin.unusable.empty())
        out << "  " << plugin.record.version << "  " << plugin.record.summary;
      else
        out << "  UNUSABLE: " << plugin.unusable;
      out << "\n      " << plugin.file.string() << "\n" << shadow_lines(plugin);
    }
  }
  out << "searched:";
  for (const auto& dir : registry.search_dirs()) out << " " << dir.string();
  out << "\n";
  return out.str();
}

std::string describe_plugin(aco::PluginRegistry& registry, const std::string& name) {
  // A built-in map format: "map/NAME", or NAME alone when no plugin is called so.
  const auto& files = registry.available();
  const bool plugin_named =
      std::any_of(files.begin(), files.end(), [&](const aco::PluginFile& p) { return p.name == name; });
  for (const auto& format : aco::builtin_map_formats())
    if (name == "map/" + format.name || (name == format.name && !plugin_named))
      return "map/" + format.name + " built-in: " + format.summary + "\n" + extensions_line(format.extensions) +
             "no parameters (terrain formats read max-slope, height-scale and cell-size)\n";
  // In the slots' order (init before heuristic), as --list-plugins shows them.
  std::vector<const aco::PluginFile*> matches;
  for (const aco::SlotInfo& slot : aco::kSlotTable)
    for (const auto& p : registry.available())
      if (p.slot == slot.name && (p.name == name || p.slot + "/" + p.name == name)) matches.push_back(&p);
  if (matches.empty()) {
    std::string message = "--describe: no plugin named '" + name + "'";
    std::vector<std::string> names;
    for (const auto& p : registry.available())
      names.push_back(name.find('/') == std::string::npos ? p.name : p.slot + "/" + p.name);
    if (const auto near = aco::nearest(name, names); !near.empty())
      for (const auto& p : registry.available())
        if (p.name == near || p.slot + "/" + p.name == near)
          message += "; did you mean '" + p.slot + "/" + p.name + "'?";
    throw aco::Error(message);
  }
  if (matches.size() > 1) {
    std::string message = "--describe: '" + name + "' names a plugin in " + std::to_string(matches.size()) +
                          " slots; give its slot too, as SLOT/NAME:";
    for (std::size_t i = 0; i < matches.size(); ++i)
      message += (i == 0 ? " " : i + 1 == matches.size() ? " or " : ", ") + matches[i]->slot + "/" + matches[i]->name;
    throw aco::Error(message);
  }
  const auto& d = registry.load(matches[0]->slot, matches[0]->name);
  std::ostringstream out;
  out << d.slot << "/" << d.name << " " << d.version << ": " << d.summary << "\n"
      << "file: " << matches[0]->file.string() << "\n"
      << shadow_lines(*matches[0]) << "built by: " << matches[0]->record.compiler << ", " << matches[0]->record.stdlib
      << ", " << matches[0]->record.build << "\n";
  if (d.slot == std::string("map")) {
    const auto values = aco::resolve(d.parameters(), {}, "map.");
    out << extensions_line(registry.create<aco::MapReader>("map", d.name, values)->extensions());
  }
  if (d.param_count == 0) {
    out << "no parameters\n";
    return out.str();
  }
  out << "parameters (--" << d.slot << ".NAME VALUE):\n";
  for (const auto& spec : d.parameters())
    out << "  " << spec.name << "  " << aco::to_string(spec.type) << "  default " << aco::shown_default(spec)
        << (spec.range && *spec.range ? std::string("  range ") + spec.range : std::string()) << "\n      " << spec.help
        << "\n";
  return out.str();
}

}  // namespace aco

#pragma once
// acobench's report of a results database: statistics per configuration and problem, tests
// against the baseline, a ranking, plots, the ablation path; as Markdown, self-contained HTML
// and a CSV of every run.
#include <filesystem>
#include <string>
#include <vector>

#include "aco/engine/plugin_registry.hpp"

namespace aco::studies {

// Writes report.md, report.html and runs.csv into `out` (created if missing), and each of the
// HTML page's plots alone as plots/<kind>-<problem>.svg (box, convergence, anytime-time,
// anytime-walks, paths; ecdf-1pct, ecdf-5pct and ablation once); returns them all. The
// warnings the report gives (an unoptimised build of acobench or of a plugin ran the trials) are
// also added to `warnings`, for the caller to print. The map plugins of problems whose maps a
// plugin reads are looked for in `plugin_dirs` (default: ACO_PLUGIN_PATH's and the bundled folder).
std::vector<std::filesystem::path> write_report(
    const std::filesystem::path& database, const std::filesystem::path& out,
    std::vector<std::string>* warnings = nullptr,
    const std::vector<std::filesystem::path>& plugin_dirs = aco::PluginRegistry::default_search_dirs());

}  // namespace aco::studies

#pragma once
// acobench's report of a results database: statistics per configuration and problem, tests
// against the baseline, a ranking, plots, the ablation path; as Markdown, self-contained HTML
// and a CSV of every run.
#include <filesystem>
#include <vector>

namespace acobench {

// Writes report.md, report.html and runs.csv into `out` (created if missing); returns them.
std::vector<std::filesystem::path> write_report(const std::filesystem::path& database, const std::filesystem::path& out);

}  // namespace acobench

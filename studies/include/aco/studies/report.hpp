#pragma once
// acobench's report of a results database: statistics per configuration and problem, tests
// against the baseline, a ranking, plots, the ablation path; as Markdown, self-contained HTML
// and a CSV of every run.
#include <filesystem>
#include <string>
#include <vector>

namespace acobench {

// Writes report.md, report.html and runs.csv into `out` (created if missing); returns them. The
// warnings the report gives (an unoptimised build of acobench or of a plugin ran the trials) are
// also added to `warnings`, for the caller to print.
std::vector<std::filesystem::path> write_report(const std::filesystem::path& database, const std::filesystem::path& out,
                                                std::vector<std::string>* warnings = nullptr);

}  // namespace acobench

// The report of a database: the analysis (report_analysis.cpp) as a document of tables
// (report_tables.cpp, report_comparisons.cpp) and figures (report_figures.cpp), written as
// Markdown, HTML, the runs' CSV and the figures' SVG files.
#include "aco/studies/report.hpp"

#include <algorithm>
#include <fstream>
#include <variant>

#include "aco/error.hpp"
#include "aco/studies/report_document.hpp"
#include "aco/studies/results_db.hpp"
#include "report_analysis.hpp"
#include "report_figures.hpp"
#include "report_tables.hpp"

namespace aco::studies {
namespace {

// The warnings of the report's head: runs left out, builds whose times mean little.
std::vector<std::string> warnings_of(const Analysis& a) {
  std::vector<std::string> warnings;
  if (!a.left_out.empty()) {
    std::string rows;
    for (std::size_t i = 0; i < std::min<std::size_t>(a.left_out.size(), 5); ++i)
      rows += (i ? "; " : "") + describe(a.left_out[i]);
    if (a.left_out.size() > 5) rows += "; ...";
    const bool one = a.left_out.size() == 1;
    warnings.push_back(std::to_string(a.left_out.size()) + (one ? " run is" : " runs are") +
                       " left out of every table and figure: " + (one ? "its rows do" : "their rows do") +
                       " not hold what the database's tables declare (" + rows + ")");
  }
  for (std::string& warning : build_warnings(a)) warnings.push_back(std::move(warning));
  return warnings;
}

// The whole report: what the analysis found, in the order a reader wants it.
ReportDocument report_document(const Analysis& a, const std::filesystem::path& database) {
  ReportDocument d{"acobench report: " + a.name, "acobench: " + a.name, {}};
  std::vector<Block>& blocks = d.blocks;
  const std::string left_out = a.left_out.empty() ? "" : " (" + std::to_string(a.left_out.size()) + " left out)";
  blocks.emplace_back(Paragraph{
      "Database `" + database.filename().string() + "`: " + std::to_string(a.trials.size()) + " runs" + left_out +
      ", " + std::to_string(a.configs.size()) + " configurations, " + std::to_string(a.problems.size()) +
      " problems. Lengths are final path lengths of solved runs (after the smoother: any-angle when it "
      "shortcuts); gap is "
      "the mean excess of the grid path (before smoothing) over the exact A* optimum on the baseline's "
      "graph, so that both "
      "are lengths on the same grid; over any-angle is the mean excess of the final path over the exact "
      "any-angle optimum (touching obstacles allowed, a lower bound of every path: docs/maps.md), the "
      "yardstick of smoothed and continuous paths; p is the two-sided Mann-Whitney U test against the baseline (`" +
      (a.configs.empty() ? "" : a.configs[0].second.name) +
      "`), Holm-corrected across all comparisons; A12 < 0.5 means shorter paths than the baseline."});
  for (std::string& warning : warnings_of(a)) blocks.emplace_back(Warning{std::move(warning)});
  FigureFiles files;
  for (Table& t : summary_tables(a)) blocks.emplace_back(std::move(t));
  for (Table& t : anytime_tables(a)) {
    const bool reached = !t.rows.empty();
    blocks.emplace_back(std::move(t));
    if (reached)
      blocks.emplace_back(
          Paragraph{"report.html plots the share of runs within each target against time (the ECDF) and, "
                    "per problem, the mean best-so-far gap against time and against walks.",
                    true});
    for (Figure& figure : ecdf_charts(a, files)) blocks.emplace_back(std::move(figure));
  }
  for (Table& t : appended_tables(a)) blocks.emplace_back(std::move(t));
  // Per problem: every configuration's summary, then its pictures.
  for (std::size_t p = 0; p < a.problems.size(); ++p) {
    blocks.emplace_back(problem_table(a, p));
    for (Figure& figure : problem_figures(a, p, files)) blocks.emplace_back(std::move(figure));
  }
  for (Table& t : ranking_tables(a)) blocks.emplace_back(std::move(t));
  for (Table& t : ablation_tables(a)) blocks.emplace_back(std::move(t));
  for (Figure& figure : ablation_charts(a, files)) blocks.emplace_back(std::move(figure));
  for (Table& t : provenance_tables(a)) blocks.emplace_back(std::move(t));
  return d;
}

void write(const std::filesystem::path& file, const std::string& text) {
  std::ofstream out(file, std::ios::binary);
  out << text;
  if (!out) throw aco::Error("cannot write " + file.string());
}

}  // namespace

std::vector<std::filesystem::path> write_report(const std::filesystem::path& database, const std::filesystem::path& out,
                                                std::vector<std::string>* warnings,
                                                const std::vector<std::filesystem::path>& plugin_dirs) {
  if (!std::filesystem::exists(database)) throw aco::Error(database.string() + ": no such results database");
  const ResultsDb db(database);
  Analysis a = analyse(db);
  aco::PluginRegistry registry(plugin_dirs);
  a.registry = &registry;
  std::filesystem::create_directories(out);
  const ReportDocument document = report_document(a, database);
  std::vector<std::filesystem::path> files = {out / "report.md", out / "report.html", out / "runs.csv"};
  write(files[0], render_markdown(document));
  write(files[1], render_html(document, "<p>All runs: <a href=\"runs.csv\">runs.csv</a></p>\n"));
  write(files[2], runs_csv(a.trials, a.problems, a.configs));
  std::filesystem::create_directories(out / "plots");
  for (const Block& block : document.blocks)
    if (const auto* figure = std::get_if<Figure>(&block); figure && !figure->svg.empty()) {
      files.push_back(out / "plots" / figure->file);
      write(files.back(), figure->svg);
    }
  if (warnings)
    for (std::string& warning : warnings_of(a)) warnings->push_back(std::move(warning));
  return files;
}

}  // namespace aco::studies

// acobench's report: one document, drawn as Markdown and as HTML.
#include <algorithm>
#include <catch2/catch.hpp>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "aco/studies/experiment.hpp"
#include "aco/studies/report.hpp"
#include "aco/studies/runner.hpp"
#include "acobench_support.hpp"
#include "support.hpp"

namespace {

using Cells = std::vector<std::vector<std::string>>;

// Markdown's tables by the heading above them: every row but the alignment line, cells trimmed.
std::map<std::string, Cells> markdown_tables(const std::string& md) {
  std::map<std::string, Cells> tables;
  std::istringstream in(md);
  std::string line, heading;
  while (std::getline(in, line)) {
    if (line.starts_with("## ")) heading = line.substr(3);
    if (!line.starts_with("|") || line.starts_with("|---")) continue;
    std::vector<std::string> row;
    std::size_t from = 1;
    for (std::size_t bar; (bar = line.find(" |", from)) != std::string::npos; from = bar + 2)
      row.push_back(line.substr(from + 1, bar - from - 1));
    tables[heading].push_back(row);
  }
  return tables;
}

std::string unescaped(std::string text) {
  for (const auto& [entity, plain] :
       {std::pair{"&lt;", "<"}, {"&gt;", ">"}, {"&quot;", "\""}, {"&apos;", "'"}, {"&amp;", "&"}})
    for (std::size_t at; (at = text.find(entity)) != std::string::npos;)
      text.replace(at, std::string(entity).size(), plain);
  return text;
}

// The text between `open` and the next `close` from `at` on (`at` moves past it), if it comes
// before `limit`. Plain searches: std::regex recurses once per character and overflows the stack
// on a page of plots.
std::optional<std::string> next_between(const std::string& text, std::size_t& at, const std::string& open,
                                        const std::string& close, std::size_t limit = std::string::npos) {
  const std::size_t from = text.find(open, at);
  if (from == std::string::npos || from >= limit) return std::nullopt;
  const std::size_t to = text.find(close, from + open.size());
  if (to == std::string::npos) return std::nullopt;
  at = to + close.size();
  return text.substr(from + open.size(), to - from - open.size());
}

// HTML's tables by the <h2> above them.
std::map<std::string, Cells> html_tables(const std::string& html) {
  std::map<std::string, Cells> tables;
  std::size_t at = 0;
  while (const auto title = next_between(html, at, "<h2>", "</h2>")) {
    const std::size_t next_heading = html.find("<h2>", at);
    const auto table = next_between(html, at, "<table>", "</table>", next_heading);
    if (!table) continue;
    Cells& cells = tables[unescaped(*title)];
    std::size_t in_table = 0;
    while (const auto row = next_between(*table, in_table, "<tr>", "</tr>")) {
      std::vector<std::string> values;
      std::size_t in_row = 0;
      for (std::optional<std::string> cell; (cell = next_between(*row, in_row, "<t", "</t"));)
        values.push_back(unescaped(cell->substr(cell->find('>') + 1)));
      cells.push_back(values);
    }
  }
  return tables;
}

// A small study over a grid map and a height map, with an ablation path, reported into `out`.
std::filesystem::path reported_study(const std::string& configurations) {
  const auto file = test::temp_file(
      "report.yaml", "name: report\nseed: 5\nrepetitions: 2\nproblems:\n  - {map: " +
                         (test::data_dir() / "maps/classic20/map1.txt").string() +
                         ", start: [0, 0], goal: [19, 19], name: map1}\n  - {scen: " +
                         (test::data_dir() / "terrain/epf30.asc.scen").string() +
                         ", count: 1}\nsettings: {preset: ant-system, ants: 8, iterations: 10}\n" + configurations);
  const auto e = aco::studies::load_experiment(file, test::plugins());
  aco::studies::RunOptions options;
  options.database = file.parent_path() / "report.db";
  std::filesystem::remove(options.database);
  options.threads = 2;
  aco::studies::run_experiment(e, test::plugins(), options);
  const auto out = file.parent_path() / "report";
  std::filesystem::remove_all(out);
  aco::studies::write_report(options.database, out);
  return out;
}

}  // namespace

TEST_CASE("the Markdown and the HTML report hold the same tables, cell for cell", "[acobench][report]") {
  const auto out = reported_study(
      "configurations:\n  - {name: elite, update: elite, q0: 0.8}\n  - {name: both, update: elite, q0: 0.8, smoother: "
      "prune}\n"
      "ablation: {target: both}\n");
  const auto md = markdown_tables(test::acobench_helpers::file_bytes(out / "report.md"));
  const auto html = html_tables(test::acobench_helpers::file_bytes(out / "report.html"));
  std::vector<std::string> md_titles, html_titles;
  for (const auto& [title, cells] : md) md_titles.push_back(title);
  for (const auto& [title, cells] : html) html_titles.push_back(title);
  CHECK(md_titles == html_titles);
  for (const char* title : {"Ranking across problems", "Ablation path", "Plugins"}) CHECK(md.count(title) == 1);
  CHECK(std::count_if(md_titles.begin(), md_titles.end(),
                      [](const auto& t) { return t.starts_with("map1 (optimal "); }) == 1);
  for (const auto& [title, cells] : md) {
    INFO("table " << title);
    CHECK(cells.size() > 1);
    CHECK(cells == html.at(title));
  }
  // The ranking, best first in both.
  const Cells& ranking = md.at("Ranking across problems");
  for (std::size_t i = 2; i < ranking.size(); ++i) CHECK(std::stod(ranking[i - 1][2]) <= std::stod(ranking[i][2]));
}

TEST_CASE("a height map's paths are drawn on the map each configuration planned on", "[acobench][report][terrain]") {
  // At 60 degrees the steepest cells of the height map are blocked: its path belongs on that map,
  // not on the one of the default 90 degrees.
  const auto out = reported_study("configurations:\n  - {name: slope60, max-slope: 60}\n");
  const auto steep = out / "plots/paths-epf30-0.svg", gentle = out / "plots/paths-epf30-0-2.svg";
  REQUIRE(std::filesystem::exists(steep));
  REQUIRE(std::filesystem::exists(gentle));
  const auto blocked = [](const std::string& svg) {
    std::size_t rects = 0;
    for (std::size_t at = 0; (at = svg.find("<rect x=", at)) != std::string::npos; ++at) ++rects;
    return rects;
  };
  const std::string first = test::acobench_helpers::file_bytes(steep),
                    second = test::acobench_helpers::file_bytes(gentle);
  CHECK_THAT(first, Catch::Contains(">baseline "));
  CHECK_THAT(second, Catch::Contains(">slope60 "));
  CHECK_THAT(second, !Catch::Contains(">baseline "));
  CHECK(blocked(second) > blocked(first));
  // The grid map looks the same whatever the slope: one picture with both paths.
  const std::string grid = test::acobench_helpers::file_bytes(out / "plots/paths-map1.svg");
  CHECK_THAT(grid, Catch::Contains(">baseline ") && Catch::Contains(">slope60 "));
  CHECK_FALSE(std::filesystem::exists(out / "plots/paths-map1-2.svg"));
}

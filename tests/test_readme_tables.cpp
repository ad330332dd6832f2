// The documentation's reference parts kept true to the programs and the tree: the option table of
// docs/planning.md ("Options") names every option of `acoplan --help`, and README.md's Layout
// section describes every top-level folder and no folder that is not there.
#include <catch2/catch.hpp>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "support.hpp"

namespace {

const std::filesystem::path kProjectDir = test::data_dir().parent_path();

std::vector<std::string> file_lines(const std::string& file) {
  INFO(file);
  std::ifstream in(kProjectDir / file);
  REQUIRE(in);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// The lines of the section of `file` under `heading` (a whole line such as "## Layout"), to the
// next heading of the same or a higher level.
std::vector<std::string> section(const std::string& file, const std::string& heading) {
  const auto lines = file_lines(file);
  const auto level = heading.find(' ');
  std::vector<std::string> body;
  bool inside = false;
  for (const auto& line : lines) {
    if (line == heading) {
      inside = true;
      continue;
    }
    const auto hashes = line.find_first_not_of('#');
    if (inside && hashes > 0 && hashes <= level && hashes != std::string::npos && line[hashes] == ' ') break;
    if (inside) body.push_back(line);
  }
  INFO(file << " has no section " << heading);
  REQUIRE(!body.empty());
  return body;
}

// The first column of the table headed "| option | meaning |": its cells' text ("\|" inside a
// cell is a '|' of the text, not the column's end).
std::vector<std::string> option_cells() {
  std::vector<std::string> cells;
  bool table = false;
  for (const auto& line : section("docs/planning.md", "## Options")) {
    if (line == "| option | meaning |") {
      table = true;
      continue;
    }
    if (!table) continue;
    if (line.rfind("|", 0) != 0) break;
    std::size_t end = 1;
    while (end < line.size() && !(line[end] == '|' && line[end - 1] != '\\')) ++end;
    cells.push_back(line.substr(1, end - 1));
  }
  REQUIRE(cells.size() > 10);
  return cells;
}

// The long options (without "--") of `acoplan --help`: "  -h [ --help ]", "  --map FILE", ...
std::set<std::string> help_options() {
  const auto help = test::acoplan({"--help"});
  REQUIRE(help.exit_code == 0);
  std::set<std::string> options;
  const std::regex option(R"(^  (?:-\w \[ )?--([a-z0-9][a-z0-9.-]*))");
  std::istringstream in(help.out);
  std::smatch match;
  for (std::string line; std::getline(in, line);)
    if (std::regex_search(line, match, option)) options.insert(match[1]);
  REQUIRE(options.size() > 30);
  return options;
}

}  // namespace

TEST_CASE("docs/planning.md's option table names every option of acoplan --help", "[readme]") {
  std::set<std::string> documented;
  const std::regex option(R"(--([a-z0-9<][a-z0-9.<>-]*))");
  for (const auto& cell : option_cells())
    for (std::sregex_iterator it(cell.begin(), cell.end(), option), end; it != end; ++it) documented.insert((*it)[1]);
  for (const auto& name : help_options()) {
    INFO("--" << name << " is in acoplan --help but not in docs/planning.md's option table (\"Options\")");
    const auto dot = name.find('.');
    if (dot == std::string::npos) {
      CHECK(documented.count(name) == 1);
      continue;
    }
    // A plugin's or planner's parameter: its owner's row (--update.<param>, --<slot>.<param>, --ifwa.<param>).
    const std::string owner = name.substr(0, dot);
    const bool slot = std::find(aco::kSlots.begin(), aco::kSlots.end(), owner) != aco::kSlots.end();
    CHECK((documented.count(owner + ".<param>") == 1 || (slot && documented.count("<slot>.<param>") == 1)));
  }
  // And the table names no option acoplan does not have.
  const auto options = help_options();
  for (const auto& name : documented) {
    if (name.find('.') != std::string::npos) continue;
    INFO("--" << name << " is in docs/planning.md's option table but not in acoplan --help");
    CHECK(options.count(name) == 1);
  }
}

TEST_CASE("README's Layout describes every top-level folder and no other", "[readme]") {
  std::set<std::string> described;
  const std::regex entry(R"(^([A-Za-z0-9._-]+)/\s)");
  std::smatch match;
  for (const auto& line : section("README.md", "## Layout"))
    if (std::regex_search(line, match, entry)) described.insert(match[1]);
  // Folders that are not the project's: git's own and what .gitignore keeps out at the top (build/).
  std::set<std::string> ignored{".git"};
  std::ifstream gitignore(kProjectDir / ".gitignore");
  for (std::string line; std::getline(gitignore, line);)
    if (line.size() > 2 && line.front() == '/' && line.back() == '/') ignored.insert(line.substr(1, line.size() - 2));
  std::set<std::string> folders;
  for (const auto& entry : std::filesystem::directory_iterator(kProjectDir))
    if (entry.is_directory() && !ignored.count(entry.path().filename().string()))
      folders.insert(entry.path().filename().string());
  REQUIRE(folders.count("core") == 1);
  for (const auto& folder : folders) {
    INFO(folder << "/ is in the tree but README.md's Layout does not describe it");
    CHECK(described.count(folder) == 1);
  }
  for (const auto& folder : described) {
    INFO(folder << "/ is described in README.md's Layout but is not in the tree");
    CHECK(folders.count(folder) == 1);
  }
}

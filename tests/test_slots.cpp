// The slot table (aco/slots.hpp) is the one list of slots: the pipeline, the scaffolding tool and
// the docs' slot table must say what it says.
#include <catch2/catch.hpp>

#include <fstream>
#include <regex>
#include <sstream>

#include "aco/pipeline.hpp"
#include "aco/slots.hpp"

namespace {

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file);
  REQUIRE(in);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<std::string> split_hooks(const std::string& list) {
  std::vector<std::string> hooks;
  std::istringstream in(list);
  for (std::string hook; std::getline(in, hook, ',');) hooks.push_back(hook.substr(hook.find_first_not_of(' ')));
  return hooks;
}

}  // namespace

TEST_CASE("the pipeline's slots are the table's pipeline rows with their defaults", "[slots]") {
  std::vector<std::string> pipeline_rows;
  for (const aco::SlotInfo& slot : aco::kSlotTable)
    if (slot.pipeline) {
      pipeline_rows.push_back(slot.name);
      CHECK(aco::default_plugin(slot.name) == std::string(slot.default_plugin));
    }
  CHECK(std::vector<std::string>(aco::kSlots.begin(), aco::kSlots.end()) == pipeline_rows);
  CHECK_THROWS_WITH(aco::default_plugin("map"), Catch::Contains("unknown slot 'map'"));
}

TEST_CASE("docs/writing-plugins.md's slot table lists the table's slots with their interfaces and hooks", "[slots]") {
  const std::string file = read_text(std::filesystem::path(ACO_TEST_SOURCE_DIR) / "docs/writing-plugins.md");
  // The slot table alone: other tables of the page have rows of the same shape.
  const std::size_t header = file.find("\n| slot | interface |");
  REQUIRE(header != std::string::npos);
  const std::string docs = file.substr(header, file.find("\n\n", header) - header);
  // Rows such as "| `init` | `PheromoneInit` | `initialize(context, tau)`: ... | hooks |".
  const std::regex row(R"(\n\| `([a-z]+)` \| `([A-Za-z]+)` \|([^\n]*))");
  std::vector<std::pair<std::string, std::string>> rows;
  for (auto it = std::sregex_iterator(docs.begin(), docs.end(), row); it != std::sregex_iterator(); ++it) {
    rows.emplace_back((*it)[1], (*it)[2]);
    const aco::SlotInfo* slot = aco::find_slot((*it)[1].str());
    if (!slot) continue;
    const std::string rest = (*it)[3];
    INFO("docs row of slot " << slot->name << ": " << rest);
    CHECK(rest.find(std::string("`") + slot->method + "(") != std::string::npos);
    if (*slot->hooks)
      for (const auto& hook : split_hooks(slot->hooks)) CHECK(rest.find(hook + "(") != std::string::npos);
  }
  std::vector<std::pair<std::string, std::string>> table;
  for (const aco::SlotInfo& slot : aco::kSlotTable) table.emplace_back(slot.name, slot.interface);
  CHECK(rows == table);
}

TEST_CASE("aco-new-plugin scaffolds every slot of the table and names them all", "[slots]") {
  const std::string script = read_text(std::filesystem::path(ACO_TEST_SOURCE_DIR) / "tools/new-plugin.sh");
  // Its case labels: "  init) interface=PheromoneInit; ...".
  const std::regex label(R"(\n  ([a-z]+)\) interface=([A-Za-z]+);)");
  std::vector<std::pair<std::string, std::string>> kinds;
  for (auto it = std::sregex_iterator(script.begin(), script.end(), label); it != std::sregex_iterator(); ++it)
    kinds.emplace_back((*it)[1], (*it)[2]);
  std::vector<std::pair<std::string, std::string>> table;
  std::string names;
  for (const aco::SlotInfo& slot : aco::kSlotTable) {
    table.emplace_back(slot.name, slot.interface);
    names += (names.empty() ? "" : ", ") + std::string(slot.name);
  }
  CHECK(kinds == table);
  // The usage line and the message for an unknown KIND list them in the table's order.
  CHECK(script.find("(KIND: " + names + ")") != std::string::npos);
  CHECK(script.find("unknown KIND '$kind' (" + names + ")") != std::string::npos);
}

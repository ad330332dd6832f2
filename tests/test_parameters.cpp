#include <catch2/catch.hpp>

#include "aco/error.hpp"
#include "aco/parameters.hpp"
#include "aco/settings_table.hpp"

using Catch::Contains;

namespace {
constexpr aco::ParamSpec kTable[] = {
    {"rho", aco::ParamType::real, "0.3", "0:1", "evaporation"},
    {"q", aco::ParamType::real, "1", "(0:inf)", "deposit"},
    {"ants", aco::ParamType::integer, "50", "1:1000", "ants"},
    {"greedy", aco::ParamType::boolean, "false", "", "flag"},
    {"mode", aco::ParamType::categorical, "fast", "fast,slow", "mode"},
};
}

TEST_CASE("values are parsed by type and checked against closed and open ranges", "[parameters]") {
  CHECK(std::get<double>(aco::parse_value(kTable[0], "0", "--rho")) == 0.0);
  CHECK(std::get<double>(aco::parse_value(kTable[0], "1", "--rho")) == 1.0);
  REQUIRE_THROWS_WITH(aco::parse_value(kTable[0], "1.5", "--update.rho"),
                      Contains("--update.rho") && Contains("outside the range [0, 1]"));
  REQUIRE_THROWS_WITH(aco::parse_value(kTable[0], "-0.1", "--rho"), Contains("outside the range"));
  REQUIRE_THROWS_WITH(aco::parse_value(kTable[0], "0.3x", "--rho"), Contains("not a finite number"));
  REQUIRE_THROWS_WITH(aco::parse_value(kTable[0], "nan", "--rho"), Contains("not a finite number"));
  REQUIRE_THROWS_WITH(aco::parse_value(kTable[1], "0", "--q"), Contains("outside the range (0, inf)"));
  CHECK(std::get<double>(aco::parse_value(kTable[1], "1e-9", "--q")) == 1e-9);
  CHECK(std::get<std::int64_t>(aco::parse_value(kTable[2], "1", "--ants")) == 1);
  REQUIRE_THROWS_WITH(aco::parse_value(kTable[2], "0", "--ants"), Contains("--ants: 0 is outside the range [1, 1000]"));
  REQUIRE_THROWS_WITH(aco::parse_value(kTable[2], "-5", "--ants"), Contains("outside the range"));
  REQUIRE_THROWS_WITH(aco::parse_value(kTable[2], "2.5", "--ants"), Contains("not a whole number"));
  CHECK(std::get<bool>(aco::parse_value(kTable[3], "yes", "--greedy")));
  CHECK_FALSE(std::get<bool>(aco::parse_value(kTable[3], "false", "--greedy")));
  REQUIRE_THROWS_WITH(aco::parse_value(kTable[3], "maybe", "--greedy"), Contains("not a boolean"));
  CHECK(std::get<std::string>(aco::parse_value(kTable[4], "slow", "--mode")) == "slow");
  REQUIRE_THROWS_WITH(aco::parse_value(kTable[4], "medium", "--mode"), Contains("not one of fast,slow"));
}

TEST_CASE("ranges with a step parse, malformed ranges are refused", "[parameters]") {
  const aco::ParamSpec stepped{"x", aco::ParamType::real, "0.5", "0:0.05:1", "x"};
  const auto range = aco::numeric_range(stepped);
  REQUIRE(range);
  CHECK(range->low == 0.0);
  CHECK(range->high == 1.0);
  CHECK(range->step == 0.05);
  const aco::ParamSpec bad{"x", aco::ParamType::real, "0.5", "1:0", "x"};
  REQUIRE_THROWS_WITH(aco::numeric_range(bad), Contains("malformed range"));
}

TEST_CASE("a parameter table is checked for duplicates and bad defaults", "[parameters]") {
  CHECK_NOTHROW(aco::check_table(kTable, "plugin t"));
  const aco::ParamSpec duplicate[] = {kTable[0], kTable[0]};
  REQUIRE_THROWS_WITH(aco::check_table(duplicate, "plugin t"), Contains("plugin t") && Contains("declared twice"));
  const aco::ParamSpec out_of_range[] = {{"rho", aco::ParamType::real, "2", "0:1", "x"}};
  REQUIRE_THROWS_WITH(aco::check_table(out_of_range, "plugin t"), Contains("bad default"));
  const aco::ParamSpec no_choices[] = {{"m", aco::ParamType::categorical, "a", "", "x"}};
  REQUIRE_THROWS_WITH(aco::check_table(no_choices, "plugin t"), Contains("lists no values"));
}

TEST_CASE("resolve fills defaults, applies overrides and names the nearest key for typos", "[parameters]") {
  const auto values = aco::resolve(kTable, {{"rho", "0.5"}, {"mode", "slow"}}, "--update.");
  CHECK(values.real("rho") == 0.5);
  CHECK(values.real("q") == 1.0);
  CHECK(values.integer("ants") == 50);
  CHECK_FALSE(values.boolean("greedy"));
  CHECK(values.text("mode") == "slow");
  REQUIRE_THROWS_WITH(aco::resolve(kTable, {{"rhoo", "0.5"}}, "--update."),
                      Contains("unknown parameter '--update.rhoo'") && Contains("did you mean '--update.rho'?"));
  REQUIRE_THROWS_WITH(aco::resolve({}, {{"x", "1"}}, "--smoother."), Contains("has no parameters"));
  REQUIRE_THROWS_WITH(values.real("ants"), Contains("not of type real"));
  REQUIRE_THROWS_WITH(values.real("missing"), Contains("not declared"));
}

TEST_CASE("nearest finds close spellings and rejects unrelated words", "[parameters]") {
  const std::vector<std::string> keys{"ants", "iterations", "alpha", "beta", "update.rho"};
  CHECK(aco::nearest("iteration", keys) == "iterations");
  CHECK(aco::nearest("alhpa", keys) == "alpha");
  CHECK(aco::nearest("update.rh", keys) == "update.rho");
  CHECK(aco::nearest("completelydifferent", keys).empty());
}

TEST_CASE("a text parameter takes any string and its table field reads and writes it", "[parameters]") {
  const aco::ParamSpec spec{"class", aco::ParamType::text, "", "", "the object"};
  for (const std::string value : {"", "ant_system:AntSystem", "a b,c:d", "0.5"})
    CHECK(std::get<std::string>(aco::parse_value(spec, value, "--update.class")) == value);
  CHECK(std::string(aco::to_string(aco::ParamType::text)) == "text");
  CHECK(aco::shown_default(spec) == "\"\"");
  CHECK_FALSE(aco::numeric_range(spec));
  CHECK(aco::choices(spec).empty());

  struct Settings {
    std::string object = "m:C";
  };
  const aco::SettingsTable<Settings> table({aco::text_field("class", &Settings::object, "the object")});
  const auto rows = table.parameters();
  REQUIRE(rows.size() == 1);
  CHECK(rows[0].type == aco::ParamType::text);
  CHECK(std::string(rows[0].default_value) == "m:C");
  CHECK(aco::shown_default(rows[0]) == "m:C");
  CHECK_NOTHROW(aco::check_table(rows, "plugin t"));
  const auto values = aco::resolve(rows, {{"class", "pkg.mod:Other"}}, "--update.");
  CHECK(values.text("class") == "pkg.mod:Other");
  CHECK(table.read(values).object == "pkg.mod:Other");
  CHECK(std::get<std::string>(table.write(Settings{}).all().at("class")) == "m:C");
}

TEST_CASE("a settings table's choice refuses a name it does not list", "[parameters]") {
  struct Search {
    bool bidirectional = false;
  };
  const aco::SettingsTable<Search> table(
      {aco::choice("search", &Search::bidirectional, {"single", "bidirectional"}, {false, true}, "how")});
  aco::ParameterValues values;
  values.set("search", std::string("bidirectional"));
  CHECK(table.read(values).bidirectional);
  values.set("search", std::string("both"));
  REQUIRE_THROWS_WITH(table.read(values), Contains("search: 'both' is not one of single,bidirectional"));
}

// The plugin boundary seen from the hosts: plugin records read without loading, compatible and
// incompatible builds, shadowing, corrupted libraries, and the provenance of every run.
#include <elf.h>
#include <link.h>

#include <catch2/catch.hpp>
#include <fstream>
#include <nlohmann/json.hpp>

#include "aco/studies/results_db.hpp"
#include "aco/error.hpp"
#include "aco/engine/plugin_registry.hpp"
#include "support.hpp"

using Catch::Contains;
namespace fs = std::filesystem;

namespace {

const std::string kBundled = ACO_TEST_PLUGIN_DIR;

std::vector<std::string> plan_on_map1(std::vector<std::string> args) {
  const std::vector<std::string> problem{"--map",        (test::data_dir() / "maps/classic20/map1.txt").string(),
                                         "--start",      "0,0",
                                         "--goal",       "19,19",
                                         "--iterations", "10",
                                         "--ants",       "10"};
  args.insert(args.end(), problem.begin(), problem.end());
  return args;
}

// A copy of a library in a fresh folder of its own.
fs::path copy_to_fresh_dir(const fs::path& library) {
  const fs::path copy = test::temp_file("placeholder", "").parent_path() / library.filename();
  fs::copy_file(library, copy);
  return copy;
}

// Overwrites the library's .text section with ud2 instructions: loading it runs its
// initialisers, which then die of SIGILL (on x86-64; elsewhere of whatever the bytes mean).
void corrupt_code(const fs::path& library) {
  std::fstream file(library, std::ios::in | std::ios::out | std::ios::binary);
  ElfW(Ehdr) header;
  file.read(reinterpret_cast<char*>(&header), sizeof header);
  std::vector<ElfW(Shdr)> sections(header.e_shnum);
  file.seekg(static_cast<std::streamoff>(header.e_shoff));
  file.read(reinterpret_cast<char*>(sections.data()),
            static_cast<std::streamsize>(sections.size() * sizeof(ElfW(Shdr))));
  std::string names(sections[header.e_shstrndx].sh_size, '\0');
  file.seekg(static_cast<std::streamoff>(sections[header.e_shstrndx].sh_offset));
  file.read(names.data(), static_cast<std::streamsize>(names.size()));
  for (const auto& s : sections) {
    if (std::string(names.c_str() + s.sh_name) != ".text") continue;
    std::string ud2;
    for (std::size_t i = 0; i + 1 < s.sh_size; i += 2) ud2 += "\x0f\x0b";
    file.seekp(static_cast<std::streamoff>(s.sh_offset));
    file.write(ud2.data(), static_cast<std::streamsize>(ud2.size()));
    return;
  }
  FAIL("no .text section in " << library);
}

std::string sha256sum(const fs::path& file) {
  const auto r = test::run({"/usr/bin/sha256sum", file.string()});
  REQUIRE(r.exit_code == 0);
  return r.out.substr(0, 64);
}

}  // namespace

TEST_CASE("plugin records are read from the library file without loading it", "[registry][records]") {
  const auto records = aco::read_plugin_records(kBundled + "/aco_update_ant_system.so");
  REQUIRE(records.size() == 1);
  const auto& r = records[0];
  CHECK(r.abi == std::to_string(aco::kPluginAbiVersion));
  CHECK(r.slot == "update");
  CHECK(r.name == "ant_system");
  CHECK(r.version == "1.0");
  CHECK_THAT(r.summary, Contains("Ant System"));
  CHECK(r.stdlib == aco::kHostStdlib);
  CHECK(!r.compiler.empty());
  CHECK(aco::incompatibility(r).empty());

  aco::PluginRegistry registry({kBundled});
  CHECK(registry.get("update", "ant_system").record.summary == r.summary);
  REQUIRE_THROWS_WITH(aco::read_plugin_records(test::temp_file("x.so", std::string(100, 'x'))),
                      Contains("is not an ELF file"));
  REQUIRE_THROWS_WITH(aco::read_plugin_records(test::temp_file("short.so",
                                                               "\x7f"
                                                               "ELF")),
                      Contains("truncated"));
}

TEST_CASE("a plugin built with the old libstdc++ string ABI is refused from its record, not loaded",
          "[registry][abi][records]") {
  aco::PluginRegistry registry({ACO_TEST_BAD_PLUGIN_DIR});
  const auto& plugin = registry.get("update", "old_string_abi");
  CHECK_THAT(plugin.unusable, Contains("_GLIBCXX_USE_CXX11_ABI=0") && Contains(aco::kHostStdlib));
  REQUIRE_THROWS_WITH(registry.load("update", "old_string_abi"),
                      Contains("plugin update/old_string_abi") && Contains("old string ABI"));
  const auto run = test::acoplan(plan_on_map1({"--plugin-dir", ACO_TEST_BAD_PLUGIN_DIR, "--update", "old_string_abi"}));
  CHECK(run.exit_code == 1);
  CHECK_THAT(run.err, Contains("_GLIBCXX_USE_CXX11_ABI=0") && !Contains("symbol lookup error"));
  const auto list = test::acoplan({"--plugin-dir", ACO_TEST_BAD_PLUGIN_DIR, "--list-plugins"});
  CHECK(list.exit_code == 0);
  CHECK_THAT(list.out, Contains("update/old_string_abi  UNUSABLE: built with libstdc++ (old string ABI"));
}

TEST_CASE("a plugin built by clang with libstdc++ is accepted and plans", "[registry][abi][records]") {
  aco::PluginRegistry registry({ACO_TEST_CLANG_PLUGIN_DIR});
  const auto& plugin = registry.get("update", "clang_built");
  CHECK_THAT(plugin.record.compiler, Contains("lang"));  // "Debian Clang 14..." or "clang version ..."
  CHECK(plugin.unusable.empty());
  const auto run = test::acoplan(plan_on_map1(
      {"--plugin-dir", ACO_TEST_CLANG_PLUGIN_DIR, "--update", "clang_built", "--update.rho", "0.2", "--json"}));
  REQUIRE(run.exit_code == 0);
  const auto j = nlohmann::json::parse(run.out);
  CHECK(j["solved"] == true);
  CHECK(j["config"]["update.rho"] == 0.2);
  CHECK(j["plugins"]["update"]["file"] == std::string(ACO_TEST_CLANG_PLUGIN_DIR) + "/aco_update_clang_built.so");
}

TEST_CASE("a plugin named like a bundled one shadows it, with a warning, and listing shows both files",
          "[registry][shadowing]") {
  const fs::path bundled = kBundled + "/aco_update_ant_system.so";
  const fs::path mine = copy_to_fresh_dir(bundled);
  const std::string dir = mine.parent_path().string();
  aco::PluginRegistry registry({mine.parent_path(), kBundled});
  const auto& plugin = registry.get("update", "ant_system");
  CHECK(plugin.file == mine);
  CHECK(plugin.shadowed == std::vector<fs::path>{bundled});

  const auto list = test::acoplan({"--plugin-dir", dir, "--list-plugins"});
  REQUIRE(list.exit_code == 0);
  CHECK_THAT(list.out, Contains("update/ant_system  1.0  Ant System") &&
                           Contains(mine.string() + "\n      shadows " + bundled.string() + " (not used"));
  const auto described = test::acoplan({"--plugin-dir", dir, "--describe", "update/ant_system"});
  CHECK_THAT(described.out, Contains("file: " + mine.string() + "\n      shadows " + bundled.string()));

  const auto run = test::acoplan(plan_on_map1({"--plugin-dir", dir, "--update", "ant_system", "--json"}));
  REQUIRE(run.exit_code == 0);
  CHECK_THAT(run.err,
             Contains("warning: plugin update/ant_system from " + mine.string() + " shadows " + bundled.string()));
  CHECK(nlohmann::json::parse(run.out)["plugins"]["update"]["file"] == mine.string());
  // Not using it: no warning.
  const auto other = test::acoplan(plan_on_map1({"--plugin-dir", dir, "--update", "acs"}));
  REQUIRE(other.exit_code == 0);
  CHECK_THAT(other.err, !Contains("shadows"));
}

TEST_CASE("a corrupted plugin library is listed from its record and refused when used, without crashing the host",
          "[registry][records][bad-input]") {
  const fs::path library = copy_to_fresh_dir(std::string(ACO_TEST_FAULTY_PLUGIN_DIR) + "/aco_update_throwing.so");
  corrupt_code(library);
  const std::string dir = library.parent_path().string();

  const auto list = test::acoplan({"--plugin-dir", dir, "--list-plugins"});
  CHECK(list.exit_code == 0);
  CHECK_THAT(list.out, Contains("update/throwing  1.0  throws an int") && Contains("update/ant_system"));

  const auto dump = test::acoplan({"--plugin-dir", dir, "--dump-irace-params", "-"});
  CHECK(dump.exit_code == 0);
  CHECK_THAT(dump.out, Contains("# skipped update/throwing: plugin update/throwing (" + library.string() +
                                "): crashed while loading (signal "));
  CHECK_THAT(dump.out, Contains("update \"--update \" c (acs, ant_system"));

  for (const auto& args : {plan_on_map1({"--plugin-dir", dir, "--update", "throwing"}),
                           std::vector<std::string>{"--plugin-dir", dir, "--describe", "update/throwing"}}) {
    const auto r = test::acoplan(args);
    CHECK(r.exit_code == 1);
    CHECK_THAT(r.err, Contains("plugin update/throwing (" + library.string() + "): crashed while loading (signal ") &&
                          Contains("rebuild or remove it"));
  }
}

TEST_CASE("every run's JSON names each slot's plugin, version, file and content hash", "[acoplan][provenance]") {
  const auto run = test::acoplan(plan_on_map1({"--update", "max_min", "--json"}));
  REQUIRE(run.exit_code == 0);
  const auto plugins = nlohmann::json::parse(run.out)["plugins"];
  REQUIRE(plugins.size() == aco::kSlots.size());
  for (const char* slot : aco::kSlots) {
    INFO(slot);
    const auto& p = plugins[slot];
    CHECK(p["version"] == "1.0");
    const fs::path file = p["file"].get<std::string>();
    CHECK(file.filename() == "aco_" + std::string(slot) + "_" + p["name"].get<std::string>() + ".so");
    CHECK(p["sha256"] == sha256sum(file));
  }
  CHECK(plugins["update"]["name"] == "max_min");
}

TEST_CASE("acobench records plugin hashes and refuses to resume with a changed plugin binary, naming it",
          "[acobench][provenance]") {
  const fs::path plugin = copy_to_fresh_dir(kBundled + "/aco_update_acs.so");
  const fs::path file =
      test::temp_file("experiment.yaml", "name: rebuilt\nseed: 3\nrepetitions: 2\nproblems:\n  - map: " +
                                             (test::data_dir() / "maps/classic20/map1.txt").string() +
                                             "\n    start: [0, 0]\n    goal: [19, 19]\n"
                                             "settings: {ants: 8, iterations: 8}\n"
                                             "baseline: {name: ACS, update: acs}\n");
  const fs::path db = file.parent_path() / "results.db";
  const std::vector<std::string> args{
      ACO_TEST_ACOBENCH, "run", file.string(), "--db", db.string(), "--plugin-dir", plugin.parent_path().string()};
  const auto first = test::run(args);
  REQUIRE(first.exit_code == 0);
  const auto configs = aco::studies::ResultsDb(db).configs();
  REQUIRE(configs.size() == 1);
  const auto stored = nlohmann::json::parse(configs[0].second.settings_json)["plugins"]["update"];
  CHECK(stored["name"] == "acs");
  CHECK(stored["sha256"] == sha256sum(plugin));
  CHECK(test::run(args).exit_code == 0);  // the same binary: resumes (nothing left to run)

  // "Rebuilt" with other contents (an ELF file ignores bytes appended to it).
  std::ofstream(plugin, std::ios::app | std::ios::binary) << "another build";
  const auto resumed = test::run(args);
  CHECK(resumed.exit_code == 1);
  CHECK_THAT(resumed.err, Contains("another binary of plugin update/acs") && Contains(sha256sum(plugin)) &&
                              Contains(stored["sha256"].get<std::string>()) && Contains("nothing in it was changed"));
}

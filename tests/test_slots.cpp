// The slot table (aco/slots.hpp) is the one list of slots: the pipeline, the scaffolding tool and
// the docs' slot table must say what it says, the interfaces must have the hooks it lists, and
// the error boundary (aco/engine/plugin_guard.hpp) must forward every one of them.
#include <catch2/catch.hpp>

#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "aco/engine/pipeline.hpp"
#include "aco/engine/plugin_guard.hpp"
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

// Every hook of a slot's interface: Strategy's (begin_run) and the table's method and hooks.
std::set<std::string> table_hooks(const aco::SlotInfo& slot) {
  std::set<std::string> hooks{"begin_run", "supports_voxel_worlds", slot.method};
  if (*slot.hooks)
    for (const auto& hook : split_hooks(slot.hooks)) hooks.insert(hook);
  return hooks;
}

// The virtual functions a class of the framework's headers declares, destructors aside, read from
// its body: "virtual void compute(" gives "compute".
std::set<std::string> declared_virtuals(const std::string& interface) {
  const auto include = std::filesystem::path(ACO_TEST_SOURCE_DIR) / "core/include/aco";
  const std::string headers = read_text(include / "strategies.hpp") + read_text(include / "map_reader.hpp");
  const std::size_t begin = headers.find("class BOOST_SYMBOL_VISIBLE " + interface + " ");
  REQUIRE(begin != std::string::npos);
  const std::string body = headers.substr(begin, headers.find("\n};", begin) - begin);
  const std::regex declaration(R"(\bvirtual [^;{]*?\b([a-z_]+)\()");
  std::set<std::string> names;
  for (auto it = std::sregex_iterator(body.begin(), body.end(), declaration); it != std::sregex_iterator(); ++it)
    names.insert((*it)[1]);
  return names;
}

// Stands in a slot and notes every hook called on it. Each slot's probe overrides every hook of
// its interface (the interface's count of virtuals is checked against the table below).
template <class Interface>
class Probe : public Interface {
 public:
  void begin_run(const aco::Context&) override { note("begin_run"); }
  bool supports_voxel_worlds() const override {
    note("supports_voxel_worlds");
    return false;
  }
  void note(const char* hook) const { called->insert(hook); }
  std::shared_ptr<std::set<std::string>> called = std::make_shared<std::set<std::string>>();
};

struct InitProbe final : Probe<aco::PheromoneInit> {
  void initialize(const aco::Context&, std::span<double>) override { note("initialize"); }
};
struct HeuristicProbe final : Probe<aco::Heuristic> {
  void compute(const aco::Context&, std::span<double>) override { note("compute"); }
  aco::HeuristicSpecs specs() const override {
    note("specs");
    return {};
  }
  void compute_powered(const aco::Context&, std::span<double>) override { note("compute_powered"); }
  void update_node(const aco::Context&, aco::NodeId, int, std::span<double>) const override { note("update_node"); }
  void step_factors(const aco::Context&, const aco::Ant&, std::span<const aco::EdgeId>,
                    std::span<double>) const override {
    note("step_factors");
  }
};
struct UpdateProbe final : Probe<aco::PheromoneUpdate> {
  void update(const aco::Context&, const aco::Iteration&, std::span<double>) override { note("update"); }
  void start(const aco::Context&, std::span<double>) override { note("start"); }
  void update_trail(const aco::Context&, const aco::Iteration&, aco::Trail&) override { note("update_trail"); }
};
struct DeadlockProbe final : Probe<aco::DeadlockPolicy> {
  int on_stuck(const aco::Context&, std::span<const aco::NodeId>) const override {
    note("on_stuck");
    return 0;
  }
  void after_iteration(const aco::Context&, const aco::Iteration&, aco::Trail&, std::vector<std::uint8_t>&) override {
    note("after_iteration");
  }
};
struct SmootherProbe final : Probe<aco::Smoother> {
  std::vector<Eigen::Vector3d> smooth(const aco::Context&, std::span<const aco::NodeId>) const override {
    note("smooth");
    return {};
  }
};
struct LocalProbe final : Probe<aco::LocalPlanner> {
  aco::VelocityCommand command(const aco::LocalView&) override {
    note("command");
    return {};
  }
};
struct MapProbe final : Probe<aco::MapReader> {
  std::unique_ptr<aco::Map> read(const std::filesystem::path&, const aco::TerrainOptions&) const override {
    note("read");
    return nullptr;
  }
  std::vector<std::string> extensions() const override {
    note("extensions");
    return {};
  }
  std::string sample() const override {
    note("sample");
    return {};
  }
};

// Calls every hook of the interface once, as a host would through the guard.
const aco::Context kContext{};
void call_every_hook(aco::PheromoneInit& p) {
  p.begin_run(kContext);
  p.initialize(kContext, {});
}
void call_every_hook(aco::Heuristic& p) {
  p.begin_run(kContext);
  p.compute(kContext, {});
  (void)p.specs();
  p.compute_powered(kContext, {});
  p.update_node(kContext, 0, 0, {});
  p.step_factors(kContext, aco::Ant{}, {}, {});
}
void call_every_hook(aco::PheromoneUpdate& p) {
  aco::Trail trail({});
  p.begin_run(kContext);
  p.update(kContext, {}, {});
  p.start(kContext, {});
  p.update_trail(kContext, {}, trail);
}
void call_every_hook(aco::DeadlockPolicy& p) {
  aco::Trail trail({});
  std::vector<std::uint8_t> forbidden;
  p.begin_run(kContext);
  (void)p.on_stuck(kContext, {});
  p.after_iteration(kContext, {}, trail, forbidden);
}
void call_every_hook(aco::Smoother& p) {
  p.begin_run(kContext);
  (void)p.smooth(kContext, {});
}
void call_every_hook(aco::LocalPlanner& p) {
  p.begin_run(kContext);
  (void)p.command(aco::LocalView{});
}
void call_every_hook(aco::MapReader& p) {
  p.begin_run(kContext);
  (void)p.read("map", {});
  (void)p.extensions();
  (void)p.sample();
}

template <class Interface>
std::set<std::string> hooks_reaching_the_plugin(std::unique_ptr<Probe<Interface>> probe) {
  const auto called = probe->called;
  const std::unique_ptr<Interface> guarded =
      aco::guard(std::unique_ptr<Interface>(std::move(probe)), {"slot", "probe", ""});
  (void)guarded->supports_voxel_worlds();
  call_every_hook(*guarded);
  return *called;
}

}  // namespace

TEST_CASE("every slot's interface declares the hooks the slot table lists, and Strategy its two", "[slots][guard]") {
  CHECK(declared_virtuals("Strategy") == std::set<std::string>{"begin_run", "supports_voxel_worlds"});
  for (const aco::SlotInfo& slot : aco::kSlotTable) {
    INFO("slot " << slot.name << ", interface " << slot.interface);
    std::set<std::string> declared = declared_virtuals(slot.interface);
    declared.insert({"begin_run", "supports_voxel_worlds"});
    CHECK(declared == table_hooks(slot));
  }
}

// A hook the guard's decorator does not forward runs the interface's default on the decorator,
// and the plugin never hears of it. With the test above, a new virtual fails here until the
// decorator forwards it (and its slot's probe and call_every_hook know it).
TEST_CASE("the error boundary forwards every hook of every slot to the plugin", "[slots][guard]") {
  const std::map<std::string, std::set<std::string>> reached{
      {"init", hooks_reaching_the_plugin<aco::PheromoneInit>(std::make_unique<InitProbe>())},
      {"heuristic", hooks_reaching_the_plugin<aco::Heuristic>(std::make_unique<HeuristicProbe>())},
      {"update", hooks_reaching_the_plugin<aco::PheromoneUpdate>(std::make_unique<UpdateProbe>())},
      {"deadlock", hooks_reaching_the_plugin<aco::DeadlockPolicy>(std::make_unique<DeadlockProbe>())},
      {"smoother", hooks_reaching_the_plugin<aco::Smoother>(std::make_unique<SmootherProbe>())},
      {"local", hooks_reaching_the_plugin<aco::LocalPlanner>(std::make_unique<LocalProbe>())},
      {"map", hooks_reaching_the_plugin<aco::MapReader>(std::make_unique<MapProbe>())},
  };
  CHECK(reached.size() == std::size(aco::kSlotTable));
  for (const aco::SlotInfo& slot : aco::kSlotTable) {
    INFO("slot " << slot.name);
    REQUIRE(reached.count(slot.name) == 1);
    CHECK(reached.at(slot.name) == table_hooks(slot));
  }
}

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
  std::vector<std::pair<std::string, std::string>> scaffolded;
  for (auto it = std::sregex_iterator(script.begin(), script.end(), label); it != std::sregex_iterator(); ++it)
    scaffolded.emplace_back((*it)[1], (*it)[2]);
  std::vector<std::pair<std::string, std::string>> table;
  std::string names;
  for (const aco::SlotInfo& slot : aco::kSlotTable) {
    table.emplace_back(slot.name, slot.interface);
    names += (names.empty() ? "" : ", ") + std::string(slot.name);
  }
  CHECK(scaffolded == table);
  // The usage line and the message for an unknown SLOT list them in the table's order.
  CHECK(script.find("(SLOT: " + names + ")") != std::string::npos);
  CHECK(script.find("unknown SLOT '$slot' (" + names + ")") != std::string::npos);
}

#include "trial_messages.hpp"

namespace acobench {

using nlohmann::json;

nlohmann::json record_json(const TrialRecord& t) {
  json j = {{"problem", t.problem},     {"config", t.config},       {"repetition", t.repetition},
            {"seed", t.seed},           {"solved", t.solved},       {"length", t.length},
            {"grid_length", t.grid_length}, {"turns", t.turns},     {"iterations", t.iterations},
            {"best_iteration", t.best_iteration}, {"time", t.time_s}, {"ant_steps", t.ant_steps},
            {"stopped_by", t.stopped_by}, {"path", t.path_json},    {"best_so_far", t.best_so_far},
            {"elapsed_s", t.elapsed_s}, {"walks", t.walks},         {"error", t.error},
            {"failure", t.failure}};
  json& properties = j["properties"] = json::object();
  for (const auto& [name, value] : t.properties) properties[name] = std::visit([](const auto& v) { return json(v); }, value);
  if (const auto& s = t.simulation)
    j["simulation"] = {{"outcome", s->outcome},   {"time_to_goal", s->time_to_goal}, {"collisions", s->collisions},
                       {"replans", s->replans},   {"clearance", s->clearance},       {"control_steps", s->control_steps}};
  return j;
}

TrialRecord record_from(const nlohmann::json& j) {
  TrialRecord t;
  t.problem = j.at("problem");
  t.config = j.at("config");
  t.repetition = j.at("repetition");
  t.seed = j.at("seed");
  t.solved = j.at("solved");
  t.length = j.at("length");
  t.grid_length = j.at("grid_length");
  t.turns = j.at("turns");
  t.iterations = j.at("iterations");
  t.best_iteration = j.at("best_iteration");
  t.time_s = j.at("time");
  t.ant_steps = j.at("ant_steps");
  t.stopped_by = j.at("stopped_by");
  t.path_json = j.at("path");
  t.best_so_far = j.at("best_so_far").get<std::vector<double>>();
  t.elapsed_s = j.at("elapsed_s").get<std::vector<double>>();
  t.walks = j.at("walks").get<std::vector<std::uint64_t>>();
  t.error = j.at("error");
  t.failure = j.at("failure");
  for (const auto& [name, value] : j.at("properties").items()) {
    if (value.is_boolean()) t.properties[name] = value.get<bool>();
    else if (value.is_number_integer()) t.properties[name] = value.get<std::int64_t>();
    else if (value.is_number()) t.properties[name] = value.get<double>();
    else t.properties[name] = value.get<std::string>();
  }
  if (j.contains("simulation")) {
    const json& s = j.at("simulation");
    t.simulation = SimulationRecord{s.at("outcome"), s.at("time_to_goal"), s.at("collisions"),
                                    s.at("replans"), s.at("clearance"),    s.at("control_steps")};
  }
  return t;
}

nlohmann::json order_json(const TrialOrder& t) { return {t.problem, t.config, t.repetition}; }

TrialOrder order_from(const nlohmann::json& j) { return {j.at(0), j.at(1), j.at(2)}; }

nlohmann::json config_json(int id, const Configuration& c) { return {{"id", id}, {"name", c.name}, {"keys", c.keys}}; }

void add_config_from(const nlohmann::json& j, TrialRunner& runner) {
  Configuration config;
  config.name = j.at("name");
  config.keys = j.at("keys").get<aco::Keys>();
  runner.add_config(j.at("id"), config);
}

}  // namespace acobench

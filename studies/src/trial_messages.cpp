#include "trial_messages.hpp"

namespace aco::studies {

using nlohmann::json;

namespace {

json to_json(const TrialCell& value) {
  return std::visit(
      [](const auto& v) -> json {
        if constexpr (std::is_same_v<std::decay_t<decltype(v)>, std::monostate>)
          return nullptr;
        else
          return v;
      },
      value);
}

TrialCell from_json(const json& value, TrialCellType type) {
  if (value.is_null()) return {};
  switch (type) {
    case TrialCellType::boolean:
      return value.get<bool>();
    case TrialCellType::integer:
      return value.get<std::int64_t>();
    case TrialCellType::count:
      return value.get<std::uint64_t>();
    case TrialCellType::real:
      return value.get<double>();
    case TrialCellType::text:
      break;
  }
  return value.get<std::string>();
}

}  // namespace

nlohmann::json record_json(const TrialRecord& t) {
  json j = {{"problem", t.problem},
            {"config", t.config},
            {"best_so_far", t.best_so_far},
            {"elapsed_s", t.elapsed_s},
            {"walks", t.walks}};
  for (const auto& f : trial_fields())
    if (f.use & kInMessage) j[f.name] = to_json(f.get(t, -1.0));
  json& properties = j["properties"] = json::object();
  for (const auto& [name, value] : t.properties)
    properties[name] = std::visit([](const auto& v) { return json(v); }, value);
  return j;
}

TrialRecord record_from(const nlohmann::json& j) {
  TrialRecord t;
  t.problem = j.at("problem");
  t.config = j.at("config");
  t.best_so_far = j.at("best_so_far").get<std::vector<double>>();
  t.elapsed_s = j.at("elapsed_s").get<std::vector<double>>();
  t.walks = j.at("walks").get<std::vector<std::uint64_t>>();
  for (const auto& f : trial_fields())
    if (f.use & kInMessage) f.set(t, from_json(j.at(f.name), f.type));
  for (const auto& [name, value] : j.at("properties").items()) {
    if (value.is_boolean())
      t.properties[name] = value.get<bool>();
    else if (value.is_number_integer())
      t.properties[name] = value.get<std::int64_t>();
    else if (value.is_number())
      t.properties[name] = value.get<double>();
    else
      t.properties[name] = value.get<std::string>();
  }
  return t;
}

nlohmann::json order_json(const TrialOrder& t) {
  nlohmann::json j = {t.problem, t.config, t.repetition};
  if (t.time_limit_s > 0.0) j.push_back(t.time_limit_s);
  return j;
}

TrialOrder order_from(const nlohmann::json& j) {
  return {j.at(0), j.at(1), j.at(2), j.size() > 3 ? j.at(3).get<double>() : 0.0};
}

nlohmann::json config_json(int id, const Configuration& c) { return {{"id", id}, {"name", c.name}, {"keys", c.keys}}; }

void add_config_from(const nlohmann::json& j, TrialRunner& runner) {
  Configuration config;
  config.name = j.at("name");
  config.keys = j.at("keys").get<aco::Keys>();
  runner.add_config(j.at("id"), config);
}

}  // namespace aco::studies

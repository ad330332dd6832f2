#pragma once
// What goes between processes (MPI ranks, worker processes) about trials: orders, the
// configurations they need, records. JSON sent as CBOR, which keeps every double's bits,
// infinities and NaN included.
#include <nlohmann/json.hpp>

#include "aco/studies/trial_record.hpp"
#include "aco/studies/trial_runner.hpp"

namespace aco::studies {

nlohmann::json record_json(const TrialRecord& record);
TrialRecord record_from(const nlohmann::json& message);

// [problem, config, repetition].
nlohmann::json order_json(const TrialOrder& order);
TrialOrder order_from(const nlohmann::json& message);

// A configuration as the receiver prepares it: its id, name and keys (it resolves them itself).
nlohmann::json config_json(int id, const Configuration& config);
// Prepares the configuration of `message` in `runner`.
void add_config_from(const nlohmann::json& message, TrialRunner& runner);

}  // namespace aco::studies

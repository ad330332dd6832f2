#pragma once
// A trial's record as a message between processes (MPI ranks, worker processes): JSON sent as
// CBOR, which keeps every double's bits, infinities and NaN included.
#include <nlohmann/json.hpp>

#include "aco/studies/trial_record.hpp"

namespace acobench {

nlohmann::json record_json(const TrialRecord& record);
TrialRecord record_from(const nlohmann::json& message);

}  // namespace acobench

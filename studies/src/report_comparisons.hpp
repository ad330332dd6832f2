#pragma once
// The report's comparisons of configurations in pairs: each with its null-model twins, and each
// OMPL configuration given another's time with that configuration, trial by trial.
#include <vector>

#include "aco/studies/report_document.hpp"
#include "report_analysis.hpp"

namespace aco::studies {

// Each configuration against its null models (docs/learning.md), found by their settings: a
// twin is a configuration whose resolved settings equal the subject's but for null-model.
std::vector<Table> pheromone_tables(const Analysis& a);

// Each OMPL configuration with time-limit-from against the configuration whose time it was given,
// trial by trial (the same problem and repetition): who is shorter at the same time.
std::vector<Table> equal_time_tables(const Analysis& a);

}  // namespace aco::studies

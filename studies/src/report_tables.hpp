#pragma once
// The report's tables (report_comparisons.hpp has those comparing configurations in pairs) and its
// warnings; report.cpp puts them in the document.
#include <cstddef>
#include <string>
#include <vector>

#include "aco/studies/report_document.hpp"
#include "report_analysis.hpp"

namespace aco::studies {

// A problem's summary: each configuration's runs, success, lengths, gaps, tests and times.
Table problem_table(const Analysis& a, std::size_t p);
// The tables over all problems: failed trials, run properties and plugin figures, simulations,
// the comparisons in pairs, and with several problems per set the summary per set and the gap by
// difficulty bucket.
std::vector<Table> summary_tables(const Analysis& a);
// Per configuration and target: how many of its runs on the problems with a known optimum came
// within the target, and how fast.
std::vector<Table> anytime_tables(const Analysis& a);
// The runs of OMPL benchmark logs appended to the database (ompl_benchmark_statistics -a), per
// experiment and planner, in the measures every planner has.
std::vector<Table> appended_tables(const Analysis& a);
// The configurations by average rank across problems (none without ranks).
std::vector<Table> ranking_tables(const Analysis& a);
// The ablation path's steps and their mean gaps (none without an ablation path).
std::vector<Table> ablation_tables(const Analysis& a);
// The plugin binary of each slot of each configuration.
std::vector<Table> provenance_tables(const Analysis& a);
// Unoptimised (Debug) builds the trials ran: the host, and each plugin binary with the
// configurations that ran it.
std::vector<std::string> build_warnings(const Analysis& a);

}  // namespace aco::studies

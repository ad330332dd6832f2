#pragma once
// Helpers of the acobench tests: experiment files in fresh folders, running the acobench binary,
// and reading results databases back for comparison.
#include <filesystem>
#include <string>
#include <vector>

#include "aco/studies/experiment.hpp"
#include "support.hpp"

namespace test::acobench_helpers {

std::string map1();  // data/maps/classic20/map1.txt

// An experiment file in a fresh folder; {MAP1} and {ARENA} stand for absolute paths.
std::filesystem::path experiment(const std::string& text);
aco::studies::Experiment load(const std::string& text);

// Four configurations (AS, ACS, beta=3, beta=7) of 4 repetitions on map1: 16 quick trials.
extern const char* const kSmall;

// kSmall without the factorial, with 150 repetitions of heavier trials: 300 trials of a few ms,
// enough that a process killed once some are stored is killed mid-way.
std::string kill_me_text();

// Waits until `db` holds at least `count` trials; gives up after a minute rather than hang.
void wait_for_trials(const std::filesystem::path& db, int count);

test::CommandResult run_acobench(const std::vector<std::string>& args, const std::vector<std::string>& env = {});

std::string file_bytes(const std::filesystem::path& file);

// Every trial's identity and results, ordered, without the times.
std::vector<std::string> trial_rows(const std::filesystem::path& db);

// The whole database as text rows (the runs' properties and plugin figures included), read with
// SQLite alone, without what may differ between two runs of one experiment: row ids, times, the
// creation date and host. Two databases of the same
// trials give the same rows whatever order the trials were stored in.
std::vector<std::string> database_rows(const std::filesystem::path& db);

// The first column of the first row of a query, as text ("NULL" for NULL, "(no row)" where the
// file or the query gives none), read with SQLite alone.
std::string sql_value(const std::filesystem::path& db, const std::string& sql);

// Runs statements that return no rows on the file directly with SQLite (a test failure if one fails).
void sql_exec(const std::filesystem::path& db, const std::string& sql);

int count_runs(const std::filesystem::path& db);  // -1 where the file holds no runs table

// Rewrites a database this acobench made into the layout of format 6 (before OMPL's layout: the
// text of ENUMs, the free text and plugins in their old columns, no limits), as an acobench of
// format 6 would have stored the same trials. Tests of older formats start from it.
void downgrade_to_format_6(const std::filesystem::path& db);

#ifdef ACO_TEST_MPIEXEC
// mpirun refuses to start as root unless told twice; CI runs as root.
extern const std::vector<std::string> kMpiEnvironment;
// mpirun -n RANKS acobench ARGS... (run with kMpiEnvironment).
std::vector<std::string> mpirun(int ranks, const std::vector<std::string>& args);
#endif

}  // namespace test::acobench_helpers

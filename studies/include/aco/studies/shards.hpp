#pragma once
// Shards: deterministic slices of an experiment's trials, each run into its own database (a
// scheduler's job array, one task per shard), and the merge of those databases.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace aco::studies {

// Shard `index` of `count` (1-based, as `--shard 2/3` is written). The configurations' trials
// are numbered configuration by configuration, problem by problem, repetition by repetition
// (fixed_trial_index); shard K holds those whose number is K-1 modulo N, so every shard gets a
// share of every configuration and problem.
struct Shard {
  int index = 1;
  int count = 1;
  bool owns(std::size_t trial_index) const { return static_cast<int>(trial_index % count) == index - 1; }
};

// "K/N" with 1 <= K <= N; anything else is an aco::Error showing the form.
Shard parse_shard(const std::string& text);
std::string to_string(const Shard& shard);
// How many of `trials` consecutive trial numbers (from 0) the shard holds.
std::size_t shard_size(const Shard& shard, std::size_t trials);

std::size_t fixed_trial_index(std::size_t config_position, std::size_t problem, std::size_t repetition,
                              std::size_t problems, std::size_t repetitions);

struct MergeSummary {
  std::size_t copied = 0;  // trials written to the output
  std::size_t duplicates = 0;  // trials held by more than one input (or already in the output), identical
  std::size_t expected = 0;  // trials of the experiment's configurations
  std::size_t missing = 0;  // of those, in no input
  // Per shard (or "unsharded input"): how many of its trials are missing, with the command
  // that runs them, for the messages.
  std::vector<std::string> missing_by_shard;
  bool ablation_left = false;  // the experiment has an ablation path, which shards do not run
};

// Copies the trials of `inputs` (results databases of one experiment: shards, or any runs of it)
// into `output`, created or, if it holds the same experiment, added to. Refused with an
// aco::Error, before anything is written, when an input holds another experiment (another file,
// or other plugin binaries) or when two inputs hold the same trial with different results.
MergeSummary merge_databases(const std::vector<std::filesystem::path>& inputs, const std::filesystem::path& output);

}  // namespace aco::studies

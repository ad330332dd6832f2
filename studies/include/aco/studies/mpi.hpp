#pragma once
// acobench under MPI (mpirun -n N acobench run ..., or srun): rank 0 reads and writes the
// results database and hands out trials on demand; every other rank runs the trials it is handed
// on its own threads and sends back the records. The database is the one a single process
// writes, trial for trial: a trial's record depends only on the experiment and its seed.
#include <algorithm>
#include <cstdlib>
#include <memory>
#include <string>

#include "aco/engine/plugin_registry.hpp"
#include "aco/studies/experiment.hpp"
#include "aco/studies/runner.hpp"
#include "aco/studies/trial_workers.hpp"

namespace aco::studies::mpi {

// Whether an MPI launcher started this process (mpirun of Open MPI or MPICH, Slurm's srun with
// PMI-2 or PMIx), from the variables it sets; known before MPI is initialised.
inline bool started_by_launcher() {
  for (const char* variable : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMI_RANK", "PMIX_RANK"})
    if (std::getenv(variable)) return true;
  return false;
}

// How many processes the launcher started, where its environment says (Open MPI's mpirun,
// PMI-2); 1 otherwise. An acobench built without MPI refuses to be one of several copies, which
// would each run every trial into one database.
inline int launched_ranks() {
  for (const char* variable : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"})
    if (const char* value = std::getenv(variable)) return std::max(1, std::atoi(value));
  return 1;
}

#ifdef ACOBENCH_WITH_MPI
// MPI initialised for the process's life, when built with it and started by a launcher.
class Session {
 public:
  Session();
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;
  int rank() const { return rank_; }
  int size() const { return size_; }
  // Ends every rank of the job with `code` (mpirun reports it): the way out for a rank that
  // failed, which the others would otherwise wait for forever.
  [[noreturn]] void abort(int code) const;

 private:
  int rank_ = 0;
  int size_ = 1;
};

// Rank 0's executor: trials go to the worker ranks as they ask for work, the records come back.
class Coordinator : public TrialExecutor {
 public:
  // `fingerprint`: the experiment's; a worker that loaded another one (another file, other plugin
  // binaries on its node) ends the job with a message naming its host.
  Coordinator(const Session& session, std::string fingerprint);
  ~Coordinator() override;
  void run(TrialRunner& runner, const TrialSequence& trials,
           const std::function<void(const TrialRecord&)>& finished) override;
  // Tells every worker there is no more work (once each has asked for more), so they exit.
  void finish();
  // Seconds the coordinator spent handling messages (not waiting for them), and of those, storing
  // the records in the database (which one process does too): the rest is MPI's overhead.
  double busy_seconds() const;
  double storing_seconds() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

// Warns when the launcher bound this rank to fewer CPUs than it would use (`threads`, 0 = all).
void warn_if_bound(const Session& session, int threads);

// A worker rank: runs the trials rank 0 hands out until told to stop: in `workers`' processes,
// one trial per worker, or on `threads` threads (0 = every CPU it may use) when it is nullptr
// (--in-process).
void serve_trials(const Session& session, const Experiment& experiment, aco::PluginRegistry& registry, int threads,
                  TrialWorkers* workers);
#endif

}  // namespace aco::studies::mpi

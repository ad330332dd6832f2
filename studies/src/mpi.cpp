#include "aco/studies/mpi.hpp"

#include <mpi.h>

#include <chrono>
#include <condition_variable>
#include <deque>
#include <iostream>
#include <mutex>
#include <optional>
#include <nlohmann/json.hpp>
#include <set>
#include <thread>

#include "aco/error.hpp"
#include "aco/machine.hpp"
#include "aco/thread_limit.hpp"
#include "aco/studies/provenance.hpp"
#include "trial_messages.hpp"

namespace aco::studies::mpi {
namespace {

using nlohmann::json;

// Worker -> coordinator: {"want": n, "records": [...]}, the first also {"hello": {...}}.
// Coordinator -> worker: {"configs": [...], "trials": [[problem, config, repetition(, time limit)], ...]}.
constexpr int kToCoordinator = 1, kWork = 2, kStop = 3;

// Messages are CBOR: it keeps every double's bits, infinities and NaN included, which the
// records' best-so-far curves and simulation measures hold (and the measured times, which the
// coordinator stores as the worker measured them).
void send(const json& message, int to, int tag) {
  const std::vector<std::uint8_t> bytes = json::to_cbor(message);
  MPI_Send(bytes.data(), static_cast<int>(bytes.size()), MPI_BYTE, to, tag, MPI_COMM_WORLD);
}

struct Received {
  int from = 0, tag = 0;
  json message;
};

// The next message from `from` (MPI_ANY_SOURCE: anyone), if one has arrived.
std::optional<Received> try_receive(int from) {
  int arrived = 0;
  MPI_Status status;
  MPI_Iprobe(from, MPI_ANY_TAG, MPI_COMM_WORLD, &arrived, &status);
  if (!arrived) return std::nullopt;
  int size = 0;
  MPI_Get_count(&status, MPI_BYTE, &size);
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(size));
  MPI_Recv(bytes.data(), size, MPI_BYTE, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return Received{status.MPI_SOURCE, status.MPI_TAG, bytes.empty() ? json() : json::from_cbor(bytes)};
}

// Blocking MPI calls spin on a core (Open MPI's default); the ranks poll and sleep instead,
// briefly at first, so the cores run trials.
class Backoff {
 public:
  void idle() {
    std::this_thread::sleep_for(wait_);
    longer();
  }
  void longer() { wait_ = std::min(wait_ * 2, std::chrono::microseconds(1000)); }
  void busy() { wait_ = std::chrono::microseconds(20); }
  std::chrono::microseconds wait() const { return wait_; }

 private:
  std::chrono::microseconds wait_{20};
};

Received receive(int from) {
  Backoff backoff;
  for (;;) {
    if (auto message = try_receive(from)) return std::move(*message);
    backoff.idle();
  }
}

}  // namespace

Session::Session() {
  int provided = 0;
  // Only the main thread of a rank calls MPI.
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

Session::~Session() { MPI_Finalize(); }

void Session::abort(int code) const {
  std::cerr.flush();
  MPI_Abort(MPI_COMM_WORLD, code);
  std::_Exit(code);  // MPI_Abort does not return; this is for the compiler
}

namespace {

// A batch's trials in their numbers' order, made one ahead of the one handed out.
class Pending {
 public:
  explicit Pending(const TrialSequence& trials) : trials_(trials) {}
  bool any() {
    while (!ahead_ && next_ < trials_.count) ahead_ = trials_.at(next_++);
    return ahead_.has_value();
  }
  TrialOrder take() {
    any();
    const TrialOrder t = *ahead_;
    ahead_.reset();
    return t;
  }
  // No fewer than the trials left: some of those not yet numbered may be stored already.
  std::size_t left() const { return (ahead_ ? 1 : 0) + trials_.count - next_; }

 private:
  const TrialSequence& trials_;
  std::size_t next_ = 0;
  std::optional<TrialOrder> ahead_;
};

}  // namespace

struct Coordinator::State {
  const Session& session;
  std::string fingerprint;
  std::deque<std::pair<int, int>> waiting;  // (rank, trials wanted) of workers that asked for work
  std::map<int, std::set<int>> known;  // per rank: the configuration ids it has been sent
  std::set<int> greeted;  // ranks whose fingerprint was checked
  std::chrono::steady_clock::duration busy{}, stored{};  // handling messages; of that, storing records

  int workers() const { return session.size() - 1; }

  // Records go to `finished`; a request for work waits in `waiting`.
  void handle(const Received& m, std::size_t& outstanding, const std::function<void(const TrialRecord&)>& finished) {
    const auto began = std::chrono::steady_clock::now();
    if (m.message.contains("hello")) greet(m.from, m.message.at("hello"));
    for (const json& r : m.message.at("records")) {
      --outstanding;
      TrialRecord record = record_from(r);
      const auto storing = std::chrono::steady_clock::now();
      finished(record);
      stored += std::chrono::steady_clock::now() - storing;
    }
    if (const int want = m.message.at("want"); want > 0) waiting.emplace_back(m.from, want);
    busy += std::chrono::steady_clock::now() - began;
  }

  void greet(int rank, const json& hello) {
    greeted.insert(rank);
    if (hello.at("fingerprint") == fingerprint) return;
    std::cerr << "acobench: error: rank " << rank << " on host " << hello.at("host").get<std::string>()
              << " loaded another experiment than rank 0 on " << aco::hostname() << ": "
              << fingerprint_change(fingerprint, hello.at("fingerprint"))
              << " (every rank must see the same experiment file, maps and plugin binaries)\n";
    session.abort(1);
  }

  // Hands trials to the workers that asked, each at most its share of what is left (at most the
  // trials not yet numbered), so the last trials spread over the workers.
  void serve(TrialRunner& runner, Pending& queue, std::size_t& outstanding) {
    while (!waiting.empty() && queue.any()) {
      const auto began = std::chrono::steady_clock::now();
      const auto [rank, want] = waiting.front();
      waiting.pop_front();
      const std::size_t share = (queue.left() + workers() - 1) / workers();
      const std::size_t count = std::min<std::size_t>(static_cast<std::size_t>(want), share);
      json work = {{"configs", json::array()}, {"trials", json::array()}};
      for (std::size_t i = 0; i < count && queue.any(); ++i) {
        const TrialOrder t = queue.take();
        if (known[rank].insert(t.config).second) {
          const Configuration& c = runner.config(t.config);
          work["configs"].push_back(config_json(t.config, c));
        }
        work["trials"].push_back(order_json(t));
      }
      send(work, rank, kWork);
      outstanding += count;
      busy += std::chrono::steady_clock::now() - began;
    }
  }
};

Coordinator::Coordinator(const Session& session, std::string fingerprint)
    : state_(std::make_unique<State>(State{session, std::move(fingerprint), {}, {}, {}, {}, {}})) {}

Coordinator::~Coordinator() = default;

void Coordinator::run(TrialRunner& runner, const TrialSequence& trials,
                      const std::function<void(const TrialRecord&)>& finished) {
  Pending queue{trials};
  std::size_t outstanding = 0;
  State& s = *state_;
  s.serve(runner, queue, outstanding);
  while (queue.any() || outstanding > 0) {
    s.handle(receive(MPI_ANY_SOURCE), outstanding, finished);
    s.serve(runner, queue, outstanding);
  }
}

void Coordinator::finish() {
  State& s = *state_;
  std::set<int> stopped;
  const auto stop_waiting = [&] {
    for (const auto& [rank, want] : s.waiting)
      if (stopped.insert(rank).second) send(json(), rank, kStop);
    s.waiting.clear();
  };
  stop_waiting();
  std::size_t none = 0;
  while (static_cast<int>(stopped.size()) < s.workers()) {
    s.handle(receive(MPI_ANY_SOURCE), none,
             [](const TrialRecord&) { throw aco::Error("a worker sent a trial that was not handed out"); });
    stop_waiting();
  }
}

double Coordinator::busy_seconds() const { return std::chrono::duration<double>(state_->busy).count(); }

double Coordinator::storing_seconds() const { return std::chrono::duration<double>(state_->stored).count(); }

void warn_if_bound(const Session& session, int threads) {
  const int usable = aco::usable_cpus(), all = static_cast<int>(std::thread::hardware_concurrency());
  if (usable >= all || (threads > 0 && threads <= usable)) return;
  std::cerr << "acobench: warning: rank " << session.rank() << " on " << aco::hostname() << " may use " << usable
            << " of its " << all
            << " CPUs: the launcher bound it (mpirun binds each rank to one core when -n is 2 or less); "
            << "start mpirun with --bind-to none, or give each rank its cores (Slurm: --cpus-per-task)\n";
}

void serve_trials(const Session& session, const Experiment& experiment, aco::PluginRegistry& registry, int threads,
                  TrialWorkers* workers) {
  warn_if_bound(session, threads);
  TrialRunner runner(experiment, registry);
  const int lanes = workers ? workers->lanes() : aco::lane_count(threads);
  // One trial on each lane. A trial's own TBB loops then run on its lane: TBB workers beside the
  // lanes would only oversubscribe the cores (one process does the same, nesting them in its
  // loop over trials).
  const aco::ThreadLimit limit(1);

  // The lanes take trials from `queue` and put records in `done`; the main thread talks to rank 0.
  std::mutex mutex;
  std::condition_variable work_ready, record_ready;
  std::deque<TrialOrder> queue;
  std::vector<TrialRecord> done;
  bool stopping = false;
  std::vector<std::thread> pool;
  for (int i = 0; i < lanes; ++i)
    pool.emplace_back([&, i] {
      std::unique_lock lock(mutex);
      for (;;) {
        work_ready.wait(lock, [&] { return stopping || !queue.empty(); });
        if (queue.empty()) return;
        const TrialOrder t = queue.front();
        queue.pop_front();
        lock.unlock();
        TrialRecord record = workers ? workers->run(i, runner, t) : runner.run(t);
        lock.lock();
        done.push_back(std::move(record));
        record_ready.notify_one();
      }
    });

  // Asks for work when two trials per lane are left, for up to four per lane in hand: the lanes
  // keep busy while the request travels and rank 0 stores the records of others.
  const auto finish = [&] {
    {
      const std::lock_guard lock(mutex);
      stopping = true;
    }
    work_ready.notify_all();
    for (auto& thread : pool) thread.join();
  };
  try {
    std::size_t in_hand = 0;  // handed out to this rank, not yet sent back
    bool asked = false, told_to_stop = false, greeted = false;
    Backoff backoff;
    for (;;) {
      std::vector<TrialRecord> records;
      {
        std::unique_lock lock(mutex);
        record_ready.wait_for(lock, backoff.wait(), [&] { return !done.empty(); });
        records.swap(done);
      }
      const int want = !asked && !told_to_stop && in_hand <= static_cast<std::size_t>(2 * lanes)
                           ? 4 * lanes - static_cast<int>(in_hand)
                           : 0;
      if (want > 0 || !records.empty()) {
        json message = {{"want", want}, {"records", json::array()}};
        for (const auto& r : records) message["records"].push_back(record_json(r));
        if (!greeted) message["hello"] = {{"fingerprint", experiment.fingerprint(registry)}, {"host", aco::hostname()}};
        send(message, 0, kToCoordinator);
        greeted = true;
        in_hand -= records.size();
        asked = asked || want > 0;
        backoff.busy();
      }
      if (auto m = try_receive(0)) {
        backoff.busy();
        if (m->tag == kStop) {
          told_to_stop = true;
        } else {
          for (const json& c : m->message.at("configs")) add_config_from(c, runner);
          {
            const std::lock_guard lock(mutex);
            for (const json& t : m->message.at("trials")) queue.push_back(order_from(t));
          }
          in_hand += m->message.at("trials").size();
          asked = false;
          work_ready.notify_all();
        }
      } else if (records.empty()) {
        backoff.longer();  // the wait for a record above is the sleep
      }
      if (told_to_stop && in_hand == 0) break;
    }
  } catch (...) {
    finish();
    throw;
  }
  finish();
}

}  // namespace aco::studies::mpi

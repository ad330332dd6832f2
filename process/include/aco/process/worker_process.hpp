#pragma once
// Work that may crash, hang or eat memory (a plugin under development) runs in a worker process,
// so it costs its own request, not the program: acobench's trials, acosim's batch variations.
// The parent holds a WorkerProcess per lane; each serves one request at a time and stays up
// between requests (no fork or exec per request). A worker that dies is started again on the
// next request; the request it was serving comes back as a failure naming the signal and the
// plugin hook it was in (the worker's signal handler writes it before the process ends).
//
// The worker is the same program started again with `argv` (posix_spawn: safe in a threaded
// parent and under MPI), talking over a socket on file descriptor 3; its stdout and stderr are
// the parent's.
#include <sys/types.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "aco/process/failure_kind.hpp"

namespace aco {

struct WorkerLimits {
  double timeout_s = 0.0;  // per request; 0: none
  std::uint64_t memory_bytes = 0;  // growth of the worker's resident memory during a request; 0: none
};

struct WorkerReply {
  // Why the request got no reply: crashed, timed_out or out_of_memory; none when it got one.
  FailureKind failure_kind = FailureKind::none;
  std::string bytes;  // the worker's reply
  // Otherwise the failure, starting with its kind's text: "crashed: SIGSEGV in plugin update/x
  // (FILE) in update() in iteration 3", "timed out after 5 s in plugin ...", "out of memory (over
  // 512 MiB) in plugin ...".
  std::string failure;
  // false: the worker had ended before the request reached it (killed while it waited), so it
  // ran nothing of it; a caller may send it again (start() gives a fresh worker).
  bool delivered = true;
};

class WorkerProcess {
 public:
  // `argv[0]` is the program to start (e.g. this_program(), aco/machine.hpp); `argv` must make it
  // call serve_worker_requests().
  explicit WorkerProcess(std::vector<std::string> argv);
  ~WorkerProcess();  // closes the socket (the worker ends), waits for it
  WorkerProcess(const WorkerProcess&) = delete;
  WorkerProcess& operator=(const WorkerProcess&) = delete;

  // Starts the worker if none is running (one that ended since its last reply, killed while it
  // waited, is started again); true if it started one now (a fresh worker knows nothing of what
  // earlier requests told the one before).
  bool start();
  // Sends a request and waits for its reply within the limits. A worker that fails to start,
  // or answers with an error of its own (serve_worker_requests' `fail`), is an aco::Error.
  WorkerReply request(const std::string& bytes, const WorkerLimits& limits);

 private:
  // Waits for the worker's frame of kind `wanted` within the limits (replied: its payload).
  WorkerReply await(char wanted, const WorkerLimits& limits, std::uint64_t baseline);
  // The reply of a request that failed as `kind`: its failure is the kind's text and `detail`.
  WorkerReply end_worker(FailureKind kind, const std::string& detail);
  // Waits up to timeout_ms (-1: no limit) for the worker's bytes and keeps them in received_.
  enum class Received { bytes, nothing, closed };
  Received receive(int timeout_ms);
  // The next whole frame received (kind, payload), if there is one; a note is kept in note_.
  std::optional<std::pair<char, std::string>> take_frame();
  std::vector<std::string> argv_;
  pid_t pid_ = -1;
  int socket_ = -1;
  std::string received_;  // bytes read, not yet a whole frame
  std::string note_;  // where the worker said it was (its signal handler's note)
  bool ready_ = false;  // the worker said it has loaded what it serves
};

// How many lanes (threads, worker processes) --threads N means: N, or for 0 every CPU this
// process may use (usable_cpus(), aco/machine.hpp).
int lane_count(int threads);

// Calls `work(lane, item)` for every item in [0, count), in order, on `lanes` threads (at most
// `count`), lane l always with l: a caller holding a WorkerProcess per lane gives each one
// request at a time. The first exception stops handing out items and is rethrown once every
// lane has ended.
void run_on_lanes(int lanes, std::size_t count, const std::function<void(int lane, std::size_t item)>& work);

// In the worker (started by WorkerProcess): answers each request with `handle`'s reply until the
// parent closes the socket, then returns. A fatal signal or SIGUSR1 (the parent's "time is up")
// first tells the parent which plugin hook the worker was in. `handle` throwing ends the worker
// with its message as an error the parent raises. Ends with the parent, whatever it runs.
void serve_worker_requests(const std::function<std::string(const std::string&)>& handle);

// In the worker, before or instead of serving: the parent's request raises `message` as an
// aco::Error (a worker that cannot load what it was started for ends the parent's work, rather
// than failing each request).
[[noreturn]] void fail_worker(const std::string& message);

// Whether this process was started by a WorkerProcess.
bool is_worker_process();

}  // namespace aco

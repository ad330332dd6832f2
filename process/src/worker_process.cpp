#include "aco/process/worker_process.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <cstdio>
#include <exception>
#include <mutex>
#include <thread>

#include "aco/process/crash_report.hpp"
#include "aco/error.hpp"
#include "aco/machine.hpp"
#include "aco/memory_limit.hpp"
#include "aco/plugin_call.hpp"

extern char** environ;

namespace aco {
namespace {

// The worker's end of the socket, and the variables that tell a program it is a worker.
constexpr int kWorkerSocket = 3;
constexpr const char* kWorkerVariable = "ACO_WORKER_PARENT";

// Worker -> parent frames: a kind byte, a 4-byte length, the payload. Parent -> worker: the
// length and the payload.
constexpr char kReady = 'H', kReply = 'R', kNote = 'N', kError = 'E';

// The 4-byte length; signal-safe (the crash note's frame is made in a signal handler).
void put_length(std::size_t n, char* out) noexcept {
  for (int i = 0; i < 4; ++i) out[i] = static_cast<char>((n >> (8 * i)) & 0xff);
}

std::string length_prefix(std::size_t n) {
  std::string bytes(4, '\0');
  put_length(n, bytes.data());
  return bytes;
}

std::uint32_t read_length(const char* bytes) {
  std::uint32_t n = 0;
  for (int i = 0; i < 4; ++i) n |= static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[i])) << (8 * i);
  return n;
}

// Writes all of `bytes`; false if the other end is gone.
bool write_all(int fd, const char* bytes, std::size_t size) noexcept {
  while (size > 0) {
    const ssize_t n = ::send(fd, bytes, size, MSG_NOSIGNAL);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    bytes += n;
    size -= static_cast<std::size_t>(n);
  }
  return true;
}

std::string seconds_text(double seconds) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", seconds);
  return text;
}

// --- the worker's side ---

// A note frame, written by a signal handler: no allocation, one write.
void write_note(const char* where, std::size_t length) noexcept {
  char frame[1024 + 5];
  if (length > sizeof frame - 5) length = sizeof frame - 5;
  frame[0] = kNote;
  put_length(length, frame + 1);
  std::memcpy(frame + 5, where, length);
  write_all(kWorkerSocket, frame, length + 5);
}

void note_crash(int, const char* where, std::size_t length) noexcept { write_note(where, length); }

// The parent's "time is up": say where, then end.
void on_time_up(int) {
  char where[1024];
  write_note(where, describe_plugin_call(where, sizeof where));
  ::_exit(128 + SIGUSR1);
}

bool read_all(int fd, char* bytes, std::size_t size) {
  while (size > 0) {
    const ssize_t n = ::read(fd, bytes, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    bytes += n;
    size -= static_cast<std::size_t>(n);
  }
  return true;
}

void send_frame(char kind, const std::string& payload) {
  const std::string frame = std::string(1, kind) + length_prefix(payload.size()) + payload;
  if (!write_all(kWorkerSocket, frame.data(), frame.size())) ::_exit(1);  // the parent is gone
}

}  // namespace

int lane_count(int threads) { return threads > 0 ? threads : usable_cpus(); }

void run_on_lanes(int lanes, std::size_t count, const std::function<void(int lane, std::size_t item)>& work) {
  std::atomic<std::size_t> next{0};
  std::mutex mutex;
  std::exception_ptr error;
  const auto lane = [&](int index) {
    try {
      for (std::size_t i; (i = next++) < count;) work(index, i);
    } catch (...) {
      const std::lock_guard lock(mutex);
      if (!error) error = std::current_exception();
      next = count;
    }
  };
  std::vector<std::thread> threads;
  const int used = static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(std::max(1, lanes)), count));
  for (int i = 0; i < used; ++i) threads.emplace_back(lane, i);
  for (auto& thread : threads) thread.join();
  if (error) std::rethrow_exception(error);
}

bool is_worker_process() { return std::getenv(kWorkerVariable) != nullptr; }

void serve_worker_requests(const std::function<std::string(const std::string&)>& handle) {
  const char* parent_text = std::getenv(kWorkerVariable);
  if (!parent_text || ::fcntl(kWorkerSocket, F_GETFD) < 0)
    throw Error("not started as a worker process (by acobench or acosim)");
  // Orphaned (the parent was killed): end, even in the middle of an endless loop.
  const pid_t parent = static_cast<pid_t>(std::atol(parent_text));
  std::thread([parent] {
    while (::getppid() == parent) std::this_thread::sleep_for(std::chrono::milliseconds(500));
    ::_exit(1);
  }).detach();
  on_fatal_signal(note_crash);
  struct sigaction action {};
  action.sa_handler = on_time_up;
  sigemptyset(&action.sa_mask);
  ::sigaction(SIGUSR1, &action, nullptr);
  send_frame(kReady, "");
  for (;;) {
    char prefix[4];
    if (!read_all(kWorkerSocket, prefix, 4)) return;  // the parent closed the socket: done
    std::string request(read_length(prefix), '\0');
    if (!read_all(kWorkerSocket, request.data(), request.size())) return;
    std::string reply;
    try {
      reply = handle(request);
    } catch (const std::exception& e) {
      fail_worker(e.what());
    }
    send_frame(kReply, reply);
  }
}

void fail_worker(const std::string& message) {
  send_frame(kError, message);
  ::_exit(1);
}

// --- the parent's side ---

WorkerProcess::WorkerProcess(std::vector<std::string> argv) : argv_(std::move(argv)) {}

WorkerProcess::~WorkerProcess() {
  if (pid_ < 0) return;
  ::close(socket_);
  int status = 0;
  // The worker ends when it reads the end of its requests; one stuck anyway is not waited for.
  for (int i = 0; i < 200 && ::waitpid(pid_, &status, WNOHANG) == 0; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  if (::waitpid(pid_, &status, WNOHANG) == 0) {
    ::kill(pid_, SIGKILL);
    ::waitpid(pid_, &status, 0);
  }
}

bool WorkerProcess::start() {
  // A worker that ended between requests (killed while it waited) served none: a new one serves
  // the next, rather than that request failing as a crash it had no part in.
  int status = 0;
  if (pid_ >= 0 && ::waitpid(pid_, &status, WNOHANG) == pid_) {
    ::close(socket_);
    pid_ = -1;
    socket_ = -1;
  }
  if (pid_ >= 0) return false;
  int ends[2];
  if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, ends) != 0)
    throw Error(std::string("cannot make a socket for a worker process: ") + std::strerror(errno));
  // Above 3, so the child's dup2 to 3 always copies it (and clears close-on-exec).
  const int child_end = ::fcntl(ends[1], F_DUPFD_CLOEXEC, 10);
  ::close(ends[1]);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, child_end, kWorkerSocket);
  std::vector<char*> args;
  for (auto& a : argv_) args.push_back(a.data());
  args.push_back(nullptr);
  std::vector<std::string> environment;
  for (char** e = environ; *e; ++e)
    if (std::strncmp(*e, kWorkerVariable, std::strlen(kWorkerVariable)) != 0) environment.emplace_back(*e);
  environment.push_back(std::string(kWorkerVariable) + "=" + std::to_string(::getpid()));
  std::vector<char*> env;
  for (auto& e : environment) env.push_back(e.data());
  env.push_back(nullptr);
  pid_t pid = -1;
  const int failed = ::posix_spawn(&pid, args[0], &actions, nullptr, args.data(), env.data());
  posix_spawn_file_actions_destroy(&actions);
  ::close(child_end);
  if (failed != 0) {
    ::close(ends[0]);
    throw Error("cannot start a worker process (" + argv_[0] + "): " + std::strerror(failed));
  }
  pid_ = pid;
  socket_ = ends[0];
  received_.clear();
  note_.clear();
  ready_ = false;
  return true;
}

WorkerReply WorkerProcess::request(const std::string& bytes, const WorkerLimits& limits) {
  start();
  // A fresh worker first loads what it serves (maps, plugins): that is not the request's time.
  if (!ready_) {
    WorkerReply started = await(kReady, {}, 0);
    if (started.failure_kind != FailureKind::none) return started;
    ready_ = true;
  }
  const std::uint64_t baseline = limits.memory_bytes ? resident_memory(pid_) : 0;
  const std::string frame = length_prefix(bytes.size()) + bytes;
  if (!write_all(socket_, frame.data(), frame.size())) {
    WorkerReply reply = end_worker(FailureKind::crashed, "");
    reply.delivered = false;
    return reply;
  }
  return await(kReply, limits, baseline);
}

WorkerReply WorkerProcess::await(char wanted, const WorkerLimits& limits, std::uint64_t baseline) {
  using clock = std::chrono::steady_clock;
  const auto began = clock::now();
  for (;;) {
    // Whole frames first: the one awaited, a note of where the worker is, or its error.
    for (auto frame = take_frame(); frame; frame = take_frame()) {
      auto& [kind, payload] = *frame;
      if (kind == wanted) return {FailureKind::none, std::move(payload), ""};
      if (kind == kError) {
        end_worker(FailureKind::crashed, "");
        throw Error(payload);
      }
    }
    // Memory first: a worker over both limits (its parent was slow to look) is out of memory.
    // A plugin filling memory gains at most a few hundred MiB between two looks.
    int wait_ms = -1;
    if (limits.memory_bytes) {
      if (resident_memory(pid_) > baseline + limits.memory_bytes)
        return end_worker(FailureKind::out_of_memory, " (over " + format_bytes(limits.memory_bytes) + ")");
      wait_ms = 20;
    }
    const double elapsed = std::chrono::duration<double>(clock::now() - began).count();
    if (limits.timeout_s > 0) {
      if (elapsed >= limits.timeout_s)
        return end_worker(FailureKind::timed_out, " after " + seconds_text(limits.timeout_s) + " s");
      const int left_ms = static_cast<int>(std::ceil((limits.timeout_s - elapsed) * 1000));
      wait_ms = wait_ms < 0 ? left_ms : std::min(wait_ms, left_ms);
    }
    if (receive(wait_ms) == Received::closed) return end_worker(FailureKind::crashed, "");  // it crashed
  }
}

WorkerProcess::Received WorkerProcess::receive(int timeout_ms) {
  pollfd p{socket_, POLLIN, 0};
  const int ready = ::poll(&p, 1, timeout_ms);
  if (ready < 0 && errno != EINTR) throw Error(std::string("waiting for a worker process: ") + std::strerror(errno));
  if (ready <= 0) return Received::nothing;
  char buffer[65536];
  const ssize_t n = ::read(socket_, buffer, sizeof buffer);
  if (n < 0 && errno == EINTR) return Received::nothing;
  if (n <= 0) return Received::closed;
  received_.append(buffer, static_cast<std::size_t>(n));
  return Received::bytes;
}

std::optional<std::pair<char, std::string>> WorkerProcess::take_frame() {
  if (received_.size() < 5 || received_.size() < 5 + read_length(received_.data() + 1)) return std::nullopt;
  const std::size_t length = read_length(received_.data() + 1);
  std::pair<char, std::string> frame{received_[0], received_.substr(5, length)};
  received_.erase(0, 5 + length);
  if (frame.first == kNote) note_ = frame.second;
  return frame;
}

WorkerReply WorkerProcess::end_worker(FailureKind kind, const std::string& detail) {
  // A worker that is still running is asked where it is (SIGUSR1 to its main thread, the one
  // serving requests), then given a moment to say it before it is killed.
  if (kind != FailureKind::crashed) ::syscall(SYS_tgkill, pid_, pid_, SIGUSR1);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(2);
  for (;;) {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0 || receive(static_cast<int>(left.count())) == Received::closed) break;
  }
  while (take_frame()) {}  // the note among them is kept
  ::kill(pid_, SIGKILL);  // if it is still there
  int wait_status = 0;
  ::waitpid(pid_, &wait_status, 0);
  ::close(socket_);
  pid_ = -1;
  socket_ = -1;
  WorkerReply reply;
  reply.failure_kind = kind;
  reply.failure = to_string(kind) + detail;
  if (kind == FailureKind::crashed) {
    if (WIFSIGNALED(wait_status))
      reply.failure += std::string(": ") + signal_name(WTERMSIG(wait_status));
    else
      reply.failure += ": the worker process exited with status " + std::to_string(WEXITSTATUS(wait_status));
  }
  if (!note_.empty()) reply.failure += " in " + note_;
  return reply;
}

}  // namespace aco

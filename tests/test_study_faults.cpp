// Fault injection into a study: SIGKILL of the runner and of its worker processes at trial
// boundaries drawn from a fixed seed, a full disk (a file size limit), a folder that cannot be
// written and two writers at once, each followed by a resume. The stored trials must equal an
// uninterrupted run's, bit for bit (but for what a rerun measures anew: times, memory).
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "acobench_support.hpp"
#include "support.hpp"

using Catch::Contains;
using namespace test::acobench_helpers;

namespace {

// The worker processes of a running acobench: the children of any of its threads.
std::vector<pid_t> workers_of(pid_t parent) {
  std::vector<pid_t> found;
  for (const auto& task : std::filesystem::directory_iterator("/proc/" + std::to_string(parent) + "/task")) {
    std::ifstream children(task.path() / "children");
    for (pid_t child; children >> child;) found.push_back(child);
  }
  return found;
}

// Whether the worker waits for its next request: blocked in read() on its socket (fd 3), its
// last reply sent. Linux's /proc/PID/syscall: the number (0: read on x86-64, 63 on arm64), then
// the arguments.
bool waiting_for_a_request(pid_t worker) {
  std::ifstream in("/proc/" + std::to_string(worker) + "/syscall");
  std::string number, fd;
  in >> number >> fd;
#if defined(__aarch64__)
  return number == "63" && fd == "0x3";
#else
  return number == "0" && fd == "0x3";
#endif
}

// Whether a process has ended: a zombie, or reaped already.
bool ended(pid_t pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  if (!std::getline(stat, line)) return true;
  const auto state = line.find(") ");
  return state != std::string::npos && line[state + 2] == 'Z';
}

int wait_for(pid_t child) {
  int status = 0;
  waitpid(child, &status, 0);
  return status;
}

}  // namespace

TEST_CASE("a study killed, starved of disk, locked and shared by two writers resumes to the same trials",
          "[acobench][slow][study-faults]") {
  const auto file = experiment(kill_me_text());  // 300 trials of a few ms
  const auto folder = file.parent_path();
  const auto whole = folder / "whole.db", db = folder / "faults.db", log = folder / "faults.log";
  REQUIRE(run_acobench({"run", file.string(), "--db", whole.string(), "--threads", "2"}).exit_code == 0);
  const std::vector<std::string> run = {ACO_TEST_ACOBENCH, "run", file.string(), "--db", db.string(), "--threads", "2"};
  std::mt19937 random(56);  // the trial boundaries faults hit
  const auto next_boundary = [&] { return count_runs(db) + std::uniform_int_distribution<int>(5, 30)(random); };

  SECTION("every fault in turn") {
    // 1. The runner killed three times.
    for (int kill_count = 0; kill_count < 3; ++kill_count) {
      const int boundary = kill_count == 0 ? std::uniform_int_distribution<int>(5, 30)(random) : next_boundary();
      const pid_t runner = test::start(run, log);
      wait_for_trials(db, boundary);
      kill(runner, SIGKILL);
      CHECK(WIFSIGNALED(wait_for(runner)));
      INFO("runner killed at " << count_runs(db) << " trials");
      CHECK(count_runs(db) >= boundary);
    }

    // 2. A worker killed three times while it waits for its next trial: the runner is stopped
    // until every worker has sent its reply, one of them is killed, the runner goes on.
    const pid_t runner = test::start(run, log);
    int worker_kills = 0;
    for (int round = 0; round < 3; ++round) {
      wait_for_trials(db, next_boundary());
      kill(runner, SIGSTOP);
      const auto workers = workers_of(runner);
      const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
      const auto idle = [&] {
        return std::all_of(workers.begin(), workers.end(), [](pid_t w) { return waiting_for_a_request(w); });
      };
      // A request sent just before the stop leaves its worker in read() until the scheduler
      // wakes it: idle means idle for a while.
      auto idle_since = std::chrono::steady_clock::now();
      while (std::chrono::steady_clock::now() < deadline) {
        if (!idle()) idle_since = std::chrono::steady_clock::now();
        if (std::chrono::steady_clock::now() - idle_since > std::chrono::milliseconds(300)) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
      }
      if (!workers.empty() && idle()) {
        const pid_t victim = workers[std::uniform_int_distribution<std::size_t>(0, workers.size() - 1)(random)];
        kill(victim, SIGKILL);
        // Gone (a zombie for the runner to reap) before the runner goes on: killed at the boundary.
        while (!ended(victim)) std::this_thread::sleep_for(std::chrono::milliseconds(1));
        ++worker_kills;
      }
      kill(runner, SIGCONT);
    }
    const int status = wait_for(runner);
    INFO(file_bytes(log));
    CHECK(worker_kills == 3);
    CHECK(count_runs(db) == 300);
    // A worker killed as it waited is started again for the next trial, and a request it never
    // read is sent again. A request it read just before it was killed cannot be told from a
    // crash: that trial is stored as crashed (SIGKILL), at most one per kill; deleting its row is how a
    // user runs it again.
    const int crashed = std::stoi(sql_value(db, "SELECT count(*) FROM run_texts WHERE error IS NOT NULL"));
    CHECK(crashed <= worker_kills);
    CHECK(sql_value(db, "SELECT count(*) FROM run_texts WHERE error LIKE '%crashed: SIGKILL'") ==
          std::to_string(crashed));
    CHECK((WIFEXITED(status) && WEXITSTATUS(status) == (crashed ? 3 : 0)));
    sql_exec(db, "DELETE FROM runs WHERE id IN (SELECT runid FROM run_texts WHERE error IS NOT NULL)");
    // The column the crashed trial added, NULL in every row left: the uninterrupted run has none.
    if (crashed) sql_exec(db, "ALTER TABLE runs DROP COLUMN failure");

    // 3. The disk full (a file size limit just above the database's size), then resumed.
    sql_exec(db, "DELETE FROM runs WHERE repetition >= 100");
    const auto size = std::filesystem::file_size(db);
    std::vector<std::string> limited = {"/usr/bin/prlimit", "--fsize=" + std::to_string(size + 64 * 1024), "--"};
    limited.insert(limited.end(), run.begin(), run.end());
    signal(SIGXFSZ, SIG_IGN);  // inherited: a write past the limit fails with EFBIG instead of killing
    const pid_t full = test::start(limited, log);
    const int full_status = wait_for(full);
    signal(SIGXFSZ, SIG_DFL);
    INFO(file_bytes(log));
    CHECK((WIFEXITED(full_status) && WEXITSTATUS(full_status) == 1));
    // EFBIG is SQLite's I/O error; ENOSPC (a full file system) its "database or disk is full".
    CHECK_THAT(file_bytes(log), Contains("acobench: error: results database " + db.string()) &&
                                    (Contains("disk I/O error") || Contains("database or disk is full")));
    CHECK(count_runs(db) < 300);

    // 4. The folder made read-only: refused, nothing written.
    const std::string before = file_bytes(db);
    using std::filesystem::perms;
    std::filesystem::permissions(folder, perms::owner_read | perms::owner_exec | perms::others_read |
                                             perms::others_exec | perms::group_read | perms::group_exec);
    std::vector<std::string> as_reader;
    if (::geteuid() == 0) as_reader = {"/usr/bin/setpriv", "--reuid=65534", "--regid=65534", "--clear-groups"};
    as_reader.insert(as_reader.end(), run.begin(), run.end());
    const auto locked = test::run(as_reader);
    std::filesystem::permissions(
        folder, perms::owner_all | perms::group_read | perms::group_exec | perms::others_read | perms::others_exec);
    CHECK(locked.exit_code == 1);
    CHECK_THAT(locked.err, Contains("cannot be written"));
    CHECK(file_bytes(db) == before);

    // 5. Two writers resume it at once: each trial stored once.
    const pid_t first = test::start(run, folder / "first.log"), second = test::start(run, folder / "second.log");
    const int first_status = wait_for(first), second_status = wait_for(second);
    INFO(file_bytes(folder / "first.log") << file_bytes(folder / "second.log"));
    CHECK((WIFEXITED(first_status) && WEXITSTATUS(first_status) == 0));
    CHECK((WIFEXITED(second_status) && WEXITSTATUS(second_status) == 0));
    CHECK(count_runs(db) == 300);
    const auto got = database_rows(db), wanted = database_rows(whole);
    const auto differs = std::mismatch(got.begin(), got.end(), wanted.begin(), wanted.end());
    INFO("first row that differs: " << (differs.first == got.end() ? "(none)" : *differs.first) << "\n  instead of "
                                    << (differs.second == wanted.end() ? "(none)" : *differs.second));
    CHECK(got == wanted);
  }
}

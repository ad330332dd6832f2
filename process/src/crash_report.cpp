#include "aco/process/crash_report.hpp"

#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cstring>

#include "aco/plugin_call.hpp"

namespace aco {
namespace {

constexpr int kFatalSignals[] = {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT};
CrashWriter crash_writer = nullptr;
const char* crash_program = "";

void on_signal(int signal) {
  char where[1024];
  const std::size_t length = describe_plugin_call(where, sizeof where);
  if (crash_writer) crash_writer(signal, where, length);
  // SA_RESETHAND restored the default action: a fault happens again on return, abort() raises
  // again, and a signal sent by kill() is delivered again once the handler returns.
  ::raise(signal);
}

void write_text(const char* text, std::size_t length) noexcept {
  while (length > 0) {
    const ssize_t n = ::write(STDERR_FILENO, text, length);
    if (n <= 0) return;
    text += n;
    length -= static_cast<std::size_t>(n);
  }
}

void write_text(const char* text) noexcept { write_text(text, std::strlen(text)); }

// "PROGRAM: error: crashed: SIGSEGV in plugin ...", or "stopped: SIGUSR1 ...".
void report(const char* what, int signal, const char* where, std::size_t length) noexcept {
  write_text(crash_program);
  write_text(": error: ");
  write_text(what);
  write_text(": ");
  write_text(signal_name(signal));
  if (length > 0) {
    write_text(" in ");
    write_text(where, length);
  }
  write_text("\n");
}

void to_stderr(int signal, const char* where, std::size_t length) noexcept { report("crashed", signal, where, length); }

// Set by the first thread into on_stop(). A lock-free atomic: safe in a signal handler.
std::atomic<bool> stopping{false};
static_assert(std::atomic<bool>::is_always_lock_free);

// SIGUSR1, as `timeout -s USR1` sends it: say where this thread was, then end as the signal would
// have. Not SA_RESETHAND: the kernel puts the default action back when it takes the signal for
// the handler, before it blocks the signal for the handler's run, and timeout sends SIGUSR1
// twice (to the command, then to its process group); a second one in between found the default
// action and ended the process before the handler wrote a byte. So the handler stays installed
// and puts the default action back itself once the report is out. A later SIGUSR1 that reaches
// another thread meanwhile (this one blocks it) waits there for the process to end.
void on_stop(int signal) {
  if (stopping.exchange(true)) {
    for (;;) ::pause();
  }
  char where[1024];
  report("stopped", signal, where, describe_plugin_call(where, sizeof where));
  struct sigaction action {};
  action.sa_handler = SIG_DFL;
  sigemptyset(&action.sa_mask);
  ::sigaction(signal, &action, nullptr);
  // Blocked while this handler runs: delivered, by the default action, when it returns.
  ::raise(signal);
}

// `handler` for `signal` on the alternate stack where one is set; with `once`, the default action
// comes back for the handler to raise the signal again.
void handle(int signal, void (*handler)(int), bool once) {
  struct sigaction action {};
  action.sa_handler = handler;
  action.sa_flags = SA_ONSTACK | (once ? SA_RESETHAND : 0);
  sigemptyset(&action.sa_mask);
  ::sigaction(signal, &action, nullptr);
}

}  // namespace

const char* signal_name(int signal) noexcept {
  switch (signal) {
    case SIGSEGV:
      return "SIGSEGV";
    case SIGBUS:
      return "SIGBUS";
    case SIGFPE:
      return "SIGFPE";
    case SIGILL:
      return "SIGILL";
    case SIGABRT:
      return "SIGABRT";
    case SIGKILL:
      return "SIGKILL";
    case SIGTERM:
      return "SIGTERM";
    case SIGUSR1:
      return "SIGUSR1";
    default:
      return "a signal";
  }
}

void on_fatal_signal(CrashWriter writer) {
  crash_writer = writer;
  static char alternate_stack[64 * 1024];
  stack_t stack{};
  stack.ss_sp = alternate_stack;
  stack.ss_size = sizeof alternate_stack;
  ::sigaltstack(&stack, nullptr);
  for (const int signal : kFatalSignals) handle(signal, on_signal, true);
}

void report_crashes(const char* program) {
  crash_program = program;
  on_fatal_signal(to_stderr);
  handle(SIGUSR1, on_stop, false);
}

}  // namespace aco

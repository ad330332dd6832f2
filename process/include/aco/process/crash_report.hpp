#pragma once
// When a plugin crashes the process (a null pointer, a failed assert), the user learns which
// plugin, hook and iteration it was in, instead of a bare "Segmentation fault". The hosts
// install this at start; acobench's worker processes pass the same text to their parent.
#include <boost/config.hpp>
#include <cstddef>

namespace aco {

// "SIGSEGV", "SIGBUS", ... for the signals a crash report covers and SIGKILL, SIGTERM, SIGUSR1;
// "a signal" for others. Async-signal-safe.
BOOST_SYMBOL_VISIBLE const char* signal_name(int signal) noexcept;

// Called from the signal handler with the signal and describe_plugin_call()'s text (length 0:
// outside every plugin). Must be async-signal-safe (write() only).
using CrashWriter = void (*)(int signal, const char* where, std::size_t length) noexcept;

// From now on a fatal signal (SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT) calls `writer` and then
// ends the process as the signal would have (a shell reports 128 + signal). The calling thread
// gets an alternate signal stack, so a stack overflow on it is reported too.
BOOST_SYMBOL_VISIBLE void on_fatal_signal(CrashWriter writer);

// on_fatal_signal() with a writer of "PROGRAM: error: crashed: SIGSEGV in plugin update/crash
// (FILE) in update() in iteration 3" to stderr; and SIGUSR1 (`timeout -s USR1`: time is up)
// writes "PROGRAM: error: stopped: SIGUSR1 in plugin ... in update() in iteration 3" (where the
// thread it reached was: with one thread, the plugin that hangs), then ends the process as
// SIGUSR1 does. `program` must outlive the process (a literal).
BOOST_SYMBOL_VISIBLE void report_crashes(const char* program);

}  // namespace aco

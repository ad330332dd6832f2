#pragma once
// Why work ended without a result, said once for every place that says it: a worker process's
// reply (aco/process/worker_process.hpp), an acobench trial's record (runs.failure, the JSON messages,
// Python) and an acosim batch's summary.
#include <cstddef>
#include <iterator>
#include <string_view>

namespace aco {

// A crash (a signal), the time limit, the memory limit, a plugin that threw, a value a plugin
// wrote that the engine refused (aco::InvalidValueError), anything else (the host's own errors,
// and every failure stored by an acobench of format 4 or earlier that threw). A request to a
// worker process fails only as crashed, timed_out or out_of_memory.
enum class FailureKind { none, crashed, timed_out, out_of_memory, plugin_error, invalid_value, error };

// Each kind's text, in the enum's order; "" for none.
inline constexpr const char* kFailureTexts[] = {
    "", "crashed", "timed out", "out of memory", "plugin error", "invalid value", "error"};
static_assert(std::size(kFailureTexts) == static_cast<std::size_t>(FailureKind::error) + 1);

constexpr const char* to_string(FailureKind kind) { return kFailureTexts[static_cast<int>(kind)]; }

// The kind that text names ("" none); an Error naming the text and the kinds for any other.
FailureKind failure_kind(std::string_view text);

}  // namespace aco

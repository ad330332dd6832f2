#include "aco/plugin_call.hpp"

#include <cxxabi.h>

#include <cstdlib>
#include <exception>
#include <memory>
#include <new>
#include <typeinfo>

#include "aco/plugin_error.hpp"

namespace aco {
namespace {

// How every message numbers an iteration: as Context::iteration does, and saying so, since
// plugin authors compare it with what their hook saw.
constexpr const char* kIterationNumbering = " (0-based, as Context::iteration)";

// The innermost guarded call of this thread. Plain pointers and an int: a signal handler reads
// them without allocating.
thread_local PluginCall current_call;

// Appends `text` to out[0, size - 1) at `length`; signal-safe (no library call).
void append(char* out, std::size_t size, std::size_t& length, const char* text) noexcept {
  for (; text && *text && length + 1 < size; ++text) out[length++] = *text;
}

void append_number(char* out, std::size_t size, std::size_t& length, long value) noexcept {
  char digits[24];
  int n = 0;
  const bool negative = value < 0;
  unsigned long v = negative ? 0ul - static_cast<unsigned long>(value) : static_cast<unsigned long>(value);
  do digits[n++] = static_cast<char>('0' + v % 10);
  while ((v /= 10) != 0);
  if (negative) digits[n++] = '-';
  char text[24];
  for (int i = 0; i < n; ++i) text[i] = digits[n - 1 - i];
  text[n] = '\0';
  append(out, size, length, text);
}

}  // namespace

std::string describe(const PluginIdentity& who) {
  std::string plugin = "plugin " + who.slot + "/" + who.name;
  if (!who.file.empty()) plugin += " (" + who.file + ")";
  return plugin;
}

PluginCallScope::PluginCallScope(const PluginIdentity& who, const char* hook, int iteration) noexcept
    : who_(current_call.who), hook_(current_call.hook), iteration_(current_call.iteration) {
  current_call = {&who, hook, iteration};
}

PluginCallScope::~PluginCallScope() { current_call = {who_, hook_, iteration_}; }

PluginCall current_plugin_call() noexcept { return current_call; }

std::size_t describe_plugin_call(char* out, std::size_t size) noexcept {
  if (size == 0) return 0;
  std::size_t length = 0;
  const PluginCall call = current_call;
  if (call.who) {
    append(out, size, length, "plugin ");
    append(out, size, length, call.who->slot.c_str());
    append(out, size, length, "/");
    append(out, size, length, call.who->name.c_str());
    if (!call.who->file.empty()) {
      append(out, size, length, " (");
      append(out, size, length, call.who->file.c_str());
      append(out, size, length, ")");
    }
    append(out, size, length, " in ");
    append(out, size, length, call.hook);
    if (call.iteration >= 0) {
      append(out, size, length, " in iteration ");
      append_number(out, size, length, call.iteration);
      append(out, size, length, kIterationNumbering);
    }
  }
  out[length] = '\0';
  return length;
}

std::string describe_current_exception() {
  try {
    throw;
  } catch (const std::exception& e) {
    return e.what();
  } catch (...) {
    // Not a std::exception: its type is all there is to say.
    const std::type_info* type = abi::__cxa_current_exception_type();
    if (!type) return "an exception of unknown type";
    int status = 0;
    std::unique_ptr<char, decltype(&std::free)> name(abi::__cxa_demangle(type->name(), nullptr, nullptr, &status),
                                                     std::free);
    return std::string("an exception of type ") + (status == 0 && name ? name.get() : type->name());
  }
}

std::string describe_hook(const char* hook, int iteration) {
  std::string in = hook;
  if (iteration >= 0) in += " in iteration " + std::to_string(iteration) + kIterationNumbering;
  return in;
}

PluginError::~PluginError() = default;
InvalidValueError::~InvalidValueError() = default;

void rethrow_from_plugin(const PluginIdentity& who, const char* hook, int iteration) {
  const std::string plugin = describe(who);
  const std::string in = describe_hook(hook, iteration);
  try {
    throw;
  } catch (const PluginFault&) {
    throw;
  } catch (const std::bad_alloc&) {
    throw OutOfMemoryError("out of memory in " + plugin + " in " + in + " (std::bad_alloc)");
  } catch (...) {
    // With the plugin's own exception nested: the Python package raises a Python hook's from it.
    std::throw_with_nested(PluginError(plugin + " failed in " + in + ": " + describe_current_exception()));
  }
}

}  // namespace aco

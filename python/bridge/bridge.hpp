#pragma once
// The python plugins (init, heuristic and update, each named `python`) hand their hooks to a
// Python object. Only the helper library libaco_python_bridge.so touches Python: a plugin loads
// it when it is created (loader.cpp), so the plugins link no libpython and load alike into
// acoplan and into a Python process, where a second Python runtime would be wrong.
#include <initializer_list>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "aco/settings_table.hpp"
#include "aco/strategies.hpp"

namespace aco::python {

struct Settings {
  std::string object;  // --<slot>.class: module:attribute
  std::string path;  // --<slot>.path: folders put in front of sys.path, ':'-separated
};
// The parameters of every python plugin.
const SettingsTable<Settings>& settings_table();

// The Python object standing in a slot. Every call takes the GIL, so any thread may call.
class Object {
 public:
  virtual ~Object() = default;
  // object.method(context, field), or object.method(context, iteration, field) when `iteration`
  // is given, or object.method(context) when `field` is empty (begin_run). `field` goes over as a writable float64
  // array on its memory, which the method fills in place (or it returns a float64 array of the same length, copied in).
  // An array on the engine's memory that Python still holds after the call is moved onto a
  // read-only copy. A Python exception is thrown as an Error with the py::error_already_set nested.
  virtual void call(const char* method, const Context& context, const Iteration* iteration,
                    std::span<double> field) = 0;
  // A run begins: the arrays made from the last run's graph (its step lengths, ...) are made again.
  virtual void new_run() = 0;
  virtual bool has(const char* method) const = 0;
  // bool(object.attribute), calling it if it is a method; false if there is none.
  virtual bool flag(const char* attribute) const = 0;
};

// The object `values` name (class, path) for `slot`, with the methods `required` lists as
// "name(self, ...)". Loads Python's runtime first if the process has none. Throws aco::Error
// saying what is wrong: no class given, no such module or attribute, a method missing, ...
std::unique_ptr<Object> make_object(const std::string& slot, const ParameterValues& values,
                                    std::initializer_list<const char*> required);

// What each python plugin is: its slot's interface over the object its parameters name.
template <class Interface>
class Adapter : public Interface {
 protected:
  Adapter(const std::string& slot, const ParameterValues& values, std::initializer_list<const char*> required)
      : object_(make_object(slot, values, required)), has_begin_run_(object_->has("begin_run")) {}
  // The object's optional begin_run(self, context): where it resets what it keeps from a run, since
  // one object may serve several runs (the lifecycle of docs/writing-plugins.md).
  void begin_run(const Context& context) override {
    object_->new_run();
    if (has_begin_run_) object_->call("begin_run", context, nullptr, {});
  }
  std::unique_ptr<Object> object_;

 private:
  bool has_begin_run_;
};

// The helper's entry point (dlsym name "aco_python_make_object").
using MakeObject = Object* (*)(const std::string& slot, const std::string& object, const std::string& path,
                               const std::vector<std::string>& required);

}  // namespace aco::python

// libaco_python_bridge.so: the only code that touches Python. Built like an extension module,
// without libpython: its Python symbols are the process's, either the Python process it was
// loaded into or the libpython the plugin loaded first (loader.cpp).
#include <pybind11/embed.h>
#include <pybind11/numpy.h>

#include <exception>
#include <mutex>
#include <sstream>

#include "aco/error.hpp"
#include "bridge.hpp"

namespace py = pybind11;
using namespace py::literals;

namespace aco::python {
namespace {

// A process without Python (acoplan, acobench's workers) gets an interpreter on first use, kept
// until exit: finalising it would break numpy, which cannot be imported twice.
void start_interpreter() {
  static std::once_flag once;
  std::call_once(once, [] {
    if (Py_IsInitialized()) return;
    py::initialize_interpreter(false /* the host's signal handlers stay */, 0, nullptr, false);
    PyEval_SaveThread();  // hand the GIL back, so any thread can take it
  });
}

std::string text(py::handle object) { return py::str(object); }

// "ZeroDivisionError: float division by zero (at bwas.py:12 in update: return 1 / 0)".
std::string describe(const py::error_already_set& e) {
  std::string message = text(e.type().attr("__name__"));
  if (const std::string what = text(e.value()); !what.empty()) message += ": " + what;
  if (!e.trace()) return message;
  const py::list frames = py::module_::import("traceback").attr("extract_tb")(e.trace());
  if (frames.empty()) return message;
  const py::object last = frames[frames.size() - 1];
  message += " (at " + text(last.attr("filename")) + ":" + text(last.attr("lineno")) + " in " + text(last.attr("name"));
  if (const std::string line = text(last.attr("line")); !line.empty()) message += ": " + line;
  return message + ")";
}

void make_read_only(const py::array& array) {
  py::detail::array_proxy(array.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
}

// A read-only copy of `values`: the ants' walks, which the engine overwrites in the next iteration
// (small beside the walks themselves).
template <class T>
py::array read_only_copy(const std::vector<T>& values) {
  py::array copy(py::dtype::of<T>(), {static_cast<py::ssize_t>(values.size())}, values.data());  // no base: copied
  make_read_only(copy);
  return copy;
}

// The arrays one call lends Python on the engine's memory, which the engine reuses or frees after
// the call: the field (tau, eta), too large to copy every iteration, and the graph's arrays. After
// the call, settle() moves every lent array something still holds (the hook kept it, or the frames
// of its exception hold it) onto a read-only copy of its values, so it reads what it held at the
// end of the call and a write to it raises. A view made of a lent array (a slice, a reshape) cannot
// be moved so: each lent array is a view of a hidden base array, which numpy makes the base of
// every such view too, so that they are counted on it.
class LentArrays {
 public:
  explicit LentArrays(const void* memory) : owner_(py::capsule(memory, "aco engine memory")) {}

  template <class T>
  py::array lend(const T* data, std::vector<py::ssize_t> shape, bool writable) {
    py::array base(py::dtype::of<T>(), shape, data, owner_);
    if (!writable) make_read_only(base);  // else numpy lets array.flags.writeable be set
    py::array array(py::dtype::of<T>(), std::move(shape), data, base);  // base's flags
    lent_.push_back({std::move(base), array});
    return array;
  }

  template <class T>
  py::array lend(const std::vector<T>& values) {
    return lend(values.data(), {static_cast<py::ssize_t>(values.size())}, false);
  }

  // After the call, the GIL held and the objects made for it let go: true if a view made of a lent
  // array is still held, which would read the engine's memory after the call.
  bool settle() {
    bool views_left = false;
    for (auto& [base, array] : lent_) {
      const bool held = array.ref_count() > 1;  // lent_ holds one reference
      if (held) move_to_copy(array);
      // The base's references: lent_, the array unless it moved, and the views made of it.
      views_left |= base.ref_count() > (held ? 1 : 2);
    }
    lent_.clear();
    return views_left;
  }

 private:
  struct Loan {
    py::array base, array;
  };

  // numpy has no call to change an array's memory: its fields are set as pybind11 sets its flags.
  static void move_to_copy(py::array& array) {
    std::vector<py::ssize_t> shape(array.shape(), array.shape() + array.ndim());
    py::array copy(array.dtype(), shape, array.data());  // no base: copied
    auto* fields = py::detail::array_proxy(array.ptr());
    fields->data = static_cast<char*>(copy.mutable_data());
    make_read_only(copy);
    PyObject* lent_base = fields->base;
    fields->base = copy.release().ptr();
    Py_DECREF(lent_base);
    make_read_only(array);
  }

  py::object owner_;
  std::vector<Loan> lent_;
};

class PythonObject final : public Object {
 public:
  PythonObject(std::string label, py::object object)
      : label_(std::move(label)),
        object_(std::move(object)),
        namespace_(py::module_::import("types").attr("SimpleNamespace")) {}

  ~PythonObject() override {
    if (!Py_IsInitialized()) {  // a Python process shutting down: nothing left to free into
      object_.release();
      namespace_.release();
      for (py::object* kept : {&cells_, &costs_, &reverse_, &positions_}) kept->release();
      return;
    }
    py::gil_scoped_acquire gil;
    object_ = py::object();
    namespace_ = py::object();
    for (py::object* kept : {&cells_, &costs_, &reverse_, &positions_}) *kept = py::object();
  }

  void call(const char* method, const Context& context, const Iteration* iteration, std::span<double> field) override {
    py::gil_scoped_acquire gil;
    LentArrays lent(field.data() ? static_cast<const void*>(field.data()) : context.graph);
    try {
      call_python(method, context, iteration, field, lent);
    } catch (py::error_already_set& e) {
      // The exception's frames may hold views of the engine's memory: their locals go then.
      if (lent.settle() && e.trace()) py::module_::import("traceback").attr("clear_frames")(e.trace());
      // Nested, for the Python package to raise the exception itself (hosts print the message).
      std::throw_with_nested(Error(label_ + "." + method + "() raised " + describe(e)));
    } catch (...) {
      lent.settle();
      throw;
    }
    if (lent.settle())
      throw Error(label_ + "." + method +
                  "() kept a view made of one of its arrays (a slice, a reshape, ...) past the call, where the "
                  "engine reuses or frees that memory; keep a copy (np.array(...)) instead");
  }

  void new_run() override {
    py::gil_scoped_acquire gil;
    costs_ = reverse_ = positions_ = py::none();  // another run may plan on another graph of the same size
  }

  bool has(const char* method) const override {
    py::gil_scoped_acquire gil;
    return py::hasattr(object_, method);
  }

  bool flag(const char* attribute) const override {
    py::gil_scoped_acquire gil;
    try {
      py::object value = py::getattr(object_, attribute, py::bool_(false));
      if (PyCallable_Check(value.ptr())) value = value();
      return py::bool_(value);
    } catch (py::error_already_set& e) {
      std::throw_with_nested(Error(label_ + "." + attribute + " raised " + describe(e)));
    }
  }

 private:
  // The call itself: every Python object made for it is let go on return, before lent.settle().
  void call_python(const char* method, const Context& context, const Iteration* iteration, std::span<double> field,
                   LentArrays& lent) {
    const py::object c = make_context(context, lent);
    if (!field.data()) {
      object_.attr(method)(c);
      return;
    }
    const py::array values = lent.lend(field.data(), {static_cast<py::ssize_t>(field.size())}, true);
    const py::object result =
        iteration ? object_.attr(method)(c, make_iteration(*iteration), values) : object_.attr(method)(c, values);
    write_back(method, result, field);
  }

  py::object make_context(const Context& c, LentArrays& lent) {
    const Graph& g = *c.graph;
    if (cells_.is_none() || width_ != g.width || height_ != g.height) make_cells(g);
    if (costs_.is_none() || nodes_ != g.num_nodes() || edges_ != g.num_edges()) make_computed_arrays(g);
    const py::object graph = namespace_(
        "width"_a = g.width, "height"_a = g.height, "node_count"_a = g.num_nodes(), "edge_count"_a = g.num_edges(),
        "offsets"_a = lent.lend(g.offsets), "targets"_a = lent.lend(g.targets), "costs"_a = costs_,
        "reverse"_a = reverse_, "positions"_a = positions_, "cells"_a = cells_,
        "neighbourhood"_a = static_cast<int>(g.options.neighbourhood), "corner_cutting"_a = g.options.corner_cutting);
    return namespace_("graph"_a = graph, "start"_a = c.start, "goal"_a = c.goal, "ants"_a = c.ants,
                      "max_iterations"_a = c.max_iterations, "alpha"_a = c.alpha, "beta"_a = c.beta, "seed"_a = c.seed,
                      "iteration"_a = c.iteration);
  }

  // Cells are not stored in the graph: computed once per map size, and kept (a copy, not a view).
  void make_cells(const Graph& g) {
    py::array_t<std::int32_t> cells({static_cast<py::ssize_t>(g.num_nodes()), py::ssize_t{2}});
    auto out = cells.mutable_unchecked<2>();
    for (NodeId n = 0; n < g.num_nodes(); ++n) {
      const Cell cell = g.cell(n);
      out(n, 0) = cell.x;
      out(n, 1) = cell.y;
    }
    make_read_only(cells);
    cells_ = std::move(cells);
    width_ = g.width;
    height_ = g.height;
  }

  // The graph computes step lengths, reverse edges and positions from its moves and cells instead
  // of storing them (aco/graph.hpp): made once per run (begin_run()) and kept (copies, not views).
  void make_computed_arrays(const Graph& g) {
    py::array_t<double> costs(g.num_edges());
    py::array_t<std::int32_t> reverse(g.num_edges());
    py::array_t<double> positions({static_cast<py::ssize_t>(g.num_nodes()), py::ssize_t{3}});
    auto cost = costs.mutable_unchecked<1>();
    auto back = reverse.mutable_unchecked<1>();
    auto at = positions.mutable_unchecked<2>();
    for (EdgeId e = 0; e < g.num_edges(); ++e) {
      cost(e) = g.cost(e);
      back(e) = g.reverse_edge(e);
    }
    for (NodeId n = 0; n < g.num_nodes(); ++n) {
      const Eigen::Vector3d p = g.position(n);
      for (int k = 0; k < 3; ++k) at(n, k) = p[k];
    }
    for (const py::array& array : {py::array(costs), py::array(reverse), py::array(positions)}) make_read_only(array);
    costs_ = std::move(costs);
    reverse_ = std::move(reverse);
    positions_ = std::move(positions);
    nodes_ = g.num_nodes();
    edges_ = g.num_edges();
  }

  py::object make_ant(const Ant& ant) {
    return namespace_("nodes"_a = read_only_copy(ant.nodes), "edges"_a = read_only_copy(ant.edges),
                      "length"_a = ant.length, "arrived"_a = ant.arrived);
  }

  py::object make_iteration(const Iteration& it) {
    py::list ants(it.ants.size());
    for (std::size_t k = 0; k < it.ants.size(); ++k) ants[k] = make_ant(it.ants[k]);
    // The best ants are the same Python objects as in ants when they are ants of this iteration.
    const auto find = [&](const Ant* ant) -> py::object {
      if (ant == nullptr) return py::none();
      if (ant >= it.ants.data() && ant < it.ants.data() + it.ants.size()) return ants[ant - it.ants.data()];
      return make_ant(*ant);
    };
    return namespace_("ants"_a = ants, "best"_a = find(it.best), "best_so_far"_a = find(it.best_so_far));
  }

  void write_back(const char* method, const py::object& result, std::span<double> field) {
    if (result.is_none()) return;
    const std::size_t size = field.size();
    const std::string returned = label_ + "." + method + "() returned ";
    const std::string expected = "; return None (with the array filled in place) or a float64 array of " +
                                 std::to_string(size) + " values, one per edge";
    if (!py::isinstance<py::array>(result))
      throw Error(returned + "a " + text(result.get_type().attr("__name__")) + expected);
    const auto array = py::reinterpret_borrow<py::array>(result);
    if (array.ndim() != 1 || array.shape(0) != static_cast<py::ssize_t>(size))
      throw Error(returned + "an array of shape " + text(result.attr("shape")) + expected);
    if (!py::isinstance<py::array_t<double>>(result))
      throw Error(returned + "an array of dtype " + text(array.dtype()) + expected);
    if (array.data() != field.data())
      std::copy_n(py::array_t<double, py::array::c_style | py::array::forcecast>(array).data(), size, field.data());
  }

  std::string label_;  // module:attribute, as given
  py::object object_;
  py::object namespace_;  // types.SimpleNamespace
  py::object cells_ = py::none();
  int width_ = 0, height_ = 0;
  py::object costs_ = py::none(), reverse_ = py::none(), positions_ = py::none();
  int nodes_ = 0, edges_ = 0;
};

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::istringstream in(text);
  for (std::string part; std::getline(in, part, separator);)
    if (!part.empty()) parts.push_back(part);
  return parts;
}

// The folders of `path` at the front of sys.path, in their order, as absolute paths (a later
// change of the working directory must not change what imports).
void prepend_to_sys_path(const std::string& path) {
  py::list sys_path = py::module_::import("sys").attr("path");
  const py::object absolute = py::module_::import("os.path").attr("abspath");
  const auto folders = split(path, ':');
  for (auto folder = folders.rbegin(); folder != folders.rend(); ++folder) {
    const py::object entry = absolute(*folder);
    while (sys_path.contains(entry)) sys_path.attr("remove")(entry);
    sys_path.insert(0, entry);
  }
}

py::object find_object(const std::string& slot, const std::string& spec, const std::string& path) {
  const std::string key = slot + ".class";
  if (spec.empty())
    throw Error(key + " is empty: name the Python object as module:attribute, e.g. --" + key +
                " my_module:MyClass (--" + slot + ".path adds folders to sys.path)");
  const auto colon = spec.find(':');
  if (colon == std::string::npos || colon == 0 || colon + 1 == spec.size())
    throw Error(key + " '" + spec + "' is not module:attribute (e.g. my_module:MyClass)");
  const std::string module_name = spec.substr(0, colon);
  try {
    py::module_::import("numpy");
  } catch (py::error_already_set& e) {
    std::throw_with_nested(
        Error("the python plugins need numpy (on Debian, python3-numpy), which cannot be imported: " + describe(e)));
  }
  prepend_to_sys_path(path);
  py::object object;
  try {
    object = py::module_::import(module_name.c_str());
  } catch (py::error_already_set& e) {
    if (e.matches(PyExc_ModuleNotFoundError) && text(e.value().attr("name")) == module_name) {
      std::string message = key + " '" + spec + "': no Python module '" + module_name + "' (searched sys.path:";
      for (const auto& entry : py::module_::import("sys").attr("path")) message += " " + text(entry);
      throw Error(message + "; --" + slot + ".path adds folders)");
    }
    std::throw_with_nested(
        Error(key + " '" + spec + "': importing module '" + module_name + "' raised " + describe(e)));
  }
  std::string walked = module_name;
  for (const auto& name : split(spec.substr(colon + 1), '.')) {
    if (!py::hasattr(object, name.c_str())) {
      const std::string file =
          walked == module_name ? " (" + text(py::getattr(object, "__file__", py::str("?"))) + ")" : "";
      throw Error(key + " '" + spec + "': " + walked + file + " has no attribute '" + name + "'");
    }
    object = object.attr(name.c_str());
    walked += (walked == module_name ? ":" : ".") + name;
  }
  if (py::isinstance<py::type>(object)) {
    try {
      object = object();
    } catch (py::error_already_set& e) {
      std::throw_with_nested(Error(key + " '" + spec + "': making the object, " + spec + "(), raised " + describe(e)));
    }
  }
  return object;
}

}  // namespace
}  // namespace aco::python

extern "C" __attribute__((visibility("default"))) aco::python::Object* aco_python_make_object(
    const std::string& slot, const std::string& spec, const std::string& path,
    const std::vector<std::string>& required) {
  using namespace aco::python;
  start_interpreter();
  py::gil_scoped_acquire gil;
  py::object object = find_object(slot, spec, path);
  for (const auto& signature : required) {
    const std::string name = signature.substr(0, signature.find('('));
    if (!PyCallable_Check(py::getattr(object, name.c_str(), py::none()).ptr()))
      throw aco::Error(slot + ".class '" + spec + "': the object has no method " + signature);
  }
  return new PythonObject(spec, std::move(object));
}

static_assert(std::is_same_v<decltype(&aco_python_make_object), aco::python::MakeObject>,
              "the plugins call the entry point through MakeObject");

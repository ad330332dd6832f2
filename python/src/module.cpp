// The native half of the Python package: aco._aco. The package's Python files (python/aco/) wrap it.
#include <pybind11/pybind11.h>

namespace py = pybind11;

PYBIND11_MODULE(_aco, m) {
  m.doc() = "aco's native module; use the package: import aco";
}

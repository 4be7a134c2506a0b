#pragma once
// The devices every exercise's API is made of (devices.hpp), bound under their C++ names. The
// laser's ranges are numpy arrays over the C++ scan (no copy): read-only views that always
// show the latest scan (Laser::set keeps its buffer).

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <vector>

namespace aula::python {
namespace py = pybind11;

// Pose3d, LaserData, Laser, BumperData, Bumper and Motors into `m`.
void bindDevices(py::module_& m);
// Belief (what the algorithm believes: its own pose and map), for the APIs that give one.
void bindBelief(py::module_& m);

// A numpy array over `values` (no copy), kept valid by `owner`; read-only unless `writable`.
template <class T>
py::array_t<T> arrayView(const T* values, std::vector<py::ssize_t> shape, py::handle owner, bool writable = false) {
  py::array_t<T> view(std::move(shape), values, owner);
  if (!writable) py::detail::array_proxy(view.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return view;
}

}  // namespace aula::python

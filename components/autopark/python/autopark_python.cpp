// Autopark's Python host: MyAlgorithm.py on AutoparkApi, the same objects under the same names
// as the C++ API (autopark_algorithm.hpp): the pose, the three lasers, the motors, the lasers'
// mounts, the car's size and kinematics, and the status line the window shows.
#include <aula/autopark/autopark_algorithm.hpp>
#include <aula/python/devices_python.hpp>
#include <aula/python/python_host.hpp>

#include <pybind11/embed.h>
#include <pybind11/functional.h>

namespace {
namespace py = pybind11;
using aula::autopark::AutoparkApi;
using aula::autopark::LaserMount;

constexpr char kApiModule[] = "aula_autopark";
using PythonAutopark = aula::python::PythonExecuteAlgorithm<aula::autopark::AutoparkAlgorithm, AutoparkApi, kApiModule>;

}  // namespace

PYBIND11_EMBEDDED_MODULE(aula_autopark, m) {
  aula::python::bindDevices(m);
  py::class_<LaserMount>(m, "LaserMount")
      .def_readonly("x_m", &LaserMount::x_m)
      .def_readonly("y_m", &LaserMount::y_m)
      .def_readonly("yaw_rad", &LaserMount::yaw_rad);
  m.def("forEachEcho",
        [](double car_x_m, double car_y_m, double car_yaw_rad, const LaserMount& mount,
           const aula::component::LaserData& scan, const std::function<void(double, double)>& echo) {
          aula::autopark::forEachEcho(car_x_m, car_y_m, car_yaw_rad, mount, scan, echo);
        });
  using aula::component::Laser;
  const auto ref = py::return_value_policy::reference;
  py::class_<AutoparkApi>(m, "AutoparkApi")
      .def_property_readonly("pose3d", [](AutoparkApi& api) -> aula::component::Pose3d& { return api.pose3d; }, ref)
      .def_property_readonly("laser1", [](AutoparkApi& api) -> Laser& { return api.laser1; }, ref)
      .def_property_readonly("laser2", [](AutoparkApi& api) -> Laser& { return api.laser2; }, ref)
      .def_property_readonly("laser3", [](AutoparkApi& api) -> Laser& { return api.laser3; }, ref)
      .def_property_readonly("motors", [](AutoparkApi& api) -> aula::component::Motors& { return api.motors; }, ref)
      .def_readonly("period_s", &AutoparkApi::period_s)
      .def_readonly("mount1", &AutoparkApi::mount1)
      .def_readonly("mount2", &AutoparkApi::mount2)
      .def_readonly("mount3", &AutoparkApi::mount3)
      .def_readonly("car_length_m", &AutoparkApi::car_length_m)
      .def_readonly("car_width_m", &AutoparkApi::car_width_m)
      .def_readonly("min_turn_radius_m", &AutoparkApi::min_turn_radius_m)
      .def_readonly("turn_centre_x_m", &AutoparkApi::turn_centre_x_m)
      .def_readonly("wheelbase_m", &AutoparkApi::wheelbase_m)
      .def_readwrite("status", &AutoparkApi::status)
      .def("time_s", &AutoparkApi::time_s);
}

AULA_PYTHON_HOST_ENTRY_POINTS(autopark, aula::autopark::AutoparkAlgorithm, PythonAutopark)

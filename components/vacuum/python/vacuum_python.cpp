// The vacuum cleaner's Python host: MyAlgorithm.py on VacuumApi, the same objects under the
// same names as the C++ API (vacuum_algorithm.hpp).
#include <aula/python/devices_python.hpp>
#include <aula/python/python_host.hpp>
#include <aula/vacuum/vacuum_algorithm.hpp>

#include <pybind11/embed.h>

namespace {
namespace py = pybind11;
using aula::vacuum::VacuumApi;
using aula::vacuum::YawSensor;

constexpr char kApiModule[] = "aula_vacuum";
using PythonVacuum = aula::python::PythonExecuteAlgorithm<aula::vacuum::VacuumAlgorithm, VacuumApi, kApiModule>;

}  // namespace

PYBIND11_EMBEDDED_MODULE(aula_vacuum, m) {
  aula::python::bindDevices(m);
  aula::python::bindBelief(m);
  py::class_<YawSensor>(m, "YawSensor").def("getYaw", &YawSensor::getYaw);
  const auto ref = py::return_value_policy::reference;
  py::class_<VacuumApi>(m, "VacuumApi")
      .def_property_readonly("pose3d", [](VacuumApi& api) -> YawSensor& { return api.pose3d; }, ref)
      .def_property_readonly("laser", [](VacuumApi& api) -> aula::component::Laser& { return api.laser; }, ref)
      .def_property_readonly("bumper", [](VacuumApi& api) -> aula::component::Bumper& { return api.bumper; }, ref)
      .def_property_readonly("motors", [](VacuumApi& api) -> aula::component::Motors& { return api.motors; }, ref)
      .def_property_readonly("belief", [](VacuumApi& api) -> aula::component::Belief& { return api.belief; }, ref)
      .def_readonly("period_s", &VacuumApi::period_s)
      .def("time_s", &VacuumApi::time_s);
}

AULA_PYTHON_HOST_ENTRY_POINTS(vacuum, aula::vacuum::VacuumAlgorithm, PythonVacuum)

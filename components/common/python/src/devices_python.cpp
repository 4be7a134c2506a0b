#include "aula/python/devices_python.hpp"

#include <aula/component/devices.hpp>

#include <pybind11/numpy.h>

#include <stdexcept>

namespace aula::python {

void bindDevices(py::module_& m) {
  using namespace aula::component;
  py::class_<Pose3d>(m, "Pose3d")
      .def("getX", &Pose3d::getX)
      .def("getY", &Pose3d::getY)
      .def("getYaw", &Pose3d::getYaw)
      .def("getRobotX", &Pose3d::getRobotX)
      .def("getRobotY", &Pose3d::getRobotY)
      .def("getRobotTheta", &Pose3d::getRobotTheta)
      .def("received", &Pose3d::received)
      .def("utime", &Pose3d::utime);
  py::class_<LaserData>(m, "LaserData")
      .def_property_readonly("values_m",
                             [](py::object self) {
                               const auto& data = self.cast<const LaserData&>();
                               return arrayView(data.values_m.data(), {py::ssize_t(data.values_m.size())}, self);
                             })
      .def_property_readonly("distanceData",
                             [](py::object self) {
                               const auto& data = self.cast<const LaserData&>();
                               return arrayView(data.distanceData.data(), {py::ssize_t(data.distanceData.size())}, self);
                             })
      .def_readonly("numLaser", &LaserData::numLaser)
      .def_readonly("minAngle", &LaserData::minAngle)
      .def_readonly("maxAngle", &LaserData::maxAngle)
      .def_readonly("angleIncrement", &LaserData::angleIncrement)
      .def_readonly("minRange", &LaserData::minRange)
      .def_readonly("maxRange", &LaserData::maxRange)
      .def_readonly("timeStamp", &LaserData::timeStamp)
      .def("angle", &LaserData::angle);
  py::class_<Laser>(m, "Laser")
      .def("getLaserData", &Laser::getLaserData, py::return_value_policy::reference_internal)
      .def("received", &Laser::received);
  py::class_<BumperData>(m, "BumperData")
      .def_readonly("bumper", &BumperData::bumper)
      .def_readonly("state", &BumperData::state)
      .def_readonly("timeStamp", &BumperData::timeStamp);
  py::class_<Bumper>(m, "Bumper").def("getBumperData", &Bumper::getBumperData, py::return_value_policy::reference_internal);
  py::class_<Motors>(m, "Motors")
      .def("sendV", &Motors::sendV)
      .def("sendW", &Motors::sendW)
      .def("sendL", &Motors::sendL)
      .def("setV", &Motors::setV)
      .def("setW", &Motors::setW)
      .def("stop", &Motors::stop)
      .def("getV", &Motors::getV)
      .def("getW", &Motors::getW)
      .def("getL", &Motors::getL)
      .def("maxV", &Motors::maxV)
      .def("maxW", &Motors::maxW);
}

void bindBelief(py::module_& m) {
  using namespace aula::component;
  // The cells as a 2-D array: row r, column c is the cell at x = origin_x_m + c * resolution_m,
  // y = origin_y_m + r * resolution_m (0 free .. 255 occupied, 128 unknown).
  using Cells = py::array_t<uint8_t, py::array::c_style | py::array::forcecast>;
  py::class_<Belief>(m, "Belief")
      .def("setPose", &Belief::setPose, py::arg("x_m"), py::arg("y_m"), py::arg("yaw_rad"))
      .def(
          "setMap",
          [](Belief& belief, const Cells& cells, double resolution_m, double origin_x_m, double origin_y_m) {
            if (cells.ndim() != 2) throw std::invalid_argument("Belief.setMap: cells must be a 2-D array (rows of y, columns of x)");
            BeliefMap map;
            map.height = static_cast<int>(cells.shape(0));
            map.width = static_cast<int>(cells.shape(1));
            map.resolution_m = resolution_m;
            map.origin_x_m = origin_x_m;
            map.origin_y_m = origin_y_m;
            map.cells.assign(cells.data(), cells.data() + cells.size());
            belief.setMap(std::move(map));
          },
          py::arg("cells"), py::arg("resolution_m"), py::arg("origin_x_m") = 0.0, py::arg("origin_y_m") = 0.0);
}

}  // namespace aula::python

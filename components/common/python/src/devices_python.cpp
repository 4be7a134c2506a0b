#include "aula/python/devices_python.hpp"

#include <aula/component/devices.hpp>

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

}  // namespace aula::python

// TeleTaxi's Python host: MyAlgorithm.py on TaxiApi, the same objects under the same names as
// the C++ API (taxi_algorithm.hpp, grid.hpp). The grid's map, field and path are numpy arrays
// over the Grid's own memory (no copy): the map read-only, the field and the path writable, as
// setVal/setPathVal write them.
#include <aula/python/devices_python.hpp>
#include <aula/python/python_host.hpp>
#include <aula/teletaxi/taxi_algorithm.hpp>

#include <pybind11/embed.h>
#include <pybind11/stl.h>

namespace {
namespace py = pybind11;
using aula::teletaxi::Grid;
using aula::teletaxi::TaxiApi;

class PythonTaxi : public aula::teletaxi::TaxiAlgorithm {
 public:
  explicit PythonTaxi(uint64_t seed) : algorithm_(seed, "aula_teletaxi") {}
  // A program in RoboticsAcademy's shape plans at its top and drives in its loop: "Generate Path"
  // runs it until it first waits (its path shown), and the taxi moves only at GO!.
  void generatePath(TaxiApi& api) override {
    algorithm_.call("generatePath", api);
    if (algorithm_.isProgram()) api.motors.stop();
  }
  void execute(TaxiApi& api) override { algorithm_.call("execute", api); }

 private:
  aula::python::PythonAlgorithm algorithm_;
};

// A view of one of the grid's images (continuous, allocated once with the grid).
template <class T>
py::array_t<T> gridImage(py::object grid, const cv::Mat& image, bool writable) {
  return aula::python::arrayView(image.ptr<T>(), {image.rows, image.cols}, grid, writable);
}

}  // namespace

PYBIND11_EMBEDDED_MODULE(aula_teletaxi, m) {
  aula::python::bindDevices(m);
  py::class_<Grid>(m, "Grid")
      .def("getWidth", &Grid::getWidth)
      .def("getHeight", &Grid::getHeight)
      .def("getMap", [](py::object self) { return gridImage<uint8_t>(self, self.cast<Grid&>().getMap(), false); })
      .def("isFree", &Grid::isFree)
      .def("getDestiny", &Grid::getDestiny)
      .def("getPose", &Grid::getPose)
      .def("setDestiny", &Grid::setDestiny)
      .def("setPose", &Grid::setPose)
      .def("setVal", &Grid::setVal)
      .def("getVal", &Grid::getVal)
      .def("field", [](py::object self) { return gridImage<float>(self, self.cast<Grid&>().field(), true); })
      .def("setPathVal", &Grid::setPathVal)
      .def("getPathVal", &Grid::getPathVal)
      .def("path", [](py::object self) { return gridImage<float>(self, self.cast<Grid&>().path(), true); })
      .def("setPathFinded", &Grid::setPathFinded)
      .def("isPathFinded", &Grid::isPathFinded)
      .def("resetPath", &Grid::resetPath)
      .def("showGrid", &Grid::showGrid)
      .def("fieldImage",
           [](const Grid& grid) {  // a new picture: a copy, as in C++
             const cv::Mat image = grid.fieldImage();
             py::array_t<uint8_t> out({image.rows, image.cols});
             for (int y = 0; y < image.rows; ++y) std::copy_n(image.ptr<uint8_t>(y), image.cols, out.mutable_data(y, 0));
             return out;
           })
      .def("gridToWorld", &Grid::gridToWorld)
      .def("worldToGrid", &Grid::worldToGrid);
  const auto ref = py::return_value_policy::reference;
  py::class_<TaxiApi>(m, "TaxiApi")
      .def_property_readonly("pose3d", [](TaxiApi& api) -> aula::component::Pose3d& { return api.pose3d; }, ref)
      .def_property_readonly("motors", [](TaxiApi& api) -> aula::component::Motors& { return api.motors; }, ref)
      .def_property_readonly("grid", [](TaxiApi& api) -> Grid& { return api.grid; }, ref)
      .def_property_readonly("sensor", [](TaxiApi& api) -> aula::component::Pose3d& { return api.sensor; }, ref)
      .def_property_readonly("vel", [](TaxiApi& api) -> aula::component::Motors& { return api.vel; }, ref)
      .def("time_s", &TaxiApi::time_s);
}

AULA_PYTHON_HOST_ENTRY_POINTS(teletaxi, aula::teletaxi::TaxiAlgorithm, PythonTaxi)

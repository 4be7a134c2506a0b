# The student API: the headers a plugin compiles against, each as DIR:SOURCE (installed to
# include/aula/DIR by AulaInstall.cmake; a header may include only others of this list, the
# generated LCM types, and what the API's targets bring: OpenCV core, Eigen). Their hash, taken by
# aula_api_headers_sha256 (cmake/aula_api_hash.cmake), is recorded next to the plugin ABI
# version (components/common/include/aula/component/algorithm_plugin.hpp) and checked by the
# test AlgorithmAbi.*: when the API changes, the version must be raised.
set(AULA_API_HEADERS
  component:components/common/include/aula/component/devices.hpp
  component:components/common/include/aula/component/algorithm_plugin.hpp
  vacuum:components/vacuum/include/aula/vacuum/vacuum_algorithm.hpp
  teletaxi:components/teletaxi/include/aula/teletaxi/taxi_algorithm.hpp
  teletaxi:components/teletaxi/include/aula/teletaxi/grid.hpp
  teletaxi:components/teletaxi/include/aula/teletaxi/gradient_field.hpp
  teletaxi:components/teletaxi/include/aula/teletaxi/path_pilot.hpp
  # The old path of the map transform, for plugins that still include it.
  world:libs/world/include/aula/world/map_transform.hpp
  autopark:components/autopark/include/aula/autopark/autopark_algorithm.hpp
  autopark:components/autopark/include/aula/autopark/slot_detector.hpp
  autopark:components/autopark/include/aula/autopark/street_search.hpp
  autopark:components/autopark/planner/include/aula/autopark/car_geometry.hpp
  # The shared plane geometry the API headers above are written in.
  geometry:libs/geometry/include/aula/geometry/angles.hpp
  geometry:libs/geometry/include/aula/geometry/map_transform.hpp
  geometry:libs/geometry/include/aula/geometry/oriented_box.hpp
  geometry:libs/geometry/include/aula/geometry/pose2d.hpp)

include(${CMAKE_CURRENT_LIST_DIR}/aula_api_hash.cmake)
aula_api_headers_sha256(AULA_API_HEADERS_SHA256 ${PROJECT_SOURCE_DIR} ${AULA_API_HEADERS})
# A header's change reconfigures the build, so the hash the test compares is always the current one.
foreach(_entry ${AULA_API_HEADERS})
  string(REGEX REPLACE "^[^:]*:" "" _file "${_entry}")
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/${_file})
endforeach()

# The student API: the headers a plugin compiles against (the common ones here, each exercise's
# declared in its own folder by aula_exercise), each as DIR:SOURCE (installed to
# include/aula/DIR by AulaInstall.cmake; a header may include only others of this list, the
# generated LCM types, and what the API's targets bring: OpenCV core, Eigen). Their hash, taken by
# aula_api_headers_sha256 (cmake/aula_api_hash.cmake), is recorded next to the plugin ABI
# version (components/common/include/aula/component/algorithm_plugin.hpp) and checked by the
# test AlgorithmAbi.*: when the API changes, the version must be raised.
set(AULA_API_HEADERS
  component:components/common/include/aula/component/devices.hpp
  component:components/common/include/aula/component/algorithm_plugin.hpp
  # The old path of the map transform, for plugins that still include it.
  world:libs/world/include/aula/world/map_transform.hpp
  # The shared plane geometry the API headers above are written in.
  geometry:libs/geometry/include/aula/geometry/angles.hpp
  geometry:libs/geometry/include/aula/geometry/map_transform.hpp
  geometry:libs/geometry/include/aula/geometry/oriented_box.hpp
  geometry:libs/geometry/include/aula/geometry/pose2d.hpp)

# The exercises add their own (aula_exercise API_HEADERS); aula_finish_exercises takes the hash.
include(${CMAKE_CURRENT_LIST_DIR}/aula_api_hash.cmake)

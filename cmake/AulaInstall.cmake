# What `cmake --install` puts in a prefix, and the .deb CPack makes of it:
#   bin/                     every program (aula, aula-sim, the components and referees, tools)
#   lib/aula/algorithms/     the in-tree templates, built as plugins (--algorithm=student)
#   lib/aula/references/     the built-in algorithms, a plugin each (--algorithm=reference...)
#   lib/aula/libaula_sim_view.so   aula-sim --gui's 3D view, opened only with --gui
#   lib/aula/python/         the Python hosts, one per exercise (--algorithm=PATH.py)
#   include/aula/            the student API (plain-data devices, the plugin ABI, the three
#                            *_algorithm.hpp and what they include: AULA_API_HEADERS) and the
#                            generated LCM types
#   lib/cmake/Aula/          find_package(Aula): Aula::<exercise>_api and aula_add_algorithm
#   share/aula/              worlds (with models and generators), configs, student templates,
#                            the built-in algorithms' sources (references/<exercise>/<name>/: what
#                            `aula grade` compares a class's code with)
#   share/doc/aula/          the user's documentation (`aula --help` names it: config::docDir),
#                            the copyright file (Apache-2.0) and the changelogs
#                            (MyAlgorithm.cpp, MyAlgorithm.py and the Python API's .pyi stubs)
# Nothing in a binary names the source or build tree: programs find share/aula next to their
# own bin/ (config::dataDir), and maps are drawn into the user's cache.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

# Each declared exercise's programs, template plugin and Python host (aula_exercise).
set(_exercise_programs)
set(_exercise_students)
set(_exercise_pythons)
set(_exercise_apis)
foreach(_exercise ${AULA_EXERCISES})
  foreach(_key COMPONENT REFEREE)
    get_property(_target GLOBAL PROPERTY AULA_EXERCISE_${_exercise}_${_key})
    list(APPEND _exercise_programs ${_target})
  endforeach()
  get_property(_target GLOBAL PROPERTY AULA_EXERCISE_${_exercise}_STUDENT)
  list(APPEND _exercise_students ${_target})
  get_property(_target GLOBAL PROPERTY AULA_EXERCISE_${_exercise}_PYTHON)
  list(APPEND _exercise_pythons ${_target})
  get_property(_target GLOBAL PROPERTY AULA_EXERCISE_${_exercise}_API)
  list(APPEND _exercise_apis ${_target})
  set_target_properties(${_target} PROPERTIES EXPORT_NAME ${_exercise}_api)
endforeach()
set(AULA_PROGRAMS aula aula-sim aula-mapgen aula-demo-client aula-replay ${_exercise_programs})
install(TARGETS ${AULA_PROGRAMS} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS ${_exercise_students} LIBRARY DESTINATION lib/aula/algorithms)
get_property(_builtins GLOBAL PROPERTY AULA_BUILTIN_ALGORITHMS)
install(TARGETS ${_builtins} LIBRARY DESTINATION lib/aula/references)
install(TARGETS aula_sim_view LIBRARY DESTINATION lib/aula)
install(TARGETS ${_exercise_pythons} LIBRARY DESTINATION lib/aula/python)

# The API a plugin compiles against (AULA_API_HEADERS, cmake/AulaApi.cmake). Not the proxies: they
# feed the devices from Aula's bus, a library a plugin never links.
set(_src ${PROJECT_SOURCE_DIR})
foreach(_entry ${AULA_API_HEADERS})
  string(REGEX MATCH "^[^:]*" _dir "${_entry}")
  string(REGEX REPLACE "^[^:]*:" "" _file "${_entry}")
  install(FILES ${_src}/${_file} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/aula/${_dir})
endforeach()
install(DIRECTORY ${PROJECT_BINARY_DIR}/lcmtypes/lcmgen/aula DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})

# find_package(Aula)
set_target_properties(aula_component_api PROPERTIES EXPORT_NAME component_api)
install(TARGETS aula_component_api ${_exercise_apis} EXPORT AulaTargets)
# Always lib/ (not the multiarch libdir): programs find their plugins at <bin>/../lib/aula.
set(AULA_CMAKE_DIR lib/cmake/Aula)
install(EXPORT AulaTargets NAMESPACE Aula:: DESTINATION ${AULA_CMAKE_DIR})
configure_package_config_file(${_src}/cmake/AulaConfig.cmake.in ${PROJECT_BINARY_DIR}/AulaConfig.cmake
                              INSTALL_DESTINATION ${AULA_CMAKE_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/AulaConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/AulaConfig.cmake ${PROJECT_BINARY_DIR}/AulaConfigVersion.cmake
              ${_src}/cmake/AulaAlgorithm.cmake ${_src}/cmake/aula_algorithm_entry.cpp.in
        DESTINATION ${AULA_CMAKE_DIR})
# The build tree is a package too (`aula new` from build/bin finds it): same config, targets
# pointing at the sources.
export(EXPORT AulaTargets NAMESPACE Aula:: FILE ${PROJECT_BINARY_DIR}/AulaTargets.cmake)
configure_file(${_src}/cmake/AulaAlgorithm.cmake ${PROJECT_BINARY_DIR}/AulaAlgorithm.cmake COPYONLY)
configure_file(${_src}/cmake/aula_algorithm_entry.cpp.in ${PROJECT_BINARY_DIR}/aula_algorithm_entry.cpp.in COPYONLY)

# Data.
install(DIRECTORY ${_src}/worlds ${_src}/config DESTINATION ${CMAKE_INSTALL_DATADIR}/aula
        PATTERN "__pycache__" EXCLUDE)
# The student templates (`aula new`): each exercise's TEMPLATES folder, its links followed.
foreach(_exercise ${AULA_EXERCISES})
  get_property(_templates GLOBAL PROPERTY AULA_EXERCISE_${_exercise}_TEMPLATES)
  file(GLOB _files LIST_DIRECTORIES false ${_templates}/*)
  foreach(_file ${_files})
    get_filename_component(_name ${_file} NAME)
    file(REAL_PATH ${_file} _real)
    install(FILES ${_real} DESTINATION ${CMAKE_INSTALL_DATADIR}/aula/templates/${_exercise} RENAME ${_name})
  endforeach()
endforeach()

# Each built-in algorithm's sources (aula_add_builtin_algorithm's CODE).
get_property(_builtin_code GLOBAL PROPERTY AULA_BUILTIN_CODE)
foreach(_builtin ${_builtin_code})
  get_property(_files GLOBAL PROPERTY AULA_BUILTIN_CODE_${_builtin})
  install(FILES ${_files} DESTINATION ${CMAKE_INSTALL_DATADIR}/aula/references/${_builtin})
endforeach()

# The user's documentation, where `aula --help` and the docs' links point (config::docDir), and
# what Debian asks of every package: a machine-readable copyright and a gzipped changelog.
install(FILES ${_src}/README.md ${_src}/CHANGELOG.md ${_src}/docs/grading.md ${_src}/docs/worlds.md
        ${_src}/docs/architecture.md ${_src}/docs/adding-an-exercise.md ${_src}/docs/copyright
        DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/aula)
install(DIRECTORY ${_src}/docs/exercises DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/aula)
set(_aula_changelog_date "Tue, 24 Nov 2026 00:00:00 +0000")  # fixed: the package builds reproducibly
file(WRITE ${PROJECT_BINARY_DIR}/changelog.Debian
  "aula (${PROJECT_VERSION}) unstable; urgency=medium\n\n"
  "  * Release ${PROJECT_VERSION}: see /usr/share/doc/aula/CHANGELOG.md.\n\n"
  " -- Aula developers <aula@example.org>  ${_aula_changelog_date}\n")
execute_process(COMMAND gzip -9nf ${PROJECT_BINARY_DIR}/changelog.Debian)
install(FILES ${PROJECT_BINARY_DIR}/changelog.Debian.gz DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/aula)

# cpack -G DEB: aula_<version>_amd64.deb. Runtime Depends come from dpkg-shlibdeps (libpython3.11 or
# 3.13 too); a student's plugin build needs a compiler, CMake and the headers the API includes; a
# student's MyAlgorithm.py, Debian's python3 with numpy and cv2 (the embedded interpreter's); a
# component names a crash's lines in the student's plugin with /usr/bin/addr2line (binutils).
set(CPACK_PACKAGE_NAME aula)
set(CPACK_PACKAGE_VENDOR "Aula")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "Robotics teaching environment: TeleTaxi, Vacuum cleaner and Autopark exercises")
set(CPACK_PACKAGE_CONTACT "Aula developers <aula@example.org>")
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION "Aula recreates three exercises of the JdeRobot Robotics-Academy: global navigation with
 Gradient Path Planning (TeleTaxi), coverage of a house without localization (Vacuum
 cleaner) and parallel parking with three lasers (Autopark). Each has a DART simulator
 world, an academic component with a Qt5 window around the student's algorithm, a
 reference solution and an automatic referee; `aula grade` grades a class in a sandbox.")
# Installed programs and modules carry no debug information (Debian's policy; lintian).
set(CPACK_STRIP_FILES ON)
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS
    "cmake, g++, binutils, libeigen3-dev, libopencv-dev, liblcm-dev, bubblewrap, python3, python3-numpy, python3-opencv, python3-greenlet")
# aula grade --engine=slurm submits with sbatch; report.html screenshots use a browser.
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "slurm-client")
include(CPack)

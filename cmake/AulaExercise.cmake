# An exercise declares itself in its own folder, as a Nav2 plugin does: components/<name>/CMakeLists.txt
# calls aula_exercise(), and everything that serves every exercise (the `aula` front door, `./aula
# run NAME`, the install rules, the student API's headers and their hash, `aula grade`'s player,
# the tests) iterates over the declared set. No list outside an exercise's folders names it.
#
#   aula_exercise(NAME vacuum
#     DECLARATION exercise.cpp            # C++: programs, settings tables, calibration (aula/settings/tables.hpp)
#     COMPONENT vacuum-cleaner REFEREE vacuum-cleaner-referee   # the programs' targets
#     API aula_vacuum_api                 # the student API target (aula_declare_algorithm_api)
#     API_HEADERS vacuum:include/aula/vacuum/vacuum_algorithm.hpp ...   # DIR:FILE, installed to include/aula/DIR
#     ABI_VERSION 1                       # the version of this API a plugin is built for (see below)
#     ABI_HEADERS_SHA256 17b4...          # API_HEADERS' hash when ABI_VERSION was set
#     STUDENT aula_vacuum_student         # the in-tree template built as a plugin
#     PYTHON aula_vacuum_python           # the Python host (aula_add_python_host)
#     TEMPLATES student                   # the folder `aula new` copies (MyAlgorithm.cpp, .py, the .pyi stubs)
#     PLUGIN_EXPORTS plugin_exports.list  # the API's patterns a component exports to plugins
#     PLAYER player.js                    # how aula grade's player draws a run of it
#     MAP vacuum vacuum.world --resolution 0.02 ...)  # build/maps/NAME.png of its world, for tests (aula-mapgen's arguments)
#     RUNS "vacuum --algorithm=reference"  # CI's headless runs of it, each "LABEL ARGS..." of `aula run NAME`
#     SANITIZE_ARGS --Vacuum.Referee.Duration=120  # what the sanitizer's runs add (its slower processes)
#     SCREENSHOT Vacuum vacuum.world --Vacuum.Algorithm=reference ...  # docs/images: SECTION WORLD COMPONENT_ARGS...
#
# ABI_VERSION: each exercise's plugins carry the version of its own API they were built for, and
# its component refuses another (plugin_library.cpp), so changing one exercise's API refuses only
# that exercise's old plugins. The test AlgorithmAbi.EachExercisesVersionFollowsItsApiHeaders
# fails when API_HEADERS change (comments, white space and the exercise's name aside: a copy keeps
# the hash): then raise ABI_VERSION and record the hash it prints in ABI_HEADERS_SHA256.
#
# RUNS, SANITIZE_ARGS and SCREENSHOT are written for the scripts that serve every exercise
# (aula_finish_exercises: build/exercises/*.txt), so CI runs a new exercise with no list to edit.
#
# Paths are relative to the declaring folder. The top-level CMakeLists.txt adds every folder of
# components/ and referees/ (the referee folder has the exercise's name too), then calls
# aula_finish_exercises().
set(_AULA_EXERCISE_DIR "${CMAKE_CURRENT_LIST_DIR}")

# In components/ and referees/: adds `common` and then every other folder with a CMakeLists.txt
# (an exercise's component or referee), so a new exercise's folder is found, never listed.
function(aula_add_exercise_folders)
  add_subdirectory(common)
  file(GLOB _dirs LIST_DIRECTORIES true CONFIGURE_DEPENDS RELATIVE ${CMAKE_CURRENT_SOURCE_DIR} ${CMAKE_CURRENT_SOURCE_DIR}/*)
  list(SORT _dirs)
  foreach(_dir ${_dirs})
    if(NOT _dir STREQUAL "common" AND EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/${_dir}/CMakeLists.txt)
      add_subdirectory(${_dir})
    endif()
  endforeach()
endfunction()

function(aula_exercise)
  set(_one NAME DECLARATION COMPONENT REFEREE API STUDENT PYTHON TEMPLATES PLUGIN_EXPORTS PLAYER ABI_VERSION ABI_HEADERS_SHA256)
  cmake_parse_arguments(ARG "" "${_one}" "API_HEADERS;MAP;RUNS;SANITIZE_ARGS;SCREENSHOT" ${ARGN})
  foreach(_required NAME DECLARATION COMPONENT API STUDENT TEMPLATES PLUGIN_EXPORTS ABI_VERSION ABI_HEADERS_SHA256)
    if(NOT ARG_${_required})
      message(FATAL_ERROR "aula_exercise() in ${CMAKE_CURRENT_SOURCE_DIR}: ${_required} is required")
    endif()
  endforeach()
  if(NOT ARG_NAME MATCHES "^[a-z][a-z0-9_]*$")
    message(FATAL_ERROR "aula_exercise(NAME ${ARG_NAME}): a name is lower-case letters, digits and _ (it names "
                        "targets, a C++ namespace and `aula run NAME`)")
  endif()
  get_property(_declared GLOBAL PROPERTY AULA_EXERCISES)
  if(ARG_NAME IN_LIST _declared)
    message(FATAL_ERROR "aula_exercise(NAME ${ARG_NAME}) in ${CMAKE_CURRENT_SOURCE_DIR}: declared twice")
  endif()
  set_property(GLOBAL APPEND PROPERTY AULA_EXERCISES ${ARG_NAME})
  if(NOT ARG_ABI_VERSION MATCHES "^[1-9][0-9]*$")
    message(FATAL_ERROR "aula_exercise(NAME ${ARG_NAME}): ABI_VERSION is a whole number from 1")
  endif()
  foreach(_key COMPONENT REFEREE API STUDENT PYTHON ABI_VERSION ABI_HEADERS_SHA256)
    set_property(GLOBAL PROPERTY AULA_EXERCISE_${ARG_NAME}_${_key} "${ARG_${_key}}")
  endforeach()
  set(_dir ${CMAKE_CURRENT_SOURCE_DIR})
  file(RELATIVE_PATH _rel_dir ${PROJECT_SOURCE_DIR} ${_dir})
  set(_headers "")
  foreach(_entry ${ARG_API_HEADERS})
    string(REGEX MATCH "^[^:]*" _install_dir "${_entry}")
    string(REGEX REPLACE "^[^:]*:" "" _file "${_entry}")
    list(APPEND _headers "${_install_dir}:${_rel_dir}/${_file}")
  endforeach()
  set_property(GLOBAL PROPERTY AULA_EXERCISE_${ARG_NAME}_API_HEADERS "${_headers}")
  set_property(GLOBAL PROPERTY AULA_EXERCISE_${ARG_NAME}_TEMPLATES "${_dir}/${ARG_TEMPLATES}")
  set_property(GLOBAL PROPERTY AULA_EXERCISE_${ARG_NAME}_PLUGIN_EXPORTS "${_dir}/${ARG_PLUGIN_EXPORTS}")
  set_property(GLOBAL PROPERTY AULA_EXERCISE_${ARG_NAME}_MAP "${ARG_MAP}")
  set_property(GLOBAL PROPERTY AULA_EXERCISE_${ARG_NAME}_DIR "${_dir}")  # its tests/ (tests/unit/CMakeLists.txt)
  foreach(_key RUNS SANITIZE_ARGS SCREENSHOT)
    set_property(GLOBAL PROPERTY AULA_EXERCISE_${ARG_NAME}_${_key} "${ARG_${_key}}")
  endforeach()
  if(ARG_PLAYER)
    set_property(GLOBAL APPEND PROPERTY AULA_EXERCISE_PLAYER_SCRIPTS "${_dir}/${ARG_PLAYER}")
  endif()
  # The declaration joins the settings library every program links (its registry is generated by
  # aula_finish_exercises): the launcher, the components and the referees all read the tables.
  target_sources(aula_settings PRIVATE ${_dir}/${ARG_DECLARATION})
endfunction()

# The linker dynamic list of exercise EXERCISE's component: the common API's patterns
# (cmake/aula_plugin_exports.list.in) and the exercise's own (PLUGIN_EXPORTS). OUT: its path.
function(aula_exercise_exports_list exercise out)
  get_property(_fragment GLOBAL PROPERTY AULA_EXERCISE_${exercise}_PLUGIN_EXPORTS)
  file(READ "${_fragment}" AULA_EXERCISE_EXPORTS)
  set(_list ${PROJECT_BINARY_DIR}/plugin_exports/${exercise}.list)
  configure_file(${_AULA_EXERCISE_DIR}/aula_plugin_exports.list.in ${_list} @ONLY)
  set_property(DIRECTORY ${PROJECT_SOURCE_DIR} APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${_fragment}")
  set(${out} ${_list} PARENT_SCOPE)
endfunction()

# After every exercise is declared: the settings' registry (with each exercise's ABI version), the
# sorted names (AULA_EXERCISES), the student API's header list (AULA_API_HEADERS, the common ones
# and every exercise's) and the common headers' hash (AULA_API_HEADERS_SHA256), all three set in
# the caller's scope, each exercise's ABI (generated/aula/exercise_abi.hpp, for the test), `./aula run NAME`'s
# targets (aula_run_<name>: that exercise's programs and plugins, nothing of another's), and the
# student templates `aula new` copies from the build tree.
function(aula_finish_exercises)
  get_property(AULA_EXERCISES GLOBAL PROPERTY AULA_EXERCISES)
  list(SORT AULA_EXERCISES)
  set(_registry_decls "")
  set(_registry_calls "")
  foreach(_exercise ${AULA_EXERCISES})
    string(APPEND _registry_decls "namespace aula::${_exercise} {\nsettings::Exercise declareExercise();\n}\n")
    get_property(_abi GLOBAL PROPERTY AULA_EXERCISE_${_exercise}_ABI_VERSION)
    string(APPEND _registry_calls "  out.push_back(aula::${_exercise}::declareExercise());\n  out.back().abi_version = ${_abi};\n")
  endforeach()
  file(CONFIGURE OUTPUT ${PROJECT_BINARY_DIR}/generated/exercise_registry.cpp CONTENT
"// Generated by aula_finish_exercises() (cmake/AulaExercise.cmake) from each exercise's
// aula_exercise(): the exercises this build declares. Do not edit.
#include <aula/settings/tables.hpp>

@_registry_decls@
std::vector<aula::settings::Exercise> aula::settings::declaredExercises() {
  std::vector<Exercise> out;
@_registry_calls@  return out;
}
")
  target_sources(aula_settings PRIVATE ${PROJECT_BINARY_DIR}/generated/exercise_registry.cpp)

  # The common headers' hash (the version in algorithm_plugin.hpp), then each exercise's own.
  aula_api_headers_sha256(AULA_API_HEADERS_SHA256 ${PROJECT_SOURCE_DIR} ${AULA_API_HEADERS})
  set(_abi_rows "")
  foreach(_exercise ${AULA_EXERCISES})
    get_property(_headers GLOBAL PROPERTY AULA_EXERCISE_${_exercise}_API_HEADERS)
    list(APPEND AULA_API_HEADERS ${_headers})
    aula_api_headers_sha256(_hash ${PROJECT_SOURCE_DIR} EXERCISE ${_exercise} ${_headers})
    get_property(_abi GLOBAL PROPERTY AULA_EXERCISE_${_exercise}_ABI_VERSION)
    get_property(_recorded GLOBAL PROPERTY AULA_EXERCISE_${_exercise}_ABI_HEADERS_SHA256)
    string(APPEND _abi_rows "    {\"${_exercise}\", ${_abi}, \"${_recorded}\", \"${_hash}\", \"${_headers}\"},\n")
  endforeach()
  file(CONFIGURE OUTPUT ${PROJECT_BINARY_DIR}/generated/aula/exercise_abi.hpp CONTENT
"// Generated by aula_finish_exercises() (cmake/AulaExercise.cmake): each exercise's declared ABI
// version, the hash recorded with it and its API headers' hash now. Do not edit.
#pragma once
namespace aula::generated {
struct ExerciseAbi {
  const char* name;
  int version;
  const char* recorded_sha256;
  const char* sha256;
  const char* headers;  // DIR:FILE;... relative to the source tree
};
inline constexpr ExerciseAbi kExerciseAbis[] = {
@_abi_rows@};
}  // namespace aula::generated
")
  # A header's change reconfigures the build, so the hash the test compares is always the current one.
  foreach(_entry ${AULA_API_HEADERS})
    string(REGEX REPLACE "^[^:]*:" "" _file "${_entry}")
    set_property(DIRECTORY ${PROJECT_SOURCE_DIR} APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/${_file})
  endforeach()

  # The lists of the scripts that serve every exercise, one line each (`#` lines say the format):
  # runs.txt (scripts/ci-debian13.sh) and sanitize-runs.txt (scripts/sanitize-check.sh):
  # LABEL EXERCISE ARGS...; screenshots.txt (scripts/update-screenshots.sh):
  # EXERCISE SECTION WORLD COMPONENT REFEREE ARGS...
  set(_runs "# LABEL EXERCISE ARGS... (RUNS of each aula_exercise)\n")
  set(_sanitize_runs "# LABEL EXERCISE ARGS... (RUNS and SANITIZE_ARGS of each aula_exercise)\n")
  set(_screenshots "# EXERCISE SECTION WORLD COMPONENT REFEREE ARGS... (SCREENSHOT of each aula_exercise)\n")
  foreach(_exercise ${AULA_EXERCISES})
    get_property(_exercise_runs GLOBAL PROPERTY AULA_EXERCISE_${_exercise}_RUNS)
    get_property(_sanitize_args GLOBAL PROPERTY AULA_EXERCISE_${_exercise}_SANITIZE_ARGS)
    list(JOIN _sanitize_args " " _sanitize_args)
    foreach(_run ${_exercise_runs})
      string(REGEX REPLACE "^([^ ]+)(.*)$" "\\1 ${_exercise}\\2" _line "${_run}")
      string(APPEND _runs "${_line}\n")
      string(STRIP "${_line} ${_sanitize_args}" _line)
      string(APPEND _sanitize_runs "${_line}\n")
    endforeach()
    get_property(_shot GLOBAL PROPERTY AULA_EXERCISE_${_exercise}_SCREENSHOT)
    if(_shot)
      get_property(_component GLOBAL PROPERTY AULA_EXERCISE_${_exercise}_COMPONENT)
      get_property(_referee GLOBAL PROPERTY AULA_EXERCISE_${_exercise}_REFEREE)
      list(GET _shot 0 _section)
      list(GET _shot 1 _world)
      list(SUBLIST _shot 2 -1 _shot_args)
      list(JOIN _shot_args " " _shot_args)
      string(STRIP "${_exercise} ${_section} ${_world} ${_component} ${_referee} ${_shot_args}" _line)
      string(APPEND _screenshots "${_line}\n")
    endif()
  endforeach()
  file(CONFIGURE OUTPUT ${PROJECT_BINARY_DIR}/exercises/runs.txt CONTENT "${_runs}")
  file(CONFIGURE OUTPUT ${PROJECT_BINARY_DIR}/exercises/sanitize-runs.txt CONTENT "${_sanitize_runs}")
  file(CONFIGURE OUTPUT ${PROJECT_BINARY_DIR}/exercises/screenshots.txt CONTENT "${_screenshots}")

  file(MAKE_DIRECTORY ${PROJECT_BINARY_DIR}/share/aula/templates)
  add_custom_target(aula_all_exercises)  # every exercise's aula_run_<name> (scripts/sanitize-check.sh)
  foreach(_exercise ${AULA_EXERCISES})
    set(_programs)
    foreach(_key COMPONENT REFEREE STUDENT PYTHON)
      get_property(_target GLOBAL PROPERTY AULA_EXERCISE_${_exercise}_${_key})
      list(APPEND _programs ${_target})
    endforeach()
    add_custom_target(aula_run_${_exercise})
    add_dependencies(aula_run_${_exercise} ${AULA_COMMON_PROGRAMS} ${_programs})
    add_dependencies(aula_all_exercises aula_run_${_exercise})
    # `aula new` copies the templates from share/aula/templates/<exercise>, as installed.
    get_property(_templates GLOBAL PROPERTY AULA_EXERCISE_${_exercise}_TEMPLATES)
    file(CREATE_LINK ${_templates} ${PROJECT_BINARY_DIR}/share/aula/templates/${_exercise} SYMBOLIC)
  endforeach()
  set(AULA_EXERCISES ${AULA_EXERCISES} PARENT_SCOPE)
  set(AULA_API_HEADERS ${AULA_API_HEADERS} PARENT_SCOPE)
  set(AULA_API_HEADERS_SHA256 ${AULA_API_HEADERS_SHA256} PARENT_SCOPE)
endfunction()

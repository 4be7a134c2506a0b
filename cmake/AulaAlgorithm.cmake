# aula_add_algorithm(NAME name EXERCISE vacuum|teletaxi|autopark SOURCES file.cpp ...)
#
# Builds a student's algorithm as a plugin (lib<name>.so) that an Aula component loads with
# --algorithm=PATH.so. The student's sources define makeStudentAlgorithm(...) exactly as in the
# exercise's template; this function adds the C entry points the component looks for (the
# exercise, the ABI version and aula_<exercise>_algorithm_v1), so students never write them.
# The plugin calls the exercise's API (Grid, SlotDetector...) in the component that loads it;
# everything of its own stays hidden, so two plugins (or a plugin and the component) never
# mix each other's functions.
#
# Used in Aula's own tree (the in-tree templates) and, installed, through find_package(Aula).
set(_AULA_ALGORITHM_DIR "${CMAKE_CURRENT_LIST_DIR}")

function(aula_add_algorithm)
  cmake_parse_arguments(ARG "" "NAME;EXERCISE;OUTPUT_DIRECTORY" "SOURCES" ${ARGN})
  if(NOT ARG_NAME OR NOT ARG_EXERCISE OR NOT ARG_SOURCES)
    message(FATAL_ERROR "aula_add_algorithm(NAME name EXERCISE vacuum|teletaxi|autopark SOURCES ...): "
                        "NAME, EXERCISE and SOURCES are required")
  endif()
  if(ARG_EXERCISE STREQUAL "vacuum")
    set(AULA_HEADER "aula/vacuum/vacuum_algorithm.hpp")
    set(AULA_CLASS "aula::vacuum::VacuumAlgorithm")
    set(AULA_MAKE "aula::vacuum::makeStudentAlgorithm(seed)")
  elseif(ARG_EXERCISE STREQUAL "teletaxi")
    set(AULA_HEADER "aula/teletaxi/taxi_algorithm.hpp")
    set(AULA_CLASS "aula::teletaxi::TaxiAlgorithm")
    set(AULA_MAKE "((void)seed, aula::teletaxi::makeStudentAlgorithm())")
  elseif(ARG_EXERCISE STREQUAL "autopark")
    set(AULA_HEADER "aula/autopark/autopark_algorithm.hpp")
    set(AULA_CLASS "aula::autopark::AutoparkAlgorithm")
    set(AULA_MAKE "aula::autopark::makeStudentAlgorithm(seed)")
  else()
    message(FATAL_ERROR "aula_add_algorithm(${ARG_NAME}): EXERCISE must be vacuum, teletaxi or autopark, "
                        "not '${ARG_EXERCISE}'")
  endif()
  set(AULA_EXERCISE "${ARG_EXERCISE}")
  set(_entry "${CMAKE_CURRENT_BINARY_DIR}/${ARG_NAME}_aula_entry.cpp")
  configure_file("${_AULA_ALGORITHM_DIR}/aula_algorithm_entry.cpp.in" "${_entry}" @ONLY)

  add_library(${ARG_NAME} MODULE ${ARG_SOURCES} "${_entry}")
  if(TARGET Aula::${ARG_EXERCISE}_api)
    target_link_libraries(${ARG_NAME} PRIVATE Aula::${ARG_EXERCISE}_api)
  else()
    target_link_libraries(${ARG_NAME} PRIVATE aula_${ARG_EXERCISE}_api)
  endif()
  # lib<name>.so, like any shared library; hidden by default (see above).
  set_target_properties(${ARG_NAME} PROPERTIES
    PREFIX "lib" SUFFIX ".so"
    CXX_STANDARD 17 CXX_STANDARD_REQUIRED ON
    CXX_VISIBILITY_PRESET hidden VISIBILITY_INLINES_HIDDEN ON)
  # Line numbers for a crash's stack (addr2line on the plugin), whatever the build type.
  target_compile_options(${ARG_NAME} PRIVATE -g)
  if(ARG_OUTPUT_DIRECTORY)
    set_target_properties(${ARG_NAME} PROPERTIES LIBRARY_OUTPUT_DIRECTORY "${ARG_OUTPUT_DIRECTORY}")
  endif()
endfunction()

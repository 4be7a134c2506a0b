# aula_add_algorithm(NAME name EXERCISE exercise SOURCES file.cpp ...)
#
# Builds a student's algorithm as a plugin (lib<name>.so) that an Aula component loads with
# --algorithm=PATH.so. The student's sources define makeStudentAlgorithm(...) exactly as in the
# exercise's template; this function adds the C entry points the component looks for (the
# exercise, the ABI versions (the common API's and the exercise's own) and
# aula_<exercise>_algorithm_v1), so students never write them.
# The plugin calls the exercise's API (Grid, SlotDetector...) in the component that loads it;
# everything of its own stays hidden, so two plugins (or a plugin and the component) never
# mix each other's functions.
#
# Optional, for Aula's own built-in algorithms (the references, built as plugins so that a
# component never contains them: components/CMakeLists.txt): HEADER and MAKE instead of the API's
# (the header declaring the maker, the expression making it from `seed`), LIBS linked privately.
#
# Used in Aula's own tree (the in-tree templates) and, installed, through find_package(Aula).
set(_AULA_ALGORITHM_DIR "${CMAKE_CURRENT_LIST_DIR}")

function(aula_add_algorithm)
  cmake_parse_arguments(ARG "" "NAME;EXERCISE;OUTPUT_DIRECTORY;HEADER;MAKE" "SOURCES;LIBS" ${ARGN})
  if(NOT ARG_NAME OR NOT ARG_EXERCISE OR (NOT ARG_SOURCES AND NOT ARG_LIBS))
    message(FATAL_ERROR "aula_add_algorithm(NAME name EXERCISE exercise SOURCES ...): "
                        "NAME, EXERCISE and SOURCES are required")
  endif()
  # The exercise's API target says what a plugin implements (aula_declare_algorithm_api).
  if(TARGET Aula::${ARG_EXERCISE}_api)
    set(_api Aula::${ARG_EXERCISE}_api)
  elseif(TARGET aula_${ARG_EXERCISE}_api)
    set(_api aula_${ARG_EXERCISE}_api)
  else()
    message(FATAL_ERROR "aula_add_algorithm(${ARG_NAME}): no exercise '${ARG_EXERCISE}' (no target "
                        "Aula::${ARG_EXERCISE}_api); `aula --help` lists the exercises")
  endif()
  get_target_property(AULA_HEADER ${_api} AULA_ALGORITHM_HEADER)
  get_target_property(AULA_CLASS ${_api} AULA_ALGORITHM_CLASS)
  get_target_property(AULA_MAKE ${_api} AULA_ALGORITHM_MAKE)
  get_target_property(AULA_EXERCISE_ABI_VERSION ${_api} AULA_ALGORITHM_ABI_VERSION)
  if(ARG_HEADER)
    set(AULA_HEADER "${ARG_HEADER}")
  endif()
  if(ARG_MAKE)
    set(AULA_MAKE "${ARG_MAKE}")
  endif()
  set(AULA_EXERCISE "${ARG_EXERCISE}")
  set(_entry "${CMAKE_CURRENT_BINARY_DIR}/${ARG_NAME}_aula_entry.cpp")
  configure_file("${_AULA_ALGORITHM_DIR}/aula_algorithm_entry.cpp.in" "${_entry}" @ONLY)

  add_library(${ARG_NAME} MODULE ${ARG_SOURCES} "${_entry}")
  target_link_libraries(${ARG_NAME} PRIVATE ${_api} ${ARG_LIBS})
  # A plugin that calls nothing of libc's directly still names it (Debian's policy for every
  # shared object, lintian's library-not-linked-against-libc).
  target_link_options(${ARG_NAME} PRIVATE "LINKER:--push-state,--no-as-needed,-lc,--pop-state")
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

# aula_declare_algorithm_api(TARGET aula_<exercise>_api HEADER h CLASS c MAKE expr)
#
# An exercise's API target (an INTERFACE library named aula_<exercise>_api) says what a plugin of
# that exercise implements: the header declaring the algorithm's class, the class, and the C++
# expression that makes the student's algorithm from `uint64_t seed` (a std::unique_ptr), and the
# exercise's ABI version (its aula_exercise() ABI_VERSION, declared before). The properties are
# exported with the target, so an installed Aula's plugins read them too.
function(aula_declare_algorithm_api)
  cmake_parse_arguments(ARG "" "TARGET;HEADER;CLASS;MAKE" "" ${ARGN})
  string(REGEX REPLACE "^aula_(.*)_api$" "\\1" _exercise "${ARG_TARGET}")
  get_property(_abi GLOBAL PROPERTY AULA_EXERCISE_${_exercise}_ABI_VERSION)
  if(NOT _abi)
    message(FATAL_ERROR "aula_declare_algorithm_api(TARGET ${ARG_TARGET}): declare aula_exercise(NAME ${_exercise} "
                        "... ABI_VERSION n) first")
  endif()
  set_target_properties(${ARG_TARGET} PROPERTIES
    AULA_ALGORITHM_HEADER "${ARG_HEADER}" AULA_ALGORITHM_CLASS "${ARG_CLASS}" AULA_ALGORITHM_MAKE "${ARG_MAKE}"
    AULA_ALGORITHM_ABI_VERSION "${_abi}"
    EXPORT_PROPERTIES "AULA_ALGORITHM_HEADER;AULA_ALGORITHM_CLASS;AULA_ALGORITHM_MAKE;AULA_ALGORITHM_ABI_VERSION")
endfunction()

# A component exports to the plugins it loads only the student API (the common patterns of
# aula_plugin_exports.list.in and its exercise's own, aula_exercise_exports_list), not its own
# symbols (-rdynamic would give a plugin the references and everything else).
# API_LIBS: the static libraries holding the API's code, linked whole: the component itself may
# not call every API function (only the references, plugins of their own, called some), and a
# student's plugin must find each one (build.ComponentsExportOnlyTheStudentApi checks it).
function(aula_export_plugin_api target)
  cmake_parse_arguments(ARG "" "EXERCISE" "API_LIBS" ${ARGN})
  aula_exercise_exports_list(${ARG_EXERCISE} _list)
  target_link_options(${target} PRIVATE "LINKER:--dynamic-list=${_list}")
  foreach(_lib ${ARG_API_LIBS})
    target_link_options(${target} PRIVATE "LINKER:--whole-archive,$<TARGET_FILE:${_lib}>,--no-whole-archive")
    target_link_libraries(${target} PRIVATE ${_lib})
  endforeach()
  set_property(TARGET ${target} APPEND PROPERTY LINK_DEPENDS ${_list})
endfunction()

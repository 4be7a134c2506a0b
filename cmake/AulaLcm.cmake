# LCM 1.3.1 on Debian ships no CMake config: find it by hand and generate C++ types with lcm-gen
# at build time (generated code lives only in the build tree).
find_path(LCM_INCLUDE_DIR lcm/lcm-cpp.hpp REQUIRED)
find_library(LCM_LIBRARY lcm REQUIRED)
find_program(LCM_GEN lcm-gen REQUIRED)
if(NOT TARGET lcm::lcm)
  add_library(lcm::lcm UNKNOWN IMPORTED)
  set_target_properties(lcm::lcm PROPERTIES
    IMPORTED_LOCATION "${LCM_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${LCM_INCLUDE_DIR}")
endif()

# aula_lcm_types(TARGET PACKAGE file1.lcm file2.lcm ...)
function(aula_lcm_types target package)
  set(out_dir "${CMAKE_CURRENT_BINARY_DIR}/lcmgen")
  set(headers "")
  foreach(lcm_file ${ARGN})
    get_filename_component(abs "${lcm_file}" ABSOLUTE)
    get_filename_component(stem "${lcm_file}" NAME_WE)
    set(header "${out_dir}/${package}/${stem}.hpp")
    add_custom_command(
      OUTPUT "${header}"
      COMMAND ${CMAKE_COMMAND} -E make_directory "${out_dir}"
      COMMAND ${LCM_GEN} --cpp --cpp-hpath "${out_dir}" "${abs}"
      DEPENDS "${abs}"
      COMMENT "lcm-gen ${package}/${stem}"
      VERBATIM)
    list(APPEND headers "${header}")
  endforeach()
  add_custom_target(${target}_gen DEPENDS ${headers})
  add_library(${target} INTERFACE)
  add_dependencies(${target} ${target}_gen)
  target_include_directories(${target} INTERFACE "${out_dir}")
  target_link_libraries(${target} INTERFACE lcm::lcm)
endfunction()

# aula_api_headers_sha256(OUT ROOT [EXERCISE NAME] DIR:FILE...): the SHA-256 of the plugin API's
# headers (FILE relative to ROOT), their comments (// and /* */) and the run of white space left out (neither
# changes a layout; the entries sorted), the ABI header itself (algorithm_plugin.hpp, which records
# the hash) left out. With EXERCISE, an exercise's own headers: its name (name, Name, NAME) is
# left out of the paths and the text, so an exercise copied under another name (the short way of
# docs/adding-an-exercise.md) has the same hash and keeps the recorded one.
# Also a script, for the test that shows the hash follows the API and only the API:
#   cmake -DROOT=DIR -DHEADERS="dir:file;..." [-DEXERCISE=name] -P aula_api_hash.cmake   prints the hash
function(aula_api_headers_sha256 out root)
  set(_entries ${ARGN})
  set(_exercise "")
  if(_entries MATCHES "^EXERCISE;")
    list(GET _entries 1 _exercise)
    list(REMOVE_AT _entries 0 1)
  endif()
  if(_exercise)
    string(TOUPPER "${_exercise}" _upper)
    string(SUBSTRING "${_upper}" 0 1 _first)
    string(SUBSTRING "${_exercise}" 1 -1 _rest)
    set(_names "${_exercise}" "${_first}${_rest}" "${_upper}")
  endif()
  set(_all "")
  # In the entries' order, sorted: the exercises declare theirs in any order.
  list(SORT _entries)
  foreach(_entry ${_entries})
    string(REGEX REPLACE "^[^:]*:" "" _file "${_entry}")
    if(_file MATCHES "algorithm_plugin\\.hpp$")
      continue()
    endif()
    file(READ "${root}/${_file}" _text)
    string(REGEX REPLACE "/\\*([^*]|\\*+[^*/])*\\*+/" "" _text "${_text}")  # /* */ and /** */
    string(REGEX REPLACE "//[^\n]*" "" _text "${_text}")
    string(REGEX REPLACE "[ \t\r\n]+" " " _text "${_text}")
    string(APPEND _all "${_entry}\n${_text}\n")
  endforeach()
  foreach(_name ${_names})
    string(REPLACE "${_name}" "<exercise>" _all "${_all}")
  endforeach()
  string(SHA256 _hash "${_all}")
  set(${out} ${_hash} PARENT_SCOPE)
endfunction()

if(CMAKE_SCRIPT_MODE_FILE AND DEFINED ROOT)
  if(EXERCISE)
    aula_api_headers_sha256(_hash "${ROOT}" EXERCISE ${EXERCISE} ${HEADERS})
  else()
    aula_api_headers_sha256(_hash "${ROOT}" ${HEADERS})
  endif()
  message("${_hash}")
endif()

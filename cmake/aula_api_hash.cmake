# aula_api_headers_sha256(OUT ROOT DIR:FILE...): the SHA-256 of the plugin API's headers (FILE
# relative to ROOT), their comments and the run of white space left out (neither changes a
# layout; the entries sorted), the ABI header itself (algorithm_plugin.hpp, which records the hash) left out.
# Also a script, for the test that shows the hash follows the API and only the API:
#   cmake -DROOT=DIR -DHEADERS="dir:file;..." -P aula_api_hash.cmake   prints the hash
function(aula_api_headers_sha256 out root)
  set(_all "")
  # In the entries' order, sorted: the exercises declare theirs in any order.
  set(_entries ${ARGN})
  list(SORT _entries)
  foreach(_entry ${_entries})
    string(REGEX REPLACE "^[^:]*:" "" _file "${_entry}")
    if(_file MATCHES "algorithm_plugin\\.hpp$")
      continue()
    endif()
    file(READ "${root}/${_file}" _text)
    string(REGEX REPLACE "//[^\n]*" "" _text "${_text}")
    string(REGEX REPLACE "[ \t\r\n]+" " " _text "${_text}")
    string(APPEND _all "${_entry}\n${_text}\n")
  endforeach()
  string(SHA256 _hash "${_all}")
  set(${out} ${_hash} PARENT_SCOPE)
endfunction()

if(CMAKE_SCRIPT_MODE_FILE AND DEFINED ROOT)
  aula_api_headers_sha256(_hash "${ROOT}" ${HEADERS})
  message("${_hash}")
endif()

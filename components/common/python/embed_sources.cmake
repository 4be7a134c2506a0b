# cmake -DOUTPUT=file.cpp -DFUNCTION=name -DSOURCES="a.py;b.py" -P embed_sources.cmake
# Writes OUTPUT: `const std::vector<aula::python::Source>& aula::python::FUNCTION()`, the files'
# text as raw strings, each under its module name (the file's name without .py).
set(_out "// Generated from ${SOURCES} by embed_sources.cmake: do not edit.\n")
string(APPEND _out "#include <aula/python/python_host.hpp>\n\nnamespace aula::python {\n\n")
string(APPEND _out "const std::vector<Source>& ${FUNCTION}() {\n  static const std::vector<Source> sources = {\n")
foreach(_file IN LISTS SOURCES)
  file(READ ${_file} _text)
  if(_text MATCHES "\\)AULA_PY\"")
    message(FATAL_ERROR "${_file} contains the raw string's end marker )AULA_PY\"")
  endif()
  get_filename_component(_name ${_file} NAME_WE)
  string(APPEND _out "      {\"${_name}\", R\"AULA_PY(${_text})AULA_PY\"},\n")
endforeach()
string(APPEND _out "  };\n  return sources;\n}\n\n}  // namespace aula::python\n")
file(WRITE ${OUTPUT}.new "${_out}")
file(COPY_FILE ${OUTPUT}.new ${OUTPUT} ONLY_IF_DIFFERENT)
file(REMOVE ${OUTPUT}.new)

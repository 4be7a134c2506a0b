#pragma once
// A Python submission read before it runs: a file that cannot run gets the 0 a C++ compile error
// gets, with its reason, instead of a run whose robot stood still (a SyntaxError's run scored
// the footprint's coverage, 0.02). Only parsed (Python's ast), never executed.

#include <string>

namespace aula::grade {

// "" when `py_file` parses and is one of the Python host's two shapes (components/common/python/
// host.py): it defines class MyAlgorithm with an execute method (or a base to inherit it from),
// or it is a program with a loop (`while`, `for`) or a time.sleep. Else the reason, in the
// student's lines: "did not compile: MyAlgorithm.py:7: SyntaxError: invalid syntax", "not an
// algorithm: ...". `log`: the checker's output.
std::string pythonNotRunnable(const std::string& py_file, const std::string& log);

}  // namespace aula::grade

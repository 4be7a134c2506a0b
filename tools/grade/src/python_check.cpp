#include "aula/grade/python_check.hpp"

#include <aula/process/child_process.hpp>

#include <chrono>
#include <fstream>
#include <iterator>
#include <stdexcept>

namespace aula::grade {

namespace {

// Parses argv[1] (never runs it) and prints one line: "ok", or the reason. The file's path is an
// argument, never part of the program's text.
constexpr const char* kChecker = R"PY(
import ast, os, sys
path = sys.argv[1]
name = os.path.basename(path)
try:
    with open(path, "rb") as f:
        tree = ast.parse(f.read(), name)
except SyntaxError as e:
    print(f"did not compile: {name}:{e.lineno}: {type(e).__name__}: {e.msg}")
    sys.exit(0)
except (ValueError, RecursionError, MemoryError) as e:
    print(f"did not compile: {name}: {type(e).__name__}: {e}")
    sys.exit(0)
classes = [n for n in tree.body if isinstance(n, ast.ClassDef) and n.name == "MyAlgorithm"]
# MyAlgorithm from a file beside it (`from cleaner import Cleaner as MyAlgorithm`, a star import)
# or by another name (`MyAlgorithm = Cleaner`): a hand-in in several files, checked when it runs.
bound = any(isinstance(n, ast.ImportFrom) and any((a.asname or a.name) in ("MyAlgorithm", "*") for a in n.names)
            or isinstance(n, ast.Assign) and any(isinstance(t, ast.Name) and t.id == "MyAlgorithm" for t in n.targets)
            for n in tree.body)
if bound and not classes:
    print("ok")
elif classes:
    methods = {n.name for n in classes[-1].body if isinstance(n, (ast.FunctionDef, ast.AsyncFunctionDef))}
    # A class with a base may inherit its execute (teletaxi_slow's does).
    print("ok" if "execute" in methods or classes[-1].bases else
          f"not an algorithm: {name}'s class MyAlgorithm has no execute(self, api) method")
elif any(isinstance(n, (ast.While, ast.For)) or (isinstance(n, ast.Call) and
         getattr(n.func, "attr", getattr(n.func, "id", "")) == "sleep") for n in ast.walk(tree)):
    print("ok")
else:
    print(f"not an algorithm: {name} defines no class MyAlgorithm (with __init__(self, seed) and "
          "execute(self, api)) and has no loop (a program's while True:) nor a time.sleep: it would end before its robot moved")
)PY";

}  // namespace

std::string pythonNotRunnable(const std::string& py_file, const std::string& log) {
  int code = -1;
  try {
    // Debian's python3, the embedded interpreter's version (components/common/CMakeLists.txt): a
    // PATH's other Python would parse another grammar.
    process::ChildProcess check({"/usr/bin/python3", "-I", "-S", "-c", kChecker, py_file}, log, log);
    const auto done = check.wait(std::chrono::seconds(60));
    if (!done) {
      check.stop(std::chrono::milliseconds(200));
      return "";  // a machine too slow to parse it: the run says what is wrong, if anything
    }
    code = *done;
  } catch (const std::runtime_error&) {
    return "";  // no python3 to check with: the run itself says it
  }
  std::ifstream in(log);
  std::string line;
  std::getline(in, line);
  if (code != 0 || line.empty()) return "";  // no python3 to check with: the run itself says it
  return line == "ok" ? "" : line.substr(0, 400);
}

}  // namespace aula::grade

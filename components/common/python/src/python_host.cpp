#include "aula/python/python_host.hpp"

#include <aula/component/memory_limit.hpp>

#include <pybind11/embed.h>

#include <dlfcn.h>

#include <stdexcept>

namespace aula::python {
namespace {

// What runs in Python: the student's file loaded afresh, and a fault said in the student's lines.
constexpr const char* kHostCode = R"PY(
import os, sys, traceback, types

class ExecuteBudgetExceeded(BaseException):
    """Raised inside a call that overran Component.ExecuteBudget. Not an Exception, so that the
    student's own `except Exception:` does not swallow it."""

budget_text = ""

class NotAnAlgorithm(Exception):
    pass

def _mine(filename, folder):
    return bool(filename) and os.path.dirname(os.path.abspath(filename)) == folder

def load(path, seed):
    folder = os.path.dirname(path)
    # The student's own modules are read afresh too (hot reload).
    for name, module in list(sys.modules.items()):
        if _mine(getattr(module, "__file__", None), folder):
            del sys.modules[name]
    if folder in sys.path:
        sys.path.remove(folder)
    sys.path.insert(0, folder)
    with open(path, "rb") as f:
        source = f.read()
    code = compile(source, path, "exec", dont_inherit=True)
    import random, numpy
    random.seed(seed)
    numpy.random.seed(seed % 2**32)
    # default_rng() without a seed: the next generator of the run's seed sequence, not the OS's entropy.
    unseeded = getattr(numpy.random, "_aula_unseeded_default_rng", numpy.random.default_rng)
    numpy.random._aula_unseeded_default_rng = unseeded
    sequence = numpy.random.SeedSequence(seed)
    numpy.random.default_rng = lambda given=None: unseeded(sequence.spawn(1)[0] if given is None else given)
    module = types.ModuleType("MyAlgorithm")
    module.__file__ = path
    sys.modules["MyAlgorithm"] = module
    exec(code, module.__dict__)
    cls = module.__dict__.get("MyAlgorithm")
    if not isinstance(cls, type):
        raise NotAnAlgorithm("no class MyAlgorithm: define class MyAlgorithm with __init__(self, seed) "
                             "and execute(self, api)")
    return cls

def describe(exc, tb, path):
    folder = os.path.dirname(path)
    if isinstance(exc, SyntaxError) and _mine(exc.filename, folder):
        text = f"{os.path.basename(exc.filename)}:{exc.lineno}: {type(exc).__name__}: {exc.msg}"
        line = (exc.text or "").strip()
        return text + (f" (`{line}`)" if line else "")
    if isinstance(exc, ExecuteBudgetExceeded):
        what = budget_text + ": interrupted here"
    elif isinstance(exc, ModuleNotFoundError):
        what = (f"ModuleNotFoundError: no module named '{exc.name}' (Aula's Python has Debian's standard "
                "library, numpy and cv2)")
    else:
        message = str(exc)
        what = type(exc).__name__ + (": " + message if message else "")
    frames = [f for f in traceback.extract_tb(tb if tb is not None else exc.__traceback__) if _mine(f.filename, folder)]
    if not frames:
        return f"{os.path.basename(path)}: {what}"
    last = frames[-1]
    trail = "; ".join(f"{os.path.basename(f.filename)}:{f.lineno} in {f.name}: `{(f.line or '').strip()}`"
                      for f in frames[-3:])
    return f"{os.path.basename(last.filename)}:{last.lineno}: {what} (traceback, most recent call last: {trail})"
)PY";

// The process's one interpreter, never shut down (numpy cannot start twice), and never freed:
// Python objects must not be released after the interpreter's own exit handlers.
struct Interpreter {
  std::string file;            // the student's .py
  py::dict helpers;            // kHostCode's globals
  py::object budget_exceeded;  // its ExecuteBudgetExceeded
  unsigned long worker = 0;    // the thread inside a call (under the GIL), 0 when none
};

Interpreter*& interpreterSlot() {
  static Interpreter* slot = nullptr;
  return slot;
}

Interpreter& interpreter() {
  Interpreter* it = interpreterSlot();
  if (it == nullptr) throw std::logic_error("the Python interpreter is not started");
  return *it;
}

void startInterpreter() {
  // Debian's extension modules (numpy's) are not linked against libpython: they need its symbols
  // global, and this module was opened RTLD_LOCAL (engineering.md, "Embedding Python").
  if (dlopen(AULA_LIBPYTHON_SONAME, RTLD_NOW | RTLD_GLOBAL | RTLD_NOLOAD) == nullptr) {
    throw std::runtime_error(std::string("cannot make ") + AULA_LIBPYTHON_SONAME + " global: " + dlerror());
  }
  // Debian's python3, whatever the student's environment has: no PYTHONPATH, no user
  // site-packages, no python from PATH.
  // UTF-8 whatever the locale (a sandbox's is C): a folder named "maría" is a path like any other.
  PyPreConfig preconfig;
  PyPreConfig_InitIsolatedConfig(&preconfig);
  preconfig.utf8_mode = 1;
  const PyStatus pre = Py_PreInitialize(&preconfig);
  if (PyStatus_Exception(pre)) throw std::runtime_error(std::string("cannot start Python: ") + (pre.err_msg ? pre.err_msg : "?"));
  PyConfig config;
  PyConfig_InitIsolatedConfig(&config);
  config.install_signal_handlers = 0;  // the component's signals stay the component's
  config.write_bytecode = 0;           // a student's folder may be read-only (the sandbox)
  config.buffered_stdio = 0;           // a print() shows at once, in the terminal's order
  PyConfig_SetBytesString(&config, &config.program_name, AULA_PYTHON_EXECUTABLE);
  PyConfig_SetBytesString(&config, &config.home, AULA_PYTHON_PREFIX);
  py::initialize_interpreter(&config, 0, nullptr, false);
  auto* it = new Interpreter;
  {
    // Only Debian's stdlib and dist-packages: nothing from /usr/local (pip) can shadow numpy.
    py::module_ sys = py::module_::import("sys");
    py::list kept;
    for (py::handle entry : sys.attr("path")) {
      const std::string dir = entry.cast<std::string>();
      if (dir.rfind(AULA_PYTHON_PREFIX "/lib/python3", 0) == 0) kept.append(entry);
    }
    sys.attr("path") = kept;
    py::exec(kHostCode, it->helpers);
    it->budget_exceeded = it->helpers["ExecuteBudgetExceeded"];
  }
  interpreterSlot() = it;
  (void)PyEval_SaveThread();  // every call takes the GIL again, from whichever thread it runs on
}

}  // namespace

std::string setFile(const std::string& path) {
  try {
    if (interpreterSlot() == nullptr) startInterpreter();
    py::gil_scoped_acquire gil;
    interpreter().file = path;
  } catch (const std::exception& e) {
    return std::string("cannot start Python: ") + e.what();
  }
  return "";
}

void interrupt(const std::string& why) {
  py::gil_scoped_acquire gil;  // the student's loop yields it every few ms
  Interpreter& it = interpreter();
  if (it.worker == 0) return;  // it returned meanwhile
  it.helpers["budget_text"] = why;
  PyThreadState_SetAsyncExc(it.worker, it.budget_exceeded.ptr());
}

PythonAlgorithm::Call::Call() { interpreter().worker = PyThread_get_thread_ident(); }

PythonAlgorithm::Call::~Call() {
  Interpreter& it = interpreter();
  PyThreadState_SetAsyncExc(it.worker, nullptr);  // an interrupt that came after the call returned
  it.worker = 0;
}

PythonAlgorithm::PythonAlgorithm(uint64_t seed, const char* api_module) {
  py::gil_scoped_acquire gil;
  Call running;
  try {
    py::module_::import(api_module);  // the API's types
    const py::object cls = interpreter().helpers["load"](interpreter().file, seed);
    self_ = cls(seed);
  } catch (py::error_already_set& e) {
    throw component::AlgorithmFault(describe(e));
  }
}

PythonAlgorithm::~PythonAlgorithm() {
  py::gil_scoped_acquire gil;
  self_ = py::object();
}

std::string PythonAlgorithm::describe(py::error_already_set& e) {
  std::string text;
  try {
    text = interpreter().helpers["describe"](e.value(), e.trace(), interpreter().file).cast<std::string>();
  } catch (py::error_already_set& inner) {
    text = std::string(e.what()) + " (and describing it failed: " + inner.what() + ")";
  }
  // A MemoryError in a sandboxed run is the sandbox's limit, said as for C++ (where it was raised after it).
  const std::string limit = e.matches(PyExc_MemoryError) ? component::memoryLimitReason() : "";
  return limit.empty() ? text : limit + " (" + text + ")";
}

}  // namespace aula::python

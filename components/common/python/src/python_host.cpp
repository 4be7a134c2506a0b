#include "aula/python/python_host.hpp"

#include <aula/component/memory_limit.hpp>

#include <pybind11/embed.h>

#include <dlfcn.h>

#include <mutex>
#include <stdexcept>

namespace aula::python {
namespace {

// What runs in Python is host.py (the student's file on a greenlet, the sim clock, faults in
// the student's lines) and the modules it offers programs (aula_ra.py: RoboticsAcademy's types for
// the exercises' HAL and GUI; aula_academy.py: JdeRobot-Academy's devices; Frequency, WebGUI...),
// compiled in as text (embed_sources.cmake).
const Source& hostSource(const char* name) {
  for (const Source& source : hostSources()) {
    if (std::string(source.name) == name) return source;
  }
  throw std::logic_error(std::string("the Python host has no ") + name + ".py");
}

// What the student's code printed, for the window's console: the last kConsoleBytes (from a
// line's start) kept between two takes; headless nobody takes, and the text is trimmed only when
// twice that has piled up, so that a print costs the same however long the run.
constexpr size_t kConsoleBytes = 64 * 1024;
std::mutex console_mutex;
std::string console_text;
bool console_dropped = false;

void trimConsole() {
  if (console_text.size() <= kConsoleBytes) return;
  size_t cut = console_text.size() - kConsoleBytes;
  const size_t line = console_text.find('\n', cut);
  cut = line == std::string::npos ? cut : line + 1;
  console_text.erase(0, cut);
  console_dropped = true;
}

void keepPrinted(const std::string& text) {
  std::lock_guard<std::mutex> lock(console_mutex);
  console_text += text;
  if (console_text.size() > 2 * kConsoleBytes) trimConsole();
}

// The process's one interpreter, never shut down (numpy cannot start twice), and never freed:
// Python objects must not be released after the interpreter's own exit handlers.
struct Interpreter {
  std::string file;            // the student's .py
  py::module_ helpers;         // host.py, as the module _aula_host
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
    py::module_ host = py::module_::import("types").attr("ModuleType")("_aula_host");
    sys.attr("modules")["_aula_host"] = host;
    const Source& code = hostSource("host");
    const py::module_ builtins = py::module_::import("builtins");
    builtins.attr("exec")(builtins.attr("compile")(code.text, "<aula:host.py>", "exec"), host.attr("__dict__"));
    it->helpers = host;
    it->budget_exceeded = host.attr("ExecuteBudgetExceeded");
    host.attr("install_clock")();
    host.attr("install_console")(py::cpp_function([](const std::string& text) { keepPrinted(text); }));
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
    interpreter().helpers.attr("preload")(path);
  } catch (const std::exception& e) {
    return std::string("cannot start Python: ") + e.what();
  }
  return "";
}

void interrupt(const std::string& why) {
  py::gil_scoped_acquire gil;  // the student's loop yields it every few ms
  Interpreter& it = interpreter();
  if (it.worker == 0) return;  // it returned meanwhile
  it.helpers.attr("budget_text") = why;
  PyThreadState_SetAsyncExc(it.worker, it.budget_exceeded.ptr());
}

PythonAlgorithm::Call::Call() { interpreter().worker = PyThread_get_thread_ident(); }

PythonAlgorithm::Call::~Call() {
  Interpreter& it = interpreter();
  PyThreadState_SetAsyncExc(it.worker, nullptr);  // an interrupt that came after the call returned
  it.worker = 0;
}

void PythonAlgorithm::keepThreadState(py::gil_scoped_acquire& gil) {
  thread_local bool kept = false;
  if (!kept) gil.inc_ref();  // one reference never released: the state lives as long as the thread
  kept = true;
}

PythonAlgorithm::PythonAlgorithm(uint64_t seed, const char* api_module) {
  py::gil_scoped_acquire gil;
  keepThreadState(gil);
  Call running;
  try {
    py::module_::import(api_module);  // the API's types
    py::list modules;  // what the host offers every exercise (aula_ra...), then the exercise's HAL, GUI...
    for (const Source& source : hostSources()) {
      if (std::string(source.name) != "host") modules.append(py::make_tuple(source.name, source.text));
    }
    for (const Source& source : exerciseSources()) modules.append(py::make_tuple(source.name, source.text));
    runner_ = interpreter().helpers.attr("Runner")(interpreter().file, seed, modules);
  } catch (py::error_already_set& e) {
    throw component::AlgorithmFault(describe(e));
  }
}

PythonAlgorithm::~PythonAlgorithm() {
  py::gil_scoped_acquire gil;
  try {
    runner_.attr("close")();
  } catch (py::error_already_set&) {
    // the program's last words (a paused program ended here); nothing to report to
  }
  runner_ = py::object();
}

bool PythonAlgorithm::isProgram() const {
  py::gil_scoped_acquire gil;
  return runner_.attr("is_program").cast<bool>();
}

void PythonAlgorithm::run(const char* method, py::object api, int64_t utime) {
  Call running;
  try {
    runner_.attr("call")(method, api, utime);
  } catch (py::error_already_set& e) {
    throw component::AlgorithmFault(describe(e));
  }
}

std::string takeConsole() {
  std::lock_guard<std::mutex> lock(console_mutex);
  trimConsole();
  std::string text = console_dropped ? "[... earlier output dropped: the console keeps the last 64 KB]\n" : "";
  text += console_text;
  console_text.clear();
  console_dropped = false;
  return text;
}

std::string PythonAlgorithm::describe(py::error_already_set& e) {
  std::string text;
  try {
    text = interpreter().helpers.attr("describe")(e.value(), e.trace(), interpreter().file).cast<std::string>();
  } catch (py::error_already_set& inner) {
    text = std::string(e.what()) + " (and describing it failed: " + inner.what() + ")";
  }
  // A MemoryError in a sandboxed run is the sandbox's limit, said as for C++ (where it was raised after it).
  const std::string limit = e.matches(PyExc_MemoryError) ? component::memoryLimitReason() : "";
  return limit.empty() ? text : limit + " (" + text + ")";
}

}  // namespace aula::python

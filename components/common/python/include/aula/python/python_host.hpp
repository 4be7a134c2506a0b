#pragma once
// The Python host: a student's MyAlgorithm.py behind the same entry points as a C++ plugin
// (algorithm_plugin.hpp). Each exercise builds one host module (aula_add_python_host) that binds
// its API objects with pybind11 under the C++ names and wraps the student's class in the
// exercise's algorithm interface (PythonAlgorithm); this part is the same for all three:
// - the interpreter: Debian's /usr/bin/python3, isolated (no PYTHONPATH, no user site-packages,
//   no python from PATH), its path cut to Debian's stdlib and dist-packages (numpy, cv2), started
//   once and never shut down (numpy cannot start twice);
// - the student's file, read and run afresh for every new algorithm (hot reload), its folder
//   first on sys.path (its own modules, dropped again on reload), in any generation's shape, told
//   from the file (host.py): Aula's (class MyAlgorithm(seed), execute(api) every period),
//   JdeRobot-Academy 2017-18's (MyAlgorithm(pose3d, motors, ...), its own run() loop) or
//   RoboticsAcademy's (`import HAL, GUI` or WebGUI, Frequency; a program run from its top with
//   `while True:`); the student's code runs on a greenlet of the calling thread, and waiting for
//   sim time returns the call (host.py says when);
// - Python's clocks are the simulator's (time.time, perf_counter, monotonic, sleep, datetime.now:
//   host.py);
// - the exercise's HAL and GUI modules (RoboticsAcademy's names, components/<exercise>/python/),
//   and the modules a generation's program imports (MAP, WebGUI, Frequency, jderobot...), made
//   afresh for every algorithm;
// - what the student prints goes to the component's stdout/stderr as before and to the window's
//   console (takeConsole);
// - `random` and numpy's global generator seeded with the run's seed before the file runs, and
//   numpy's default_rng() without a seed drawing from the run's seed sequence;
// - every Python exception, a SyntaxError at load included, becomes an AlgorithmFault in the
//   student's own lines ("MyAlgorithm.py:12: ZeroDivisionError: division by zero (...)");
// - interrupt(): a call that overran its budget raises inside the student's loop.

#include <aula/component/algorithm_plugin.hpp>

#include <pybind11/pybind11.h>

#include <cstdint>
#include <string>
#include <vector>

namespace aula::python {
namespace py = pybind11;

// A Python module's text, compiled in (embed_sources.cmake): host.py and the modules every
// exercise shares in hostSources(), the exercise's HAL.py, GUI.py... in exerciseSources() (each
// host module's own).
struct Source {
  const char* name;  // the module's name ("HAL")
  const char* text;
};
const std::vector<Source>& hostSources();
const std::vector<Source>& exerciseSources();

// What the student's code printed since the last take (stdout and stderr, in order), at most the
// last 64 KB (a line says when more was dropped). Any thread.
std::string takeConsole();

// The file the host's factory loads; starts the interpreter on first use and imports the heavy
// modules the file imports (numpy, cv2: host.py's preload), outside any call's budget. Error
// text or "".
std::string setFile(const std::string& path);
// Raises `why` inside the call now running (from another thread; waits for the GIL).
void interrupt(const std::string& why);

// One instance of the student's class MyAlgorithm, and calls to its methods.
class PythonAlgorithm {
 public:
  // Runs the file, seeds, imports `api_module` (the exercise's bindings) and makes
  // MyAlgorithm(seed). Throws AlgorithmFault.
  PythonAlgorithm(uint64_t seed, const char* api_module);
  ~PythonAlgorithm();
  PythonAlgorithm(const PythonAlgorithm&) = delete;
  PythonAlgorithm& operator=(const PythonAlgorithm&) = delete;

  // self.<method>(api) (RoboticsAcademy's shape: the program on until it waits), the api object
  // passed by reference (never copied, never owned by Python), at the api's sim time. Throws
  // AlgorithmFault.
  template <class Api>
  void call(const char* method, Api& api) {
    py::gil_scoped_acquire gil;
    keepThreadState(gil);
    run(method, py::cast(&api, py::return_value_policy::reference), api.clock.utime());
  }
  // A program in RoboticsAcademy's shape (no class MyAlgorithm) rather than a class.
  bool isProgram() const;

 private:
  // Marks this thread as the one to interrupt while a call runs (under the GIL).
  struct Call {
    Call();
    ~Call();
  };
  static std::string describe(py::error_already_set& e);
  // The calling thread's Python thread state, kept for the thread's life: pybind11 makes a new one
  // at each acquire on a thread Python did not start (the window's AlgorithmThread) and deletes
  // it at release, and a paused greenlet belongs to the thread state it ran on.
  static void keepThreadState(py::gil_scoped_acquire& gil);
  void run(const char* method, py::object api, int64_t utime);  // under the GIL

  py::object runner_;  // host.py's Runner
};

// The student's class behind an exercise's interface whose one method is execute(Api&)
// (vacuum, Autopark); `kApiModule` names the exercise's bindings.
template <class Algorithm, class Api, const char* kApiModule>
class PythonExecuteAlgorithm : public Algorithm {
 public:
  explicit PythonExecuteAlgorithm(uint64_t seed) : algorithm_(seed, kApiModule) {}
  void execute(Api& api) override { algorithm_.call("execute", api); }

 private:
  PythonAlgorithm algorithm_;
};

}  // namespace aula::python

// The entry points of the exercise's host module: the four of algorithm_plugin.hpp, the factory
// making `PythonClass(seed)` (an ALGORITHM), and the three of the Python host.
#define AULA_PYTHON_HOST_ENTRY_POINTS(EXERCISE, ALGORITHM, PythonClass)                                        \
  AULA_PLUGIN_EXPORT int aula_algorithm_abi_version() { return AULA_ALGORITHM_ABI_VERSION; }                  \
  AULA_PLUGIN_EXPORT int aula_algorithm_exercise_abi_version() { return AULA_EXERCISE_ABI_VERSION; }         \
  AULA_PLUGIN_EXPORT const char* aula_algorithm_exercise() { return #EXERCISE; }                             \
  AULA_PLUGIN_EXPORT ALGORITHM* aula_##EXERCISE##_algorithm_v1(uint64_t seed) { return new PythonClass(seed); } \
  AULA_PLUGIN_EXPORT const char* aula_python_set_file(const char* path) {                                    \
    static std::string error;                                                                                 \
    error = aula::python::setFile(path);                                                                      \
    return error.empty() ? nullptr : error.c_str();                                                           \
  }                                                                                                           \
  AULA_PLUGIN_EXPORT void aula_python_interrupt(const char* why) { aula::python::interrupt(why); }            \
  AULA_PLUGIN_EXPORT const char* aula_python_take_console() {                                                \
    static std::string text;                                                                                  \
    text = aula::python::takeConsole();                                                                       \
    return text.c_str();                                                                                      \
  }

#pragma once
// Which algorithm a component runs, and running it with the student's faults contained. Every
// algorithm is a plugin, found by name: the exercise's built-ins (references, baselines: NAME is
// <lib>/aula/references/libaula_<exercise>_NAME.so, a plugin of its own, so that no component
// contains a reference a student's plugin could call), "student" (the in-tree template, built as a
// plugin like any student's), the path of a plugin (.so, built with aula_add_algorithm) or of a
// student's Python file (.py, run by the exercise's Python host behind the same entry points).
// Around every call into the algorithm:
// - an exception is caught: the fault's text is kept, the robot stopped, the algorithm halted;
//   with windows (containHangs), so is a crash (SIGSEGV...) inside a C++ algorithm's call
//   (crash_report.hpp: its text names the student's line); headless, a crash ends the process;
// - a call past its budget (AlgorithmBudgets: CPU time of the thread that runs it, time it spends
//   blocked; never the machine's wall time) ends the process (ExecuteWatchdog) with its own exit
//   code and reason, which the launcher explains; with windows (containHangs) the calls run on an
//   AlgorithmThread instead, and a call given up halts the algorithm for good: the fault says so,
//   the component freezes its devices and stops the robot (its onHung hook), the window stays
//   responsive; an algorithm that can be interrupted (Python) is first raised into, and a call
//   that then returns is an ordinary fault;
// - non-finite motor commands are counted, and said once in the log.

#include <aula/component/algorithm_box.hpp>
#include <aula/component/algorithm_thread.hpp>
#include <aula/component/box_wire.hpp>
#include <aula/component/devices.hpp>
#include <aula/component/crash_report.hpp>
#include <aula/component/execute_watchdog.hpp>
#include <aula/component/plugin_library.hpp>
#include <aula/component/printed_text.hpp>

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace aula::component {

// The non-template half: the plugin, the fault, the counters and the log lines.
class AlgorithmHostBase {
 public:
  // The in-tree student template's plugin: <bin>/../lib/aula/algorithms/libaula_<exercise>_student.so.
  static std::string studentPluginPath(const std::string& exercise);
  // Is `choice` a plugin file rather than a built-in's name?
  static bool namesPlugin(const std::string& choice);

  const std::string& choice() const { return choice_; }
  // For reports: a built-in's name ("reference", "student"), or the plugin's file name ("libmy_algorithm.so").
  std::string name() const;
  // A student's file (or the in-tree template) rather than a built-in: Reload offers its new build.
  bool isPlugin() const { return !plugin_path_.empty() && !builtin_; }
  bool isBuiltin() const { return builtin_; }
  // The algorithm runs in a process of its own (Component.OwnProcess, algorithm_box.hpp).
  bool ownProcess() const { return own_process_; }
  // How many processes of the algorithm were started so far (each Reload starts one): what
  // went to the previous one (TeleTaxi's map) goes again.
  int64_t boxStarts() const { return box_starts_; }
  // The plugin's file, kept when a reload failed: the window watches it.
  const std::string& pluginPath() const { return plugin_path_; }
  // What runs, for windows and logs: "reference", "libmy_algorithm.so (built 2026-11-23 17:04:12)"
  // or "MyAlgorithm.py (saved 2026-11-23 17:04:12)".
  std::string label() const;
  // A rebuilt plugin waits on disk (hot reload: the window offers it at the next Run).
  bool pluginChanged() const;
  // Why the algorithm was halted ("execute() threw std::runtime_error: ..."), or "".
  const std::string& fault() const { return fault_; }
  int64_t nonFiniteCommands() const { return motors_.nonFiniteTotal(); }
  // One line for the end of the run when commands were refused, else "".
  std::string nonFiniteSummary() const;

  // Takes what the algorithm printed since the last take (a Python program's print() and its
  // stderr; "" for C++, whose output goes to the component's stdout), keeps it for the window's
  // console (printed()) and returns it: the component publishes it after each tick.
  std::string takePrinted();
  const PrintedText& printed() const { return printed_; }
  // A Python program: its prints are taken (the window shows a console).
  bool takesPrints() const;

  // With windows: calls run on a thread of their own, and one that does not return within the
  // budget halts the algorithm instead of ending the process (no effect when the budget is 0).
  void containHangs();
  // A call was abandoned: nothing runs or reloads any more, and whatever that call can reach
  // (the algorithm, the plugin, the devices) is never touched or freed again; end the process
  // with std::_Exit. `hook` runs once, when it happens (the component freezes its devices).
  bool hung() const { return hung_; }
  // Calls run on an AlgorithmThread (containHangs).
  bool containsHangs() const { return thread_ != nullptr; }
  // A call crashed (with windows, where a crash inside a call is survived): the algorithm it
  // ran in is left as the crash left it, never destroyed (its destructor could crash again).
  bool crashed() const { return crashed_; }
  void setOnHung(std::function<void()> hook) { on_hung_ = std::move(hook); }

 protected:
  AlgorithmHostBase(std::string program, std::string exercise, std::string choice, Motors& motors,
                    const AlgorithmBudgets& budgets, bool own_process);
  void loadPlugin();
  // Loads the plugin again (in a process of its own: starts that process again); a file that
  // cannot be used becomes the fault.
  bool reloadPlugin();
  // Runs `call` under the watchdog (or on the AlgorithmThread); an exception becomes the fault.
  // False when it threw or hung. `call` must own what it uses: a hung call outlives this frame.
  bool guarded(const char* what, const CallBudget& budget, std::function<void()> call);
  const AlgorithmBudgets& budgets() const { return budgets_; }
  // In a process of its own: starts it (the algorithm loaded there); PluginError as loadPlugin's.
  void startBox();
  // One call in that process; false when it failed (the fault says why).
  bool callBox(uint64_t seed, const char* what, CallKind kind, const std::function<void(BoxWire&)>& inputs,
               const std::function<void(BoxWire&)>& outputs);
  void dropBox() { box_.reset(); }

  std::string program_, exercise_, choice_;
  Motors& motors_;
  std::string plugin_path_;
  bool builtin_ = false;  // one of the exercise's built-ins (its own plugin under references/)
  std::unique_ptr<PluginLibrary> plugin_;
  int64_t refused_mtime_ns_ = -1;  // the build a reload could not use: not offered again
  std::string fault_;
  bool crashed_ = false;

 private:
  void noteNonFinite();
  void abandonHungCall(const std::string& why);
  // The algorithm's process ended: headless, this process ends the same way; with windows, it
  // is the algorithm's fault.
  void boxEnded(const BoxEnded& ended);
  // Its lines (escape tries...) to the launcher, as if said here.
  void passOnBoxLines();
  AlgorithmBudgets budgets_;
  ExecuteWatchdog watchdog_;
  std::unique_ptr<AlgorithmThread> thread_;  // with windows (containHangs)
  bool hung_ = false;
  bool own_process_ = false;
  int64_t box_starts_ = 0;
  bool windows_ = false;  // containHangs(): with windows, the algorithm's end is a fault
  std::unique_ptr<AlgorithmBox> box_;
  std::string box_printed_;  // what its replies brought, not yet taken
  std::function<void()> on_hung_;
  int64_t non_finite_said_ = 0;
  PrintedText printed_;
};

template <class Algorithm>
class AlgorithmHost : public AlgorithmHostBase {
 public:
  // Throws PluginError (exit 2) for an unknown name or a plugin that cannot be used, at once.
  // `own_process`: the algorithm runs in a process of its own (algorithm_box.hpp), called with
  // callInBox; else here, called with call.
  AlgorithmHost(std::string program, std::string exercise, std::string choice, Motors& motors,
                const AlgorithmBudgets& budgets, bool own_process = false)
      : AlgorithmHostBase(std::move(program), std::move(exercise), std::move(choice), motors, budgets, own_process) {
    if (own_process) {
      startBox();
    } else {
      loadPlugin();
    }
  }
  ~AlgorithmHost() {  // the algorithm's code lives in the plugin
    dropBox();
    dropAlgorithm();
  }

  // Calls `use(algorithm)` (creating it with `seed` on first use) with faults contained.
  // Does nothing once halted by a fault. False when it threw now.
  // Creating it has a budget of its own (Component.StartBudget), apart from the first call's.
  bool call(uint64_t seed, const char* what, CallKind kind, const std::function<void(Algorithm&)>& use) {
    if (!fault_.empty() || ownProcess()) return false;
    if (!algorithm_ && !guarded("creating the algorithm (loading its file, its imports, its constructor)",
                                budgets().start, [this, seed] { algorithm_ = create(seed); })) {
      return false;
    }
    const CallBudget& budget = kind == CallKind::Plan ? budgets().plan : budgets().execute;
    return guarded(what, budget, [this, use] { use(*algorithm_); });  // copies: the call may outlive this frame (a hang)
  }
  // The same call in the algorithm's own process: `inputs` writes what the API gives now (the
  // exercise's exchange), `outputs` reads what the algorithm left. Does nothing once halted.
  bool callInBox(uint64_t seed, const char* what, CallKind kind, const std::function<void(BoxWire&)>& inputs,
                 const std::function<void(BoxWire&)>& outputs) {
    if (!fault_.empty()) return false;
    return callBox(seed, what, kind, inputs, outputs);
  }

  // Drops the algorithm and loads the plugin's file again (a new build). The next call creates a
  // fresh algorithm. False when the new file cannot be used: the fault says why, and nothing runs
  // (the old build is gone too: nothing half-loaded runs) until a reload succeeds.
  bool reload() {
    if (hung()) return false;  // the abandoned call may still be running in the algorithm
    fault_.clear();
    dropAlgorithm();  // none here when it runs in a process of its own
    return reloadPlugin();
  }

 private:
  void dropAlgorithm() {
    if (crashed_) abandonAfterCrash(algorithm_.release());  // left as the crash left it
    if (algorithm_ && containsHangs() && !hung()) {
      // Ended on the thread its calls ran on, under the watchdog like a call: a Python program
      // paused there (a greenlet of that thread) is ended by that thread, its `finally` run at
      // Reload. Ended from the window's thread, greenlet put it off to the next call on the
      // AlgorithmThread: the old program's last words ran inside the new one's first call.
      Algorithm* algorithm = algorithm_.release();
      guarded("ending the algorithm", budgets().execute, [algorithm] { delete algorithm; });
    }
    algorithm_.reset();
    crashed_ = false;
  }
  std::unique_ptr<Algorithm> create(uint64_t seed) {
    if (plugin_ == nullptr) throw std::runtime_error("no algorithm is loaded");
    auto made = plugin_->make<Algorithm>(seed);
    if (!made) throw std::runtime_error("the algorithm's factory returned no algorithm");
    return made;
  }

  std::unique_ptr<Algorithm> algorithm_;
};

}  // namespace aula::component

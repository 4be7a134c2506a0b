#include "aula/component/algorithm_host.hpp"

#include <aula/component/algorithm_plugin.hpp>
#include <aula/component/crash_report.hpp>
#include <aula/component/memory_limit.hpp>
#include <aula/component/throw_site.hpp>
#include <aula/config/paths.hpp>

#include <cxxabi.h>
#include <csignal>
#include <cmath>
#include <pthread.h>

#include <filesystem>
#include <iostream>
#include <memory>
#include <new>
#include <optional>
#include <sstream>
#include <thread>
#include <typeinfo>

#include <aula/process/exit_codes.hpp>

#include <cstdlib>

#include <unistd.h>

namespace aula::component {
namespace fs = std::filesystem;

namespace {

std::string typeName(const std::type_info& type);

// Whether this thread is inside a call into the student's code: an exit() from there is the
// student's, said as such (the process's exit code kExitAlgorithmExited), not a silent client.
thread_local bool in_student_call = false;

void exitedInsideACall() {
  if (!in_student_call) return;
  static const char said[] = "the algorithm called exit() inside a call into it: the component ends\n";
  (void)!::write(STDERR_FILENO, said, sizeof said - 1);
  std::_Exit(process::kExitAlgorithmExited);
}

// A line of the algorithm's own process, to the launcher as if said here (crash_report.hpp's line).
void passOnLine(const std::string& line) {
  const int line_fd = crashLineFd();
  if (line_fd < 0) return;
  const std::string said = line + "\n";
  (void)!::write(line_fd, said.data(), said.size());
}

// What a call into the student's code came to: "" when it returned, else what it threw and
// where in the plugin (when it can tell), or where it crashed.
struct CallOutcome {
  std::string fault;
  bool crashed = false;  // what the call owned is left as the crash left it
};

// Runs `call`, surviving a crash in it when `survive_crashes` (crash_report.hpp).
CallOutcome outcomeOf(const char* what, const std::function<void()>& call, const PluginLibrary* plugin,
                      bool survive_crashes);

// Runs `call`; "" when it returned, else what it threw, and where in `plugin` (when it can tell).
std::string faultOf(const char* what, const std::function<void()>& call, const PluginLibrary* plugin) {
  static const bool watched = std::atexit(exitedInsideACall) == 0;
  (void)watched;
  struct InCall {
    InCall() { in_student_call = true; }
    ~InCall() { in_student_call = false; }
  } in_call;
  std::optional<KeepThrowSites> keep_throw_sites;  // a C++ plugin's: a Python host says its own lines
  if (plugin != nullptr && !PluginLibrary::isPythonFile(plugin->path())) keep_throw_sites.emplace();
  try {
    call();
  } catch (const AlgorithmFault& e) {
    return e.what();  // already in the student's lines (a Python traceback)
  } catch (const std::bad_alloc& e) {
    const std::string limit = memoryLimitReason();  // a sandboxed run's memory limit is why
    if (!limit.empty()) return limit + " (" + what + " threw std::bad_alloc)";
    return std::string(what) + " threw std::bad_alloc: " + e.what();
  } catch (const std::exception& e) {
    const std::string site = plugin != nullptr ? plugin->throwSite(dynamic_cast<const void*>(&e)) : "";
    return std::string(what) + " threw " + typeName(typeid(e)) + ": " + e.what() +
           (site.empty() ? "" : " (thrown at " + site + ")");
  } catch (...) {
    return std::string(what) + " threw an exception that is not a std::exception";
  }
  return "";
}

CallOutcome outcomeOf(const char* what, const std::function<void()>& call, const PluginLibrary* plugin,
                      bool survive_crashes) {
  if (!survive_crashes) return {faultOf(what, call, plugin)};
  std::string crash;
  CallOutcome outcome{faultOf(what, [&] { crash = callSurvivingCrashes(call); }, plugin)};
  if (!crash.empty()) outcome = {std::string(what) + " " + crash, true};
  return outcome;
}

std::string typeName(const std::type_info& type) {
  int status = 0;
  char* demangled = abi::__cxa_demangle(type.name(), nullptr, nullptr, &status);
  std::string name = status == 0 && demangled != nullptr ? demangled : type.name();
  std::free(demangled);
  return name;
}

}  // namespace

std::string AlgorithmHostBase::studentPluginPath(const std::string& exercise) {
  return (fs::path(config::libDir()) / "algorithms" / ("libaula_" + exercise + "_student.so")).string();
}

bool AlgorithmHostBase::namesPlugin(const std::string& choice) {
  return choice.find('/') != std::string::npos || fs::path(choice).extension() == ".so" ||
         PluginLibrary::isPythonFile(choice);
}

AlgorithmHostBase::AlgorithmHostBase(std::string program, std::string exercise, std::string choice, Motors& motors,
                                     const AlgorithmBudgets& budgets, bool own_process)
    : program_(std::move(program)),
      exercise_(std::move(exercise)),
      choice_(std::move(choice)),
      motors_(motors),
      budgets_(budgets),
      watchdog_(program_, budgets.run),
      own_process_(own_process) {
  installCrashReport(program_, PluginImage{});
}

void AlgorithmHostBase::loadPlugin() {
  if (choice_ == "student") {
    plugin_path_ = studentPluginPath(exercise_);
  } else if (namesPlugin(choice_)) {
    plugin_path_ = fs::absolute(choice_).lexically_normal().string();
  } else if (const std::string builtin = config::builtinAlgorithmPath(exercise_, choice_); fs::exists(builtin)) {
    plugin_path_ = builtin;
    builtin_ = true;
  } else {
    throw PluginError("algorithm '" + choice_ + "': not a built-in algorithm of " + exercise_ + " (no " + builtin +
                      ") and not a plugin file (PATH.so) or a Python file (PATH.py)");
  }
  plugin_ = std::make_unique<PluginLibrary>(plugin_path_, exercise_);
  watchdog_.setInterrupter(plugin_->interrupter());
  installCrashReport(program_, plugin_->image());
  // Which file and which build runs, said once (a stale build is refused by `aula run`).
  std::cerr << (program_ + ": running " + plugin_path_ + " (" + label() + ")\n") << std::flush;  // one write
}

bool AlgorithmHostBase::reloadPlugin() {
  const std::string file = fs::path(plugin_path_).filename().string();
  watchdog_.setInterrupter({});
  plugin_.reset();
  box_.reset();
  try {
    if (own_process_) {
      startBox();
    } else {
      loadPlugin();
    }
  } catch (const PluginError& e) {
    refused_mtime_ns_ = PluginLibrary::mtimeNs(plugin_path_);
    fault_ = "reloading " + file + " failed: " + e.what();
    motors_.stop();
    std::cerr << program_ << ": " << fault_ << std::endl;
    return false;
  }
  std::cerr << program_ << ": loaded " << label() << std::endl;
  return true;
}

bool AlgorithmHostBase::pluginChanged() const {
  if (builtin_) return false;  // Aula's own build, not the student's
  if (own_process_) {
    const int64_t now = isPlugin() ? PluginLibrary::mtimeNs(plugin_path_) : -1;
    const int64_t loaded = box_ ? box_->loaded().plugin_mtime_ns : -1;
    return now >= 0 && now != loaded && now != refused_mtime_ns_;
  }
  if (plugin_ != nullptr) return plugin_->changedOnDisk();
  const int64_t now = isPlugin() ? PluginLibrary::mtimeNs(plugin_path_) : -1;
  return now >= 0 && now != refused_mtime_ns_;
}

std::string AlgorithmHostBase::name() const {
  if (own_process_) return box_ ? box_->loaded().name : choice_;
  return plugin_ == nullptr || choice_ == "student" || builtin_ ? choice_ : fs::path(plugin_->path()).filename().string();
}

std::string AlgorithmHostBase::label() const {
  if (builtin_) return choice_;
  if (box_) return box_->loaded().label;
  if (plugin_ == nullptr) return plugin_path_.empty() ? choice_ : fs::path(plugin_path_).filename().string() + " (not loaded)";
  const char* when = PluginLibrary::isPythonFile(plugin_->path()) ? " (saved " : " (built ";
  return fs::path(plugin_->path()).filename().string() + when + plugin_->builtAt() + ")";
}

std::string AlgorithmHostBase::takePrinted() {
  std::string text;
  if (own_process_) {
    text = std::move(box_printed_);
    box_printed_.clear();
    printed_.append(text);
    return text;
  }
  if (hung_ || !plugin_) return {};  // an abandoned call's plugin is never touched again
  text = plugin_->takePrinted();
  printed_.append(text);
  return text;
}

bool AlgorithmHostBase::takesPrints() const { return PluginLibrary::isPythonFile(plugin_path_); }

void AlgorithmHostBase::containHangs() {
  windows_ = true;
  if (own_process_) return;  // its process ends instead, and this one stays
  if (thread_) return;
  thread_ = std::make_unique<AlgorithmThread>();
  watchdog_.setResponse(ExecuteWatchdog::Response::Flag);
}

bool AlgorithmHostBase::guarded(const char* what, const CallBudget& budget, std::function<void()> call) {
  if (hung_) return false;
  if (thread_) {
    // The outcome is shared with the job: an abandoned call may still write it. A crash in a C++
    // algorithm comes back as its fault (a Python one may hold the interpreter's lock: it ends the process).
    auto outcome = std::make_shared<CallOutcome>();
    const bool survive = !PluginLibrary::isPythonFile(plugin_path_);
    ExecuteWatchdog& watchdog = watchdog_;  // never destroyed once a call is abandoned (the process _Exits)
    const bool returned = thread_->run(
        [what, budget, outcome, survive, &watchdog, call = std::move(call), plugin = plugin_.get()] {
          watchdog.arm(what, budget);
          *outcome = outcomeOf(what, call, plugin, survive);
          watchdog.disarm();
        },
        watchdog_);
    if (!returned) {
      abandonHungCall(watchdog_.abandoned());
      return false;
    }
    fault_ = outcome->fault;
    crashed_ = outcome->crashed;
  } else {
    watchdog_.arm(what, budget);
    fault_ = faultOf(what, call, plugin_.get());
    watchdog_.disarm();
  }
  noteNonFinite();
  if (fault_.empty()) return true;
  motors_.stop();
  std::cerr << program_ << ": the student's algorithm failed: " << fault_ << "; the robot is stopped" << std::endl;
  return false;
}

void AlgorithmHostBase::abandonHungCall(const std::string& why) {
  hung_ = true;
  (void)thread_.release();  // still running the call: never joined, never freed
  fault_ = why;
  std::cerr << program_ << ": the student's algorithm: " << fault_ << "; the robot is stopped and the algorithm halted. "
            << "Fix it, rebuild, and start the run again." << std::endl;
  if (on_hung_) on_hung_();
}

void AlgorithmHostBase::startBox() {
  BoxStart start{program_, exercise_, choice_, motors_.maxV(), motors_.maxW()};
  box_ = std::make_unique<AlgorithmBox>(start, budgets_);
  box_->setOnLine([](const std::string& line) { passOnLine(line); });
  ++box_starts_;
  plugin_path_ = box_->loaded().plugin_path;
  builtin_ = box_->loaded().builtin;
  // (that process said which file and build runs)
}

bool AlgorithmHostBase::callBox(uint64_t seed, const char* what, CallKind kind,
                                const std::function<void(BoxWire&)>& inputs,
                                const std::function<void(BoxWire&)>& outputs) {
  if (!box_) return false;
  const AlgorithmBox::Result result = box_->call(seed, what, kind, inputs, outputs);
  passOnBoxLines();
  if (!result.returned) {
    boxEnded(result.ended);
    return false;
  }
  const BoxReply& reply = result.reply;
  box_printed_ += reply.printed;
  // Its non-finite commands, counted here as if sent here (a NaN counts and zeroes its axis),
  // then the commands it left.
  const double v = motors_.getV(), w = motors_.getW(), l = motors_.getL();
  for (int64_t n = motors_.nonFiniteV(); n < reply.non_finite_v; ++n) motors_.sendV(std::nan(""));
  for (int64_t n = motors_.nonFiniteW(); n < reply.non_finite_w; ++n) motors_.sendW(std::nan(""));
  for (int64_t n = motors_.nonFiniteL(); n < reply.non_finite_l; ++n) motors_.sendL(std::nan(""));
  motors_.sendV(v);
  motors_.sendW(w);
  motors_.sendL(l);
  // Its process said the fault and the first non-finite command, as the component said them.
  fault_ = reply.fault;
  if (fault_.empty()) return true;
  motors_.stop();
  return false;
}

void AlgorithmHostBase::passOnBoxLines() {
  for (const std::string& line : box_->takeLines()) passOnLine(line);
}

void AlgorithmHostBase::boxEnded(const BoxEnded& ended) {
  motors_.stop();
  if (!windows_) {
    // Headless: this process ends as the algorithm's did (its lines already passed on), so that
    // the launcher explains it as before: the same exit code, or death by the same signal.
    std::cout.flush();
    std::cerr.flush();
    if (ended.exit_code > 128) {
      const int signal = ended.exit_code - 128;
      struct sigaction plain {};
      plain.sa_handler = SIG_DFL;
      ::sigaction(signal, &plain, nullptr);
      sigset_t only;
      sigemptyset(&only);
      sigaddset(&only, signal);
      ::pthread_sigmask(SIG_UNBLOCK, &only, nullptr);
      ::raise(signal);
    }
    std::_Exit(ended.exit_code);
  }
  fault_ = ended.reason;
  std::cerr << program_ << ": the student's algorithm: " << fault_ << "; the robot is stopped and the algorithm halted. "
            << "Fix it, rebuild, and start the run again." << std::endl;
}

void AlgorithmHostBase::noteNonFinite() {
  const int64_t total = motors_.nonFiniteTotal();
  if (total == 0 || non_finite_said_ != 0) return;
  non_finite_said_ = total;
  std::cerr << program_ << ": the algorithm sent a motor command that is not a finite number (NaN or inf): that axis "
            << "is set to 0; every such command is counted in the window and the report" << std::endl;
}

std::string AlgorithmHostBase::nonFiniteSummary() const {
  std::string out;
  auto add = [&](const char* call, int64_t count) {
    if (count == 0) return;
    out += std::string(out.empty() ? "" : ", ") + call + "(nan/inf) ignored: " + std::to_string(count) + " times";
  };
  add("sendV", motors_.nonFiniteV());
  add("sendW", motors_.nonFiniteW());
  add("sendL", motors_.nonFiniteL());
  return out;
}

}  // namespace aula::component

#include "aula/supervision/supervisor.hpp"

#include <aula/auth/run_key.hpp>
#include <aula/config/paths.hpp>
#include <aula/process/child_process.hpp>
#include <aula/process/exit_codes.hpp>
#include <aula/process/line_pipe.hpp>
#include <aula/process/machine_reason.hpp>
#include <aula/process/process_tree.hpp>
#include <aula/process/signal_watcher.hpp>
#include <aula/sandbox/sandbox.hpp>
#include <aula/supervision/capped_output.hpp>
#include <aula/supervision/escape_watch.hpp>
#include <aula/supervision/rules.hpp>
#include <aula/supervision/wall_backstop.hpp>

#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>

#include <fcntl.h>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace aula::supervision {
namespace {

// One supervised run: its children, the private lines to them, and what has happened so far.
class RunSupervisor {
 public:
  explicit RunSupervisor(const Supervision& run) : run_(run) {}

  int supervise() {
    process::SignalWatcher signals;  // before the children start: they unblock for themselves
    // Orphans of the run (a student's detached children) come to the launcher, which ends them.
    ::prctl(PR_SET_CHILD_SUBREAPER, 1, 0, 0, 0);
    if (run_.sandbox && run_.has_referee) output_ = std::make_unique<CappedOutput>();
    start();
    for (;;) {
      if (signals.stopRequested()) {
        std::cerr << "aula: stopping (" << (signals.signal() == SIGINT ? "SIGINT" : "SIGTERM") << ")\n";
        result_ = 128 + signals.signal();
        break;
      }
      checkWallBudget();
      checkLimits();
      // The referee had its chance to grade and say why: now everything stops.
      // (A backstop: on a starved machine grading what there is can take a while.)
      if (ending_since_ && std::chrono::steady_clock::now() - *ending_since_ > std::chrono::seconds(60)) break;
      readSimulatorStatus();
      readComponentLine();
      escapes_.poll();
      bool finished = false;
      for (size_t i = 0; i < children_.size(); ++i) {
        if (const auto code = children_[i]->poll()) finished = onExit(i, *code) || finished;
      }
      if (finished) break;
      awaitEvent(signals);
    }
    stopAll();
    return result_;
  }

 private:
  // The command line of child `i`, with its private lines passed as inherited descriptors.
  struct Launch {
    std::vector<std::string> args;
    std::vector<int> passed;
    std::vector<int> ours_to_close;  // passed descriptors to close once the child has them
  };

  Launch launchOf(size_t i, int status_write, int control_read, int crash_write, const std::optional<auth::Key>& key) const {
    const bool referee = run_.has_referee && i == 2;
    const bool keyed = key && (i == 0 || referee);
    Launch launch{run_.lines[i], {}, {}};
    auto pass = [&](const std::string& option, int fd) {
      launch.args.push_back("--" + option + "=" + std::to_string(process::ChildProcess::passedFd(launch.passed.size())));
      launch.passed.push_back(fd);
    };
    if (i == 0 && status_write >= 0) pass("status-fd", status_write);  // why the simulator ended a graded run
    if (referee) pass("control-fd", control_read);
    auto passKey = [&](const std::string& option, const auth::Key& k) {  // a pipe of its own; ours closed once passed
      pass(option, auth::keyPipe(k));
      launch.ours_to_close.push_back(launch.passed.back());
    };
    if (keyed) passKey("key-fd", *key);
    if (i == 1 && key) passKey("lockstep-key-fd", auth::clientKey(*key, run_.component_client));  // its client's, not the run's
    if (i == 1 && crash_write >= 0) pass("crash-fd", crash_write);  // where a crash struck, in the student's lines
    const bool sandboxed = run_.sandbox && run_.has_referee && i == 1;
    if (sandboxed) {  // the student's code: in bubblewrap, under the seccomp filter (docs/grading.md)
      const int seccomp_child_fd = process::ChildProcess::passedFd(launch.passed.size());
      launch.passed.push_back(sandbox::seccompProgram());
      launch.ours_to_close.push_back(launch.passed.back());
      launch.args = sandbox::wrap(launch.args, seccomp_child_fd, run_.confinement);
    }
    return launch;
  }

  // Starts the simulator, the component (sandboxed if asked) and the referee, each with its
  // private lines: the simulator's status pipe, the referee's control pipe, a graded run's key.
  void start() {
    int control[2] = {-1, -1}, status[2] = {-1, -1}, crash[2] = {-1, -1};
    if (run_.has_referee &&
        (pipe2(control, O_CLOEXEC) != 0 || pipe2(status, O_CLOEXEC) != 0 || pipe2(crash, O_CLOEXEC) != 0)) {
      throw std::runtime_error("pipe2 failed");
    }
    // A graded run's key, for the simulator and the referee only (never the component, which runs
    // the student's code): each reads it from a pipe of its own, not from its command line.
    const std::optional<auth::Key>& key = run_.key;
    for (size_t i = 0; i < run_.lines.size(); ++i) {
      const Launch launch = launchOf(i, status[1], control[0], crash[1], key);
      // The sandboxed component's output goes through the launcher, capped.
      const std::string output = i == 1 && output_ ? output_->childPath() : "";
      children_.push_back(std::make_unique<process::ChildProcess>(launch.args, output, output, launch.passed, run_.placement));
      for (const int fd : launch.ours_to_close) close(fd);  // the child has its copy
      if (i == 1 && output_) output_->childStarted();
    }
    if (control[0] >= 0) close(control[0]);
    if (status[1] >= 0) close(status[1]);
    if (crash[1] >= 0) close(crash[1]);
    crash_line_ = std::make_unique<process::LinePipe>(crash[0]);
    control_fd_ = control[1];
    ::signal(SIGPIPE, SIG_IGN);  // a line to a referee that has ended fails (EPIPE): the launcher goes on
    if (run_.has_referee) escapes_.tellTo(control_fd_);
    simulator_status_ = std::make_unique<process::LinePipe>(status[0]);
  }

  void tellReferee(const std::string& why) {
    const std::string line = "abort " + why + "\n";
    (void)!write(control_fd_, line.data(), line.size());
    told_referee_ = true;
    abort_reason_ = why;
    result_ = 1;
  }

  void abortedReport(const std::string& why) { writeAbortedReport(run_.report_path, run_.exercise, run_.algorithm, why); }

  // The referee is told why the run ends and has a few seconds to grade what there is.
  void endRun(const std::string& why) {
    if (run_.has_referee && !told_referee_) tellReferee(why);
    ending_since_ = std::chrono::steady_clock::now();
    result_ = 1;
  }

  // The run's wall-clock backstop (wall_backstop.hpp): the machine's reason.
  void checkWallBudget() {
    if (ending_since_ || !backstop_.ranOut(std::chrono::steady_clock::now())) return;
    const std::string why = backstop_.reason();
    std::cerr << "aula: " << why << "\n";
    machine_ = true;
    endRun(why);
  }

  // A sandboxed component past a limit the launcher counts: its output (stdout and stderr), its
  // processes (bubblewrap's two aside, looked at every 100 ms) and the memory they use together.
  // The run ends with that reason and the component is stopped at once (its whole process
  // namespace dies with it).
  void checkLimits() {
    if (!run_.sandbox || children_.size() < 2 || told_referee_) return;
    const auto now = std::chrono::steady_clock::now();
    std::vector<pid_t> processes;
    const bool look = now - processes_checked_ >= std::chrono::milliseconds(100);
    if (look) processes_checked_ = now, processes = process::descendantsOf(children_[1]->pid());
    const std::string why =
        limitPassed(run_.confinement.limits, output_ ? output_->bytesRead() : 0, look ? &processes : nullptr);
    if (why.empty()) return;
    std::cerr << "aula: " << why << ": stopping it\n";
    tellReferee(why);
    children_[1]->stop(std::chrono::milliseconds(200));
  }

  // Sleeps until a child exits or a stop signal comes, or 20 ms pass (the wall budget, the
  // simulator's status line): the end of a run is seen when it happens.
  void awaitEvent(const process::SignalWatcher& signals) {
    std::vector<pollfd> watched{{signals.fd(), POLLIN, 0}};
    if (escapes_.fd() >= 0) watched.push_back({escapes_.fd(), POLLIN, 0});
    if (output_) {
      output_->drain();
      watched.push_back({output_->readFd(), POLLIN, 0});
    }
    for (const auto& child : children_) {
      if (child->exitFd() >= 0 && !child->poll()) watched.push_back({child->exitFd(), POLLIN, 0});
    }
    ::poll(watched.data(), watched.size(), 20);
  }

  // The component's private line: a crash's one line (kept for its exit), and each system call
  // its watch refused (sandbox/forbidden_calls.hpp), handed to the referee at once: it flags the run.
  void readComponentLine() {
    if (!crash_line_) return;
    for (const std::string& line : crash_line_->lines()) {
      if (!escapes_.onComponentLine(line)) crash_text_ = line;
    }
  }

  void readSimulatorStatus() {
    for (const std::string& line : simulator_status_->lines()) {
      if (line.rfind("ended ", 0) != 0 || simulator_ended_run_) continue;
      simulator_ended_run_ = true;
      // The simulator's own pipe, which no student's code writes: its lockstep backstop.
      if (process::saysMachineReason(line.substr(6))) machine_ = true;
      std::cerr << "aula: the simulator ended the run: " << line.substr(6) << "\n";
      endRun(line.substr(6));
    }
  }

  // Child `i` exited with `code`: the rules decide (rules.hpp), this carries it out.
  bool onExit(size_t i, int code) {
    if (i == 0) readSimulatorStatus();  // its last words were written before it exited
    if (run_.has_referee && i == 2) {
      referee_exited_ = true;
      escapes_.tellTo(-1);
    }
    ExitEvent event;
    event.role = static_cast<Role>(i);
    event.code = code;
    event.has_referee = run_.has_referee;
    event.headless = run_.headless;
    event.referee_told = told_referee_;
    event.simulator_ended_run = simulator_ended_run_;
    event.last_child = i + 1 == children_.size();
    if (i == 1) {
      readComponentLine();
      event.crash_line = crash_text_;
      event.refused = escapes_.lastRefused();
    }
    const std::string name = std::filesystem::path(run_.lines[i][0]).filename().string();  // the program, not its sandbox's wrapper
    const ExitVerdict verdict = supervision::onExit(event, name);
    if (verdict.discard && control_fd_ >= 0) (void)!write(control_fd_, "discard\n", 8);
    if (!verdict.message.empty()) std::cerr << "aula: " << verdict.message << "\n";
    if (!verdict.aborted_report.empty()) abortedReport(verdict.aborted_report);
    if (!verdict.tell_referee.empty()) {
      const std::string& said = verdict.algorithm_fault.empty() ? verdict.tell_referee : verdict.algorithm_fault;
      if (verdict.message.empty()) {
        std::cerr << "aula: " << name << " (running the algorithm '" << run_.algorithm << "') ended the run: " << said << "\n";
      }
      if (!verdict.algorithm_fault.empty()) {
        const std::string line = "fault " + verdict.algorithm_fault + "\n";
        (void)!write(control_fd_, line.data(), line.size());
      }
      tellReferee(verdict.tell_referee);
    }
    if (verdict.result) result_ = *verdict.result;
    machine_ = machine_ || verdict.machine;
    return verdict.run_over;
  }

  // The clients first (they send their last commands and leave lockstep), the simulator last.
  void stopAll() {
    escapes_.tellTo(-1);
    if (control_fd_ >= 0) close(control_fd_);
    for (auto c = children_.rbegin(); c != children_.rend(); ++c) {
      const int code = (*c)->stop();
      if (code != 0 && code != 128 + SIGTERM && code != 128 + SIGINT && result_ == 0 && (*c)->name() != run_.lines[0][0]) {
        std::cerr << "aula: " << (*c)->name() << " stopped with code " << code << "\n";
      }
    }
    // Whatever the run left behind (detached, SIGTERM blocked): gone with it.
    const std::vector<pid_t> left = process::descendantsOf(::getpid());
    for (const pid_t orphan : left) ::kill(orphan, SIGKILL), ::waitpid(orphan, nullptr, 0);  // ours (the subreaper): reaped
    if (output_) output_->finish();
    if (told_referee_ && !referee_exited_) {
      // Told why, the referee did not answer in time (stopped, hung): the report says why, no mark.
      std::cerr << "aula: the referee did not grade in time: the run has no mark\n";
      abortedReport(machine_ ? abort_reason_ + "; the referee did not answer"
                             : process::machineReason(abort_reason_ + "; the referee did not grade in time"));
      machine_ = true;
    }
    // What the launcher saw itself, in its exit code: the only word `aula grade` takes for it.
    if (machine_ && result_ != 0 && result_ != 128 + SIGINT && result_ != 128 + SIGTERM) result_ = process::kExitMachine;
  }

  const Supervision& run_;
  std::vector<std::unique_ptr<process::ChildProcess>> children_;
  int control_fd_ = -1;  // the referee's control pipe, our end
  std::unique_ptr<process::LinePipe> simulator_status_;
  std::unique_ptr<process::LinePipe> crash_line_;  // the component's crash, in the student's lines
  std::string crash_text_;                         // its last crash line
  EscapeWatch escapes_{run_.watched_lcm_port};  // what the student's code tried to get out of the run
  int result_ = 0;
  bool told_referee_ = false, referee_exited_ = false, simulator_ended_run_ = false;
  bool machine_ = false;  // the run ends for the machine's reason, as the launcher saw it
  std::string abort_reason_;
  std::optional<std::chrono::steady_clock::time_point> ending_since_;
  std::chrono::steady_clock::time_point processes_checked_;
  WallBackstop backstop_{run_.wall_budget_s, std::chrono::steady_clock::now()};
  std::unique_ptr<CappedOutput> output_;
};

}  // namespace

int supervise(const Supervision& run) { return RunSupervisor(run).supervise(); }

}  // namespace aula::supervision

#pragma once
// The reading end of a private line between the launcher and a process it started: a pipe
// inherited by the child, never on the bus, so no other process can write to it. One message per
// line. The launcher to the referee (`--control-fd=N`):
//   fault <text>        the algorithm's fault, said before the abort it causes (a crash's line:
//                       "component crashed (SIGSEGV) at MyAlgorithm.cpp:14 (MyAlgorithm::execute)").
//   abort <reason>      the run cannot go on (a process died, execute() hung): grade and end.
//   discard             the run never started: no mark.
// The simulator to the launcher (`--status-fd=N`):
//   ended <reason>      the simulator ended a graded run early (a client silent too long).
// The component to the launcher (`--crash-fd=N`), as it dies of a signal:
//   crashed (SIGSEGV) at MyAlgorithm.cpp:14 (MyAlgorithm::execute)
// Reads never block; a closed pipe (the other end exited) reads as nothing more.

#include <string>
#include <vector>

namespace aula::process {

class LinePipe {
 public:
  explicit LinePipe(int fd = -1);  // -1: no pipe (three-terminal mode)
  ~LinePipe();
  LinePipe(const LinePipe&) = delete;
  LinePipe& operator=(const LinePipe&) = delete;

  // Complete lines received since the last call.
  std::vector<std::string> lines();

 private:
  int fd_;
  std::string pending_;
};

}  // namespace aula::process

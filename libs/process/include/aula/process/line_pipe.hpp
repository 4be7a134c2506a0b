#pragma once
// The reading end of a private line between the launcher and a process it started: a pipe
// inherited by the child, never on the bus, so no other process can write to it. One message per
// line. The launcher to the referee (`--control-fd=N`):
//   abort <reason>      the run cannot go on (a process died, execute() hung): grade and end.
//   discard             the run never started: no mark.
// The simulator to the launcher (`--status-fd=N`):
//   ended <reason>      the simulator ended a graded run early (a client silent too long).
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

#pragma once
// The launcher's private line to a process it started: a pipe inherited as `--control-fd=N`,
// never on the bus, so no other process can write to it. One command per line:
//   abort <reason>      the run cannot go on (a process died, execute() hung): grade and end.
// Reads never block; a closed pipe (the launcher died) reads as nothing more.

#include <string>
#include <vector>

namespace aula::app {

class ControlPipe {
 public:
  explicit ControlPipe(int fd = -1);  // -1: no pipe (three-terminal mode)
  ~ControlPipe();
  ControlPipe(const ControlPipe&) = delete;
  ControlPipe& operator=(const ControlPipe&) = delete;

  // Complete lines received since the last call.
  std::vector<std::string> lines();

 private:
  int fd_;
  std::string pending_;
};

}  // namespace aula::app

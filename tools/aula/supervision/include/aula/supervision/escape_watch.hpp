#pragma once
// What a graded run's student code tried to get out of the run, as the launcher sees it, told to
// the referee ("escape WHAT" on its control pipe: TruthGate::escapeAttempt flags the run):
// - the system calls the sandboxed component's watch refused ("refused mount" on its private
//   line: sandbox/forbidden_calls.hpp);
// - in a private network, the datagrams sent to any port but the run's (sandbox::DatagramWatch).
// At most kTold lines: a loop of tries must not fill the referee's pipe.

#include <aula/sandbox/datagram_watch.hpp>

#include <memory>
#include <string>

namespace aula::supervision {

class EscapeWatch {
 public:
  static constexpr int kTold = 256;

  // `watched_lcm_port` > 0: watch datagrams to other ports (said once on stderr when it cannot).
  explicit EscapeWatch(int watched_lcm_port);
  // Where to tell the referee (-1: nobody to tell any more).
  void tellTo(int control_fd) { control_fd_ = control_fd; }
  // A line of the component's private line: true when it was a refused call (told), false when it
  // is something else (a crash's line, the caller's).
  bool onComponentLine(const std::string& line);
  // The datagrams seen since the last call, told.
  void poll();
  int fd() const { return datagrams_ ? datagrams_->fd() : -1; }  // readable when one was seen
  // The last refused try of the component's ("" for none): why a component that ended for one did.
  const std::string& lastRefused() const { return last_refused_; }

 private:
  void tell(const std::string& what);
  int control_fd_ = -1;
  int told_ = 0;
  std::string last_refused_;
  std::unique_ptr<sandbox::DatagramWatch> datagrams_;
};

}  // namespace aula::supervision

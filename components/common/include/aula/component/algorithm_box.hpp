#pragma once
// The student's algorithm in a process of its own (Component.OwnProcess): the component, which
// stays trusted (the world, the bus, the run's keys, the teacher's environment), starts its own
// executable again as `PROGRAM --algorithm-box` and hands it only what the API gives, one call at
// a time, over a socket pair: the sensors in, the commands and beliefs back (box_wire.hpp, each
// exercise's exchange functions). That process is exec'd afresh (nothing of the component's
// memory), with a short environment, no descriptor but the socket and its private line, and the
// component is not dumpable once it starts it (no /proc/PID/mem, environ or fd of the component
// for it to read).
//
// Inside, the algorithm is hosted as in the component (AlgorithmHost: its plugin or Python file,
// its CPU budgets, its faults, its crash report, the forbidden-call watch), so a fault, a budget
// and a report are the same whichever process runs it. What ends that process (a crash, a call
// past its budget, exit() inside a call, a forbidden try) is said on its private line and by its
// exit status; the component then takes the same end (headless: the same line to the launcher,
// the same exit code or signal, so the launcher explains it as before) or, with windows, shows it
// as the algorithm's fault and stays (a new process at the next Reload).
//
// Lockstep makes it cost no mark: the component waits for the reply whatever the machine's load.

#include <aula/component/box_wire.hpp>
#include <aula/component/execute_watchdog.hpp>
#include <aula/process/child_process.hpp>
#include <aula/process/line_pipe.hpp>

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace aula::component {

// What the algorithm's process is told once, at its start.
struct BoxStart {
  std::string program;   // the component's name ("vacuum-cleaner"), for the same messages
  std::string exercise;  // "vacuum"
  std::string choice;    // the algorithm: a built-in's name, "student", PATH.so or PATH.py
  double max_v_mps = 0, max_w_radps = 0;
};

// What the process loaded, for the component's windows and logs (AlgorithmHostBase's accessors).
struct BoxLoaded {
  std::string plugin_path, name, label;
  bool builtin = false;
  int64_t plugin_mtime_ns = -1;  // the file it loaded, to offer a new build
};

// How one call came back.
struct BoxReply {
  std::string fault;    // "" when it returned
  std::string printed;  // what a Python program printed during it
  int64_t non_finite_v = 0, non_finite_w = 0, non_finite_l = 0;  // totals so far
};

// The process ended (a crash, a budget, exit(), a forbidden try): why, for the fault and the
// launcher.
struct BoxEnded {
  int exit_code = 0;    // 128 + N: signal N
  std::string reason;   // for the student: "execute() crashed (SIGSEGV) at MyAlgorithm.cpp:14 (...)"
};

// Frames on the socket: a 32-bit length, then the bytes (BoxWire's), each sent whole.
// A frame is read in one read() when it is all there (every exchange of a control period was two
// reads a frame, at each end), into a buffer that is kept and never cleared (zeroing 64 KiB for
// each frame was most of a call's own cost).
class FrameReader {
 public:
  // `wait_in_poll`: wait for a frame in poll() before reading. A read() blocked on a stream
  // socket is woken each time the peer takes what this end wrote (the socket's space to write):
  // the algorithm's end, which waits while the component reads its reply, was switched in and
  // out for nothing once a call. poll() for input is woken by input only.
  explicit FrameReader(int fd = -1, bool wait_in_poll = false) : fd_(fd), wait_in_poll_(wait_in_poll) {}
  void setFd(int fd) { fd_ = fd; }
  // The next frame into `bytes`: false at the end of the stream (or an error) before a frame.
  // Throws BoxWireError for a frame past `max_bytes` or a stream that ends inside a frame.
  bool read(std::string& bytes, size_t max_bytes);

 private:
  static constexpr size_t kChunk = 64 * 1024;
  bool fill(size_t bytes);  // until `bytes` are buffered: false at the end of the stream or an error
  size_t buffered() const { return end_ - start_; }

  int fd_ = -1;
  bool wait_in_poll_ = false;
  std::unique_ptr<char[]> buffer_;  // read but not yet taken: [start_, end_)
  size_t capacity_ = 0, start_ = 0, end_ = 0;
};

// The component's end.
class AlgorithmBox {
 public:
  // Starts the process and has it load the algorithm; PluginError (its text) when the algorithm
  // cannot be used, at once, as in the component. `budgets` go with it (its calls are watched
  // there). `crash_fd`: the launcher's private line, where that process's lines are passed on
  // (-1: none).
  AlgorithmBox(const BoxStart& start, const AlgorithmBudgets& budgets);
  ~AlgorithmBox();  // closes the socket: the process ends its algorithm and exits
  AlgorithmBox(const AlgorithmBox&) = delete;
  AlgorithmBox& operator=(const AlgorithmBox&) = delete;

  const BoxLoaded& loaded() const { return loaded_; }

  // One call into the algorithm: `inputs` writes what the API gives now, `outputs` reads what it
  // left (also after a fault: the motors stopped). The reply, or the end of the process.
  struct Result {
    bool returned = false;  // a reply came (its fault may be set)
    BoxReply reply;
    BoxEnded ended;         // when !returned
  };
  Result call(uint64_t seed, const char* what, CallKind kind, const std::function<void(BoxWire&)>& inputs,
              const std::function<void(BoxWire&)>& outputs);

  // The lines its process said on its private line since the last take (escape tries, its
  // crash's or overrun's line): the component passes them on to the launcher.
  std::vector<std::string> takeLines();
  // Called with each line as it comes while a call runs (an escape try is said at once, as the
  // component said it when the algorithm ran inside it); the rest wait for takeLines().
  void setOnLine(std::function<void(const std::string&)> on_line) { on_line_ = std::move(on_line); }

 private:
  BoxEnded endOf(const char* what);
  // Until the reply can be read, passing on each line its process says meanwhile.
  void waitForReply();

  int socket_ = -1;
  FrameReader frames_;  // socket_'s
  std::unique_ptr<process::ChildProcess> child_;
  std::unique_ptr<process::LinePipe> line_;
  std::vector<std::string> pending_lines_;  // read when it ended, not yet taken
  std::function<void(const std::string&)> on_line_;
  std::vector<std::string> call_lines_;  // what it said during the current call (an end's reason)
  int line_fd_ = -1;  // line_'s, to wait on
  BoxLoaded loaded_;
  bool gone_ = false;
};

// The algorithm's end: `PROGRAM --algorithm-box` (its own main's first line; argv[1] alone).
bool isAlgorithmBox(int argc, char** argv);

// Sends one frame whole (FrameReader reads it). Throws BoxWireError when the socket fails.
void writeFrame(int fd, const std::string& bytes);

// The descriptors the algorithm's process is given.
constexpr int kBoxSocketFd = process::ChildProcess::passedFd(0);
constexpr int kBoxLineFd = process::ChildProcess::passedFd(1);
// The largest frame a reply or a call may be: a belief's map at its largest, and the rest.
constexpr size_t kMaxReplyBytes = size_t{512} << 20;
// The start, written by the component and read by the algorithm's process: the same at both ends.
void ioStart(BoxWire& wire, BoxStart& start, AlgorithmBudgets& budgets);
// Messages of the protocol, the first byte of a frame.
enum class BoxMessage : uint8_t { Start = 1, Loaded = 2, Refused = 3, Call = 4, Reply = 5 };

}  // namespace aula::component

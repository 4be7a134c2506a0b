#include "aula/component/algorithm_box.hpp"

#include <aula/component/crash_report.hpp>
#include <aula/component/plugin_library.hpp>
#include <aula/process/exit_codes.hpp>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <unistd.h>

namespace aula::component {

namespace {

// What the algorithm's process keeps of the component's environment: where to write, the
// language, one BLAS thread (sandbox.cpp's reasons), and Aula's own data folder.
constexpr const char* kBoxEnvironment[] = {"PATH", "TMPDIR", "HOME", "XDG_CACHE_HOME", "OPENBLAS_NUM_THREADS",
                                           "OMP_NUM_THREADS", "LANG", "LC_ALL", "AULA_DATA_DIR"};

std::vector<std::string> boxEnvironment() {
  std::vector<std::string> out;
  for (const char* name : kBoxEnvironment) {
    const char* value = std::getenv(name);
    if (value != nullptr) out.push_back(std::string(name) + "=" + value);
  }
  return out;
}

void ioBudget(BoxWire& wire, CallBudget& budget) {
  wire.io(budget.cpu_s, "budgets");
  wire.io(budget.blocked_s, "budgets");
}

std::string signalName(int signal) {
  switch (signal) {
    case SIGSEGV: return "SIGSEGV";
    case SIGBUS: return "SIGBUS";
    case SIGFPE: return "SIGFPE";
    case SIGILL: return "SIGILL";
    case SIGABRT: return "SIGABRT";
    case SIGKILL: return "SIGKILL";
    case SIGTERM: return "SIGTERM";
    case SIGSYS: return "SIGSYS";
    case SIGXFSZ: return "SIGXFSZ";
    case SIGXCPU: return "SIGXCPU";
    default: return "signal " + std::to_string(signal);
  }
}

}  // namespace

void ioStart(BoxWire& wire, BoxStart& start, AlgorithmBudgets& budgets) {
  wire.io(start.program, 256, "start");
  wire.io(start.exercise, 256, "start");
  wire.io(start.choice, 4096, "start");
  wire.io(start.max_v_mps, "start");
  wire.io(start.max_w_radps, "start");
  ioBudget(wire, budgets.start);
  ioBudget(wire, budgets.execute);
  ioBudget(wire, budgets.plan);
  wire.io(budgets.run.cpu_s, "budgets");
  wire.io(budgets.run.blocked_s, "budgets");
  wire.io(budgets.memory_bytes, "budgets");
}

bool FrameReader::fill(size_t bytes) {
  while (buffered() < bytes) {
    if (capacity_ - start_ < std::max(bytes, kChunk)) {  // room for the frame and a whole chunk after it
      const size_t capacity = std::max({capacity_, bytes, kChunk}) + kChunk;
      std::unique_ptr<char[]> grown(new char[capacity]);  // not zeroed: only what read() wrote is used
      if (buffered() > 0) std::memcpy(grown.get(), buffer_.get() + start_, buffered());
      buffer_ = std::move(grown);
      capacity_ = capacity;
      end_ -= start_;
      start_ = 0;
    }
    if (wait_in_poll_) {
      pollfd input{fd_, POLLIN, 0};
      if (::poll(&input, 1, -1) < 0 && errno != EINTR) return false;
    }
    const ssize_t got = ::read(fd_, buffer_.get() + end_, capacity_ - end_);
    if (got > 0) {
      end_ += static_cast<size_t>(got);
      continue;
    }
    if (got == 0) {
      if (buffered() == 0) return false;
      throw BoxWireError("the algorithm's socket ended inside a frame");
    }
    if (errno != EINTR) return false;
  }
  return true;
}

bool FrameReader::read(std::string& bytes, size_t max_bytes) {
  uint32_t length = 0;
  if (!fill(sizeof length)) return false;
  std::memcpy(&length, buffer_.get() + start_, sizeof length);
  if (length > max_bytes) {
    throw BoxWireError("a frame of " + std::to_string(length) + " bytes, at most " + std::to_string(max_bytes));
  }
  if (!fill(sizeof length + length)) throw BoxWireError("the algorithm's socket ended inside a frame");
  bytes.assign(buffer_.get() + start_ + sizeof length, length);
  start_ += sizeof length + length;
  if (start_ == end_) start_ = end_ = 0;  // the usual case: nothing after it
  return true;
}

void writeFrame(int fd, const std::string& bytes) {
  const uint32_t length = static_cast<uint32_t>(bytes.size());
  std::string frame(reinterpret_cast<const char*>(&length), sizeof length);
  frame += bytes;
  size_t done = 0;
  while (done < frame.size()) {
    const ssize_t put = ::send(fd, frame.data() + done, frame.size() - done, MSG_NOSIGNAL);
    if (put > 0) {
      done += static_cast<size_t>(put);
    } else if (put < 0 && errno != EINTR) {
      throw BoxWireError(std::string("the algorithm's socket: ") + std::strerror(errno));
    }
  }
}

bool isAlgorithmBox(int argc, char** argv) { return argc == 2 && std::strcmp(argv[1], "--algorithm-box") == 0; }

AlgorithmBox::AlgorithmBox(const BoxStart& start, const AlgorithmBudgets& budgets) {
  int pair[2];
  if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, pair) != 0) {
    throw std::runtime_error(std::string("cannot make the algorithm's socket: ") + std::strerror(errno));
  }
  int line[2];
  if (::pipe2(line, O_CLOEXEC) != 0) {
    ::close(pair[0]);
    ::close(pair[1]);
    throw std::runtime_error(std::string("cannot make the algorithm's line: ") + std::strerror(errno));
  }
  socket_ = pair[0];
  frames_.setFd(socket_);
  line_ = std::make_unique<process::LinePipe>(line[0]);
  line_fd_ = line[0];
  // Nothing of this process (its memory, environment, descriptors under /proc) for a process of
  // the same user to read: the algorithm's is one.
  ::prctl(PR_SET_DUMPABLE, 0);
  std::error_code error;
  const std::string self = std::filesystem::read_symlink("/proc/self/exe", error).string();
  try {
    child_ = std::make_unique<process::ChildProcess>(std::vector<std::string>{self, "--algorithm-box"}, "", "",
                                                     std::vector<int>{pair[1], line[1]}, process::Placement(),
                                                     boxEnvironment());
  } catch (...) {
    ::close(pair[1]);
    ::close(line[1]);
    throw;
  }
  ::close(pair[1]);
  ::close(line[1]);

  BoxWire wire = BoxWire::writing();
  auto type = static_cast<uint8_t>(BoxMessage::Start);
  BoxStart s = start;
  AlgorithmBudgets b = budgets;
  wire.io(type, "start");
  ioStart(wire, s, b);
  writeFrame(socket_, wire.bytes());

  std::string frame;
  if (!frames_.read(frame, 1 << 20)) {
    const BoxEnded ended = endOf("loading the algorithm");
    throw PluginError(start.program + ": the algorithm's process ended while loading it: " + ended.reason);
  }
  BoxWire in = BoxWire::reading(std::move(frame));
  in.io(type, "loaded");
  if (type == static_cast<uint8_t>(BoxMessage::Refused)) {
    std::string why;
    in.io(why, 1 << 16, "refused");
    throw PluginError(why);
  }
  if (type != static_cast<uint8_t>(BoxMessage::Loaded)) throw BoxWireError("loaded: message " + std::to_string(type));
  in.io(loaded_.plugin_path, 4096, "loaded");
  in.io(loaded_.name, 4096, "loaded");
  in.io(loaded_.label, 4096, "loaded");
  in.io(loaded_.builtin, "loaded");
  in.expectEnd("loaded");
  loaded_.plugin_mtime_ns = PluginLibrary::mtimeNs(loaded_.plugin_path);
}

AlgorithmBox::~AlgorithmBox() {
  if (socket_ >= 0) ::close(socket_);  // its end of the stream: it ends its algorithm and exits
  if (child_ && !gone_ && !child_->wait(std::chrono::seconds(5))) child_->stop();
}

AlgorithmBox::Result AlgorithmBox::call(uint64_t seed, const char* what, CallKind kind,
                                        const std::function<void(BoxWire&)>& inputs,
                                        const std::function<void(BoxWire&)>& outputs) {
  Result result;
  if (gone_) {
    result.ended = {process::kExitFailed, "the algorithm's process has ended"};
    return result;
  }
  BoxWire wire = BoxWire::writing();
  auto type = static_cast<uint8_t>(BoxMessage::Call);
  auto kind_code = static_cast<int32_t>(kind);
  std::string call_name = what;
  wire.io(type, "call");
  wire.io(seed, "call");
  wire.io(kind_code, "call");
  wire.io(call_name, 256, "call");
  inputs(wire);
  call_lines_.clear();
  std::string frame;
  try {
    writeFrame(socket_, wire.bytes());
    waitForReply();
    if (!frames_.read(frame, kMaxReplyBytes)) {
      result.ended = endOf(what);
      return result;
    }
  } catch (const BoxWireError&) {
    result.ended = endOf(what);  // a broken socket: the process is gone, or as good as
    return result;
  }
  BoxWire in = BoxWire::reading(std::move(frame));
  in.io(type, "reply");
  if (type != static_cast<uint8_t>(BoxMessage::Reply)) throw BoxWireError("reply: message " + std::to_string(type));
  in.io(result.reply.fault, 1 << 20, "reply");
  in.io(result.reply.printed, kMaxReplyBytes, "reply");
  in.io(result.reply.non_finite_v, "reply");
  in.io(result.reply.non_finite_w, "reply");
  in.io(result.reply.non_finite_l, "reply");
  outputs(in);
  in.expectEnd("reply");
  result.returned = true;
  return result;
}

void AlgorithmBox::waitForReply() {
  pollfd watched[2] = {{socket_, POLLIN, 0}, {line_fd_, POLLIN, 0}};
  for (;;) {
    watched[0].revents = watched[1].revents = 0;
    if (::poll(watched, line_fd_ >= 0 ? 2 : 1, -1) < 0 && errno != EINTR) return;
    if (watched[1].revents != 0) {
      for (const std::string& line : line_->lines()) {
        call_lines_.push_back(line);
        if (on_line_) {
          on_line_(line);
        } else {
          pending_lines_.push_back(line);
        }
      }
      if ((watched[1].revents & (POLLHUP | POLLERR)) != 0) line_fd_ = -1;  // it has ended: the socket says so
    }
    if (watched[0].revents != 0) return;
  }
}

std::vector<std::string> AlgorithmBox::takeLines() {
  std::vector<std::string> out = std::move(pending_lines_);
  pending_lines_.clear();
  for (std::string& line : line_->lines()) out.push_back(std::move(line));
  return out;
}

BoxEnded AlgorithmBox::endOf(const char* what) {
  gone_ = true;
  if (socket_ >= 0) ::close(socket_);
  socket_ = -1;
  // It is ending or has ended (its socket closed with it): its status, then its last lines.
  const std::optional<int> code = child_->wait(std::chrono::seconds(10));
  BoxEnded ended;
  ended.exit_code = code ? *code : child_->stop();
  for (const std::string& line : line_->lines()) {
    pending_lines_.push_back(line);
    call_lines_.push_back(line);
  }
  // Its last words in this call: a crash's or an overrun's line, else (a forbidden try's end)
  // the last refusal.
  std::string said;
  for (const std::string& line : call_lines_) {
    if (line.rfind("crashed ", 0) == 0 || line.rfind(kOverranPrefix, 0) == 0) said = line;
    if (said.empty() && ended.exit_code == process::kExitAlgorithmForbidden && line.rfind("refused ", 0) == 0) said = line;
  }
  const std::string call = what;
  if (said.rfind("crashed ", 0) == 0) {
    ended.reason = call + " " + said;  // as a crash survived in the component says it
  } else if (said.rfind(kOverranPrefix, 0) == 0) {
    ended.reason = said.substr(std::strlen(kOverranPrefix));
  } else if (said.rfind("refused ", 0) == 0) {
    ended.reason = "the algorithm tried to " + said.substr(8) + ", which no student's algorithm may";
  } else if (ended.exit_code == process::kExitAlgorithmExited) {
    ended.reason = "the algorithm called exit() inside " + call;
  } else if (ended.exit_code > 128) {
    ended.reason = "the algorithm's process died of " + signalName(ended.exit_code - 128) + " in " + call;
  } else {
    ended.reason = "the algorithm's process ended (exit code " + std::to_string(ended.exit_code) + ") in " + call;
  }
  return ended;
}

}  // namespace aula::component

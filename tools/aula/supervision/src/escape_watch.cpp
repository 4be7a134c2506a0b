#include "aula/supervision/escape_watch.hpp"

#include <aula/sandbox/forbidden_calls.hpp>

#include <iostream>
#include <stdexcept>

#include <unistd.h>

namespace aula::supervision {

EscapeWatch::EscapeWatch(int watched_lcm_port) {
  if (watched_lcm_port <= 0) return;
  try {
    datagrams_ = std::make_unique<sandbox::DatagramWatch>(watched_lcm_port);
  } catch (const std::runtime_error& e) {
    std::cerr << "aula: datagrams sent outside the run are not watched (" << e.what() << ")\n";
  }
}

bool EscapeWatch::onComponentLine(const std::string& line) {
  const std::string prefix = sandbox::kRefusedPrefix;
  if (line.rfind(prefix, 0) != 0) return false;
  last_refused_ = line.substr(prefix.size());
  tell(last_refused_);
  return true;
}

void EscapeWatch::poll() {
  if (!datagrams_) return;
  for (const std::string& what : datagrams_->seen()) tell(what);
}

void EscapeWatch::tell(const std::string& what) {
  if (told_ >= kTold || control_fd_ < 0) return;
  ++told_;
  const std::string line = "escape " + what.substr(0, 100) + "\n";
  (void)!::write(control_fd_, line.data(), line.size());
}

}  // namespace aula::supervision

#include "aula/lcm/bus.hpp"

#include <aula/config/config.hpp>

#include <arpa/inet.h>
#include <dirent.h>
#include <netinet/in.h>
#include <linux/filter.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <vector>

namespace aula::lcmbus {
namespace {

constexpr const char* kUdpmScheme = "udpm://";

bool isUdpm(const std::string& url) { return url.rfind(kUdpmScheme, 0) == 0; }

// The port of a udpm:// URL (LCM's 7667 when it names none), its group checked too.
int udpmPort(const std::string& url) {
  std::string rest = url.substr(std::strlen(kUdpmScheme));
  rest = rest.substr(0, rest.find('?'));
  int port = 7667;
  if (const auto colon = rest.find(':'); colon != std::string::npos) {
    const std::string text = rest.substr(colon + 1);
    char* end = nullptr;
    const long value = std::strtol(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0' || value <= 0 || value > 65535) {
      throw config::ConfigError("LCM URL '" + url + "': port '" + text + "' is not a number from 1 to 65535");
    }
    port = static_cast<int>(value);
    rest = rest.substr(0, colon);
  }
  const std::string group = rest.empty() ? "239.255.76.67" : rest;
  in_addr address{};
  if (inet_pton(AF_INET, group.c_str(), &address) != 1 || (ntohl(address.s_addr) >> 28) != 0xE) {
    throw config::ConfigError("LCM URL '" + url + "': '" + group + "' is not an IPv4 multicast group (224.0.0.0 to 239.255.255.255)");
  }
  return port;
}

// LCM subscribes to a regular expression; Aula's channels are plain names.
bool isPattern(const std::string& channel) {
  for (char c : channel) {
    const bool plain = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '-' || c == '/';
    if (!plain) return true;
  }
  return false;
}

}  // namespace

std::string resolveUrl(const config::CommandLine& cl, const config::Config& cfg) {
  const std::string from_option = cl.option("lcm-url");
  if (!from_option.empty()) return from_option;
  // A declared default does not hide LCM's own environment variable.
  if (cfg.has("Aula.LcmUrl") && cfg.origin("Aula.LcmUrl") != "default") return cfg.getString("Aula.LcmUrl");
  if (const char* env = std::getenv("LCM_DEFAULT_URL"); env != nullptr && *env != '\0') return env;
  return kDefaultUrl;
}

int freeUdpPort() {
  const int probe = socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  socklen_t size = sizeof address;
  const bool bound = probe >= 0 && bind(probe, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0 &&
                     getsockname(probe, reinterpret_cast<sockaddr*>(&address), &size) == 0;
  if (probe >= 0) close(probe);
  if (!bound) throw BusError("cannot get a free UDP port from the OS");
  return ntohs(address.sin_port);
}

std::string withFreePort(const std::string& url) {
  if (!isUdpm(url)) return url;
  const size_t query = url.find('?');
  const std::string head = url.substr(0, query);
  const size_t colon = head.rfind(':');
  if (colon == std::string::npos || colon < std::strlen(kUdpmScheme) || head.substr(colon + 1) != "0") return url;
  return head.substr(0, colon + 1) + std::to_string(freeUdpPort()) + (query == std::string::npos ? "" : url.substr(query));
}

std::set<int> udpSocketsBoundTo(int port) {
  std::set<int> found;
  DIR* fds = opendir("/proc/self/fd");
  if (fds == nullptr) return found;
  std::vector<int> candidates;
  while (const dirent* entry = readdir(fds)) {
    char* end = nullptr;
    const long fd = std::strtol(entry->d_name, &end, 10);
    if (*end == '\0' && fd != dirfd(fds)) candidates.push_back(static_cast<int>(fd));
  }
  closedir(fds);
  for (int fd : candidates) {
    int type = 0;
    socklen_t type_size = sizeof type;
    sockaddr_in address{};
    socklen_t address_size = sizeof address;
    if (getsockopt(fd, SOL_SOCKET, SO_TYPE, &type, &type_size) != 0 || type != SOCK_DGRAM) continue;
    if (getsockname(fd, reinterpret_cast<sockaddr*>(&address), &address_size) != 0) continue;
    if (address.sin_family == AF_INET && ntohs(address.sin_port) == port) found.insert(fd);
  }
  return found;
}


std::vector<SocketFilterInstruction> channelFilter(const std::set<std::string>& channels) {
  // Offsets from the start of the UDP header, where a UDP socket's filter starts reading.
  constexpr uint32_t kMagicOffset = 8;         // after the 8-byte UDP header
  constexpr uint32_t kChannelOffset = 8 + 8;   // after LCM's short header: magic, sequence number
  constexpr uint32_t kShortMagic = 0x4c433032;  // "LC02"
  constexpr uint32_t kAccept = 0xffffffff, kDrop = 0;
  auto op = [](uint16_t code, uint32_t value, uint8_t jt = 0, uint8_t jf = 0) {
    return SocketFilterInstruction{code, jt, jf, value};
  };
  std::vector<SocketFilterInstruction> program = {
      op(BPF_LD | BPF_W | BPF_ABS, kMagicOffset),
      op(BPF_JMP | BPF_JEQ | BPF_K, kShortMagic, 1, 0),
      op(BPF_RET | BPF_K, kAccept),  // a fragment of a long message
  };
  for (const std::string& channel : channels) {
    // Compare the name and its NUL in 4-, 2- and 1-byte loads (big-endian, as BPF loads them);
    // a mismatch jumps past this channel's block to the next.
    const std::string bytes = channel + '\0';
    std::vector<SocketFilterInstruction> block;
    for (std::size_t at = 0; at < bytes.size();) {
      const std::size_t width = bytes.size() - at >= 4 ? 4 : bytes.size() - at >= 2 ? 2 : 1;
      uint32_t value = 0;
      for (std::size_t i = 0; i < width; ++i) value = (value << 8) | static_cast<unsigned char>(bytes[at + i]);
      const uint16_t size = width == 4 ? BPF_W : width == 2 ? BPF_H : BPF_B;
      block.push_back(op(BPF_LD | size | BPF_ABS, kChannelOffset + static_cast<uint32_t>(at)));
      block.push_back(op(BPF_JMP | BPF_JEQ | BPF_K, value));
      at += width;
    }
    block.push_back(op(BPF_RET | BPF_K, kAccept));
    if (block.size() > 255) throw BusError("channel name too long for the socket filter: " + channel);
    for (std::size_t i = 0; i < block.size(); ++i) {
      if (block[i].code == (BPF_JMP | BPF_JEQ | BPF_K)) block[i].jump_if_false = static_cast<uint8_t>(block.size() - i - 1);
    }
    program.insert(program.end(), block.begin(), block.end());
  }
  program.push_back(op(BPF_RET | BPF_K, kDrop));
  return program;
}

Bus::Bus(std::string url) : url_(std::move(url)) {
  const char* stats = std::getenv("AULA_BUS_STATS");  // bench/exercise_overhead.sh
  print_stats_ = stats != nullptr && *stats != '\0';
  const bool udpm = isUdpm(url_);
  const int port = udpm ? udpmPort(url_) : 0;
  const std::set<int> before = udpm ? udpSocketsBoundTo(port) : std::set<int>{};
  receiver_ = std::make_unique<lcm::LCM>(url_);
  if (!receiver_->good()) {
    std::string why = "cannot open the LCM bus '" + url_ + "'";
    if (udpm) {
      why +=
          ": UDP multicast needs a multicast route. On a machine without a default route, run as "
          "root: 'ip link set lo multicast on; ip route add 224.0.0.0/4 dev lo'";
    }
    throw BusError(why);
  }
  if (!udpm) return;
  // LCM makes its receiving socket (and thread) on the first getFileno() or subscribe(): the one
  // socket on the port that appears now is it.
  if (receiver_->getFileno() < 0) throw BusError("cannot open the LCM bus '" + url_ + "': LCM's self test failed");
  std::vector<int> appeared;
  for (int fd : udpSocketsBoundTo(port)) {
    if (before.count(fd) == 0) appeared.push_back(fd);
  }
  if (appeared.size() != 1) {
    std::cerr << "aula: LCM bus " << url_ << ": cannot tell LCM's receiving socket (" << appeared.size()
              << " new sockets on the port); this process receives every channel" << std::endl;
    return;
  }
  receive_fd_ = appeared.front();
  applyFilter();
}

Bus::~Bus() {
  if (print_stats_) {
    // One write, so that the three processes' lines do not interleave on a shared terminal.
    const std::string line = std::string("aula-bus: ") + program_invocation_short_name + " handled " +
                             std::to_string(handled_) + " messages on " + url_ + "\n";
    std::cerr.write(line.data(), static_cast<std::streamsize>(line.size())).flush();
  }
}

void Bus::receive(const std::string& channel) {
  if (receive_fd_ < 0 || receive_all_) return;
  if (isPattern(channel)) {
    receive_all_ = true;
    const int unused = 0;  // the kernel wants an int, and ignores it
    if (setsockopt(receive_fd_, SOL_SOCKET, SO_DETACH_FILTER, &unused, sizeof unused) != 0) {
      throw BusError("LCM bus " + url_ + ": cannot lift the socket filter for '" + channel + "': " + std::strerror(errno));
    }
    return;
  }
  if (channels_.insert(channel).second) applyFilter();
}

void Bus::applyFilter() {
  static_assert(sizeof(SocketFilterInstruction) == sizeof(sock_filter), "the kernel's sock_filter layout");
  std::vector<SocketFilterInstruction> program = channelFilter(channels_);
  std::vector<sock_filter> kernel_program(program.size());
  for (std::size_t i = 0; i < program.size(); ++i) {
    kernel_program[i] = sock_filter{program[i].code, program[i].jump_if_true, program[i].jump_if_false, program[i].value};
  }
  sock_fprog filter{static_cast<unsigned short>(kernel_program.size()), kernel_program.data()};
  if (setsockopt(receive_fd_, SOL_SOCKET, SO_ATTACH_FILTER, &filter, sizeof filter) != 0) {
    throw BusError("LCM bus " + url_ + ": cannot set the socket filter for " + std::to_string(channels_.size()) +
                   " channels: " + std::strerror(errno));
  }
}

std::unique_ptr<Bus> openBus(const std::string& url) { return std::make_unique<Bus>(url); }

}  // namespace aula::lcmbus

#include "aula/sandbox/datagram_watch.hpp"

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include <arpa/inet.h>
#include <linux/filter.h>
#include <linux/if_packet.h>
#include <net/ethernet.h>
#include <net/if.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

namespace aula::sandbox {

namespace {

// Offsets are from the IPv4 header (a SOCK_DGRAM packet socket has no link header); a jump's
// targets count from the next instruction: every "dropped" lands on 10.
std::vector<sock_filter> filterFor(int lcm_port) {
  const auto port = static_cast<uint32_t>(lcm_port);
  return {
      {BPF_LD | BPF_B | BPF_ABS, 0, 0, static_cast<uint32_t>(SKF_AD_OFF + SKF_AD_PKTTYPE)},  // 0: A = pkttype
      {BPF_JMP | BPF_JEQ | BPF_K, 8, 0, PACKET_OUTGOING},  // 1: counted arriving only (lo shows it once so)
      {BPF_LD | BPF_B | BPF_ABS, 0, 0, 9},                 // 2: A = protocol
      {BPF_JMP | BPF_JEQ | BPF_K, 0, 6, IPPROTO_UDP},      // 3
      {BPF_LD | BPF_H | BPF_ABS, 0, 0, 6},                 // 4: A = flags and fragment offset
      {BPF_JMP | BPF_JSET | BPF_K, 4, 0, 0x1fff},          // 5: a later fragment has no UDP header
      {BPF_LDX | BPF_B | BPF_MSH, 0, 0, 0},                // 6: X = the IP header's length
      {BPF_LD | BPF_H | BPF_IND, 0, 0, 2},                 // 7: A = destination port
      {BPF_JMP | BPF_JEQ | BPF_K, 1, 0, port},             // 8: the run's own: dropped
      {BPF_RET | BPF_K, 0, 0, 64},                         // 9: kept (its headers)
      {BPF_RET | BPF_K, 0, 0, 0},                          // 10: dropped
  };
}

}  // namespace

DatagramWatch::DatagramWatch(int lcm_port) {
  fd_ = ::socket(AF_PACKET, SOCK_DGRAM | SOCK_NONBLOCK | SOCK_CLOEXEC, htons(ETH_P_IP));
  if (fd_ < 0) throw std::runtime_error(std::string("the datagram watch's socket: ") + std::strerror(errno));
  const std::vector<sock_filter> program = filterFor(lcm_port);
  const sock_fprog filter{static_cast<unsigned short>(program.size()), const_cast<sock_filter*>(program.data())};
  sockaddr_ll loopback{};
  loopback.sll_family = AF_PACKET;
  loopback.sll_protocol = htons(ETH_P_IP);
  loopback.sll_ifindex = static_cast<int>(::if_nametoindex("lo"));
  if (::setsockopt(fd_, SOL_SOCKET, SO_ATTACH_FILTER, &filter, sizeof filter) != 0 ||
      ::bind(fd_, reinterpret_cast<sockaddr*>(&loopback), sizeof loopback) != 0) {
    const std::string why = std::strerror(errno);
    ::close(fd_);
    throw std::runtime_error("the datagram watch: " + why);
  }
}

DatagramWatch::~DatagramWatch() {
  if (fd_ >= 0) ::close(fd_);
}

std::vector<std::string> DatagramWatch::seen() {
  std::vector<std::string> out;
  unsigned char packet[64];
  for (;;) {
    const ssize_t n = ::recv(fd_, packet, sizeof packet, 0);
    if (n < 0) break;  // EAGAIN: nothing more
    const size_t header = static_cast<size_t>(packet[0] & 0xf) * 4;
    if (n < static_cast<ssize_t>(header + 4)) continue;
    char address[INET_ADDRSTRLEN] = "?";
    ::inet_ntop(AF_INET, packet + 16, address, sizeof address);
    const int port = (packet[header + 2] << 8) | packet[header + 3];
    out.push_back("datagram to " + std::string(address) + ":" + std::to_string(port));
  }
  return out;
}

}  // namespace aula::sandbox

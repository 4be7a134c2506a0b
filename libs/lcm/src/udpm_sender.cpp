#include "aula/lcm/udpm_sender.hpp"

#include "aula/lcm/bus.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace aula::lcmbus {
namespace {

constexpr uint32_t kShortMagic = 0x4c433032;   // "LC02"
constexpr std::size_t kShortHeader = 8;        // magic, sequence number
constexpr std::size_t kShortMessageMax = 1400;  // LCM 1.3's LCM_SHORT_MESSAGE_MAX_SIZE: channel, NUL, payload

void putBe32(uint8_t* at, uint32_t value) {
  at[0] = static_cast<uint8_t>(value >> 24);
  at[1] = static_cast<uint8_t>(value >> 16);
  at[2] = static_cast<uint8_t>(value >> 8);
  at[3] = static_cast<uint8_t>(value);
}

}  // namespace

UdpmSender::UdpmSender(const UdpmUrl& url) {
  const std::string where = "LCM bus udpm://" + url.group + ":" + std::to_string(url.port);
  fd_ = socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
  if (fd_ < 0) throw BusError(where + ": cannot open a UDP socket to send: " + std::strerror(errno));
  const unsigned char ttl = static_cast<unsigned char>(url.ttl), loop = 1;
  sockaddr_in group{};
  group.sin_family = AF_INET;
  group.sin_port = htons(static_cast<uint16_t>(url.port));
  inet_pton(AF_INET, url.group.c_str(), &group.sin_addr);
  const char* failed = nullptr;
  if (setsockopt(fd_, IPPROTO_IP, IP_MULTICAST_TTL, &ttl, sizeof ttl) != 0) {
    failed = "IP_MULTICAST_TTL";
  } else if (setsockopt(fd_, IPPROTO_IP, IP_MULTICAST_LOOP, &loop, sizeof loop) != 0) {
    failed = "IP_MULTICAST_LOOP";
  } else if (connect(fd_, reinterpret_cast<const sockaddr*>(&group), sizeof group) != 0) {
    failed = "connect";
  }
  if (failed != nullptr) {
    const int error = errno;
    close(fd_);
    throw BusError(where + ": " + failed + ": " + std::strerror(error));
  }
}

UdpmSender::~UdpmSender() {
  if (fd_ >= 0) close(fd_);
}

bool UdpmSender::fitsOneDatagram(const std::string& channel, std::size_t size) {
  return channel.size() + 1 + size <= kShortMessageMax;
}

int UdpmSender::send(const Message* messages, std::size_t count) {
  headers_.resize(count * kShortHeader);
  pieces_.resize(count * 3);
  datagrams_.assign(count, mmsghdr{});
  for (std::size_t i = 0; i < count; ++i) {
    uint8_t* header = headers_.data() + i * kShortHeader;
    putBe32(header, kShortMagic);
    putBe32(header + 4, sequence_++);
    iovec* piece = pieces_.data() + i * 3;
    piece[0] = iovec{header, kShortHeader};
    piece[1] = iovec{const_cast<char*>(messages[i].channel->c_str()), messages[i].channel->size() + 1};
    piece[2] = iovec{const_cast<uint8_t*>(messages[i].data), messages[i].size};
    datagrams_[i].msg_hdr.msg_iov = piece;
    datagrams_[i].msg_hdr.msg_iovlen = 3;
  }
  for (std::size_t sent = 0; sent < count;) {
    const int now = sendmmsg(fd_, datagrams_.data() + sent, static_cast<unsigned>(count - sent), 0);
    if (now > 0) {
      sent += static_cast<std::size_t>(now);
    } else if (now == 0 || errno != EINTR) {
      return -1;
    }
  }
  return 0;
}

}  // namespace aula::lcmbus

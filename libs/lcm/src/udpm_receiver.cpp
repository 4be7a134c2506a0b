#include "aula/lcm/udpm_receiver.hpp"

#include "aula/lcm/bus.hpp"

#include <aula/config/config.hpp>

#include <arpa/inet.h>
#include <linux/filter.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <time.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <algorithm>

namespace aula::lcmbus {
namespace {

constexpr const char* kUdpmScheme = "udpm://";
constexpr uint32_t kShortMagic = 0x4c433032;  // "LC02"
constexpr uint32_t kLongMagic = 0x4c433033;   // "LC03"
constexpr std::size_t kShortHeader = 8;       // magic, sequence number
constexpr std::size_t kLongHeader = 20;       // magic, sequence, size, offset, fragment no, count
constexpr std::size_t kMaxChannel = 63;       // LCM_MAX_CHANNEL_NAME_LENGTH
constexpr uint32_t kMaxMessage = 1u << 28;    // LCM_MAX_MESSAGE_SIZE
constexpr int kMinReceiveBuffer = 2 * 1024 * 1024;

uint32_t be32(const uint8_t* at) {
  return (uint32_t{at[0]} << 24) | (uint32_t{at[1]} << 16) | (uint32_t{at[2]} << 8) | uint32_t{at[3]};
}
uint16_t be16(const uint8_t* at) { return static_cast<uint16_t>((at[0] << 8) | at[1]); }

// The channel's length when a NUL ends it within `size` bytes and it is a legal length, else -1.
long channelLength(const uint8_t* at, std::size_t size) {
  const void* nul = std::memchr(at, '\0', std::min(size, kMaxChannel + 1));
  if (nul == nullptr) return -1;
  const long length = static_cast<const uint8_t*>(nul) - at;
  return length == 0 ? -1 : length;
}

void attachFilter(int fd, const std::vector<SocketFilterInstruction>& program, const std::string& what) {
  static_assert(sizeof(SocketFilterInstruction) == sizeof(sock_filter), "the kernel's sock_filter layout");
  std::vector<sock_filter> kernel_program(program.size());
  for (std::size_t i = 0; i < program.size(); ++i) {
    kernel_program[i] = sock_filter{program[i].code, program[i].jump_if_true, program[i].jump_if_false, program[i].value};
  }
  sock_fprog filter{static_cast<unsigned short>(kernel_program.size()), kernel_program.data()};
  if (setsockopt(fd, SOL_SOCKET, SO_ATTACH_FILTER, &filter, sizeof filter) != 0) {
    throw BusError("cannot set the socket filter for " + what + ": " + std::strerror(errno));
  }
}

}  // namespace

bool isUdpmUrl(const std::string& url) { return url.rfind(kUdpmScheme, 0) == 0; }

int64_t wallUtime() {
  timespec now{};
  clock_gettime(CLOCK_REALTIME, &now);
  return int64_t{now.tv_sec} * 1000000 + now.tv_nsec / 1000;
}

UdpmUrl parseUdpmUrl(const std::string& url) {
  UdpmUrl parsed;
  std::string rest = url.substr(std::strlen(kUdpmScheme));
  const std::size_t query = rest.find('?');
  const std::string options = query == std::string::npos ? "" : rest.substr(query + 1);
  rest = rest.substr(0, query);
  auto number = [&url](const std::string& key, const std::string& text, long low, long high) {
    char* end = nullptr;
    const long value = std::strtol(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0' || value < low || value > high) {
      throw config::ConfigError("LCM URL '" + url + "': " + key + " '" + text + "' is not a number from " +
                                std::to_string(low) + " to " + std::to_string(high));
    }
    return static_cast<int>(value);
  };
  if (const auto colon = rest.find(':'); colon != std::string::npos) {
    parsed.port = number("port", rest.substr(colon + 1), 1, 65535);
    rest = rest.substr(0, colon);
  }
  if (!rest.empty()) parsed.group = rest;
  in_addr address{};
  if (inet_pton(AF_INET, parsed.group.c_str(), &address) != 1 || (ntohl(address.s_addr) >> 28) != 0xE) {
    throw config::ConfigError("LCM URL '" + url + "': '" + parsed.group +
                              "' is not an IPv4 multicast group (224.0.0.0 to 239.255.255.255)");
  }
  for (std::size_t at = 0; at < options.size();) {
    const std::size_t end = std::min(options.find('&', at), options.size());
    const std::string option = options.substr(at, end - at);
    if (option.rfind("recv_buf_size=", 0) == 0) {
      parsed.recv_buf_size = number("recv_buf_size", option.substr(14), 0, 1 << 30);
    } else if (option.rfind("ttl=", 0) == 0) {
      parsed.ttl = number("ttl", option.substr(4), 0, 255);
    }
    at = end + 1;
  }
  return parsed;
}

std::optional<LcmMessage> LcmDatagramAssembler::add(const uint8_t* datagram, std::size_t size, uint64_t sender) {
  if (size >= kShortHeader && be32(datagram) == kShortMagic) {
    const long channel = channelLength(datagram + kShortHeader, size - kShortHeader);
    if (channel < 0) {
      ++malformed_;
      return std::nullopt;
    }
    const std::size_t payload = kShortHeader + static_cast<std::size_t>(channel) + 1;
    return LcmMessage{reinterpret_cast<const char*>(datagram + kShortHeader), datagram + payload,
                      static_cast<uint32_t>(size - payload)};
  }
  if (size >= kLongHeader && be32(datagram) == kLongMagic) return addFragment(datagram, size, sender);
  ++malformed_;
  return std::nullopt;
}

std::optional<LcmMessage> LcmDatagramAssembler::addFragment(const uint8_t* datagram, std::size_t size, uint64_t sender) {
  const uint32_t sequence = be32(datagram + 4);
  const uint32_t message_size = be32(datagram + 8);
  const uint32_t offset = be32(datagram + 12);
  const uint16_t fragment = be16(datagram + 16);
  const uint16_t fragments = be16(datagram + 18);
  const uint8_t* data = datagram + kLongHeader;
  std::size_t data_size = size - kLongHeader;
  auto partial = partial_.find(sender);
  if (partial != partial_.end() && (partial->second.sequence != sequence || partial->second.data.size() != message_size)) {
    partial_.erase(partial);  // a newer message from that sender: the unfinished one is lost
    partial = partial_.end();
  }
  if (partial == partial_.end()) {
    if (fragment != 0) return std::nullopt;  // its first fragment was lost
    const long channel = channelLength(data, data_size);
    if (channel < 0 || message_size > kMaxMessage || fragments == 0) {
      ++malformed_;
      return std::nullopt;
    }
    Partial started;
    started.sequence = sequence;
    started.channel.assign(reinterpret_cast<const char*>(data), static_cast<std::size_t>(channel));
    started.data.resize(message_size);
    started.fragments_left = fragments;
    partial = partial_.emplace(sender, std::move(started)).first;
    data += channel + 1;
    data_size -= static_cast<std::size_t>(channel) + 1;
  }
  Partial& message = partial->second;
  if (offset > message.data.size() || data_size > message.data.size() - offset) {
    ++malformed_;
    partial_.erase(partial);
    return std::nullopt;
  }
  std::memcpy(message.data.data() + offset, data, data_size);
  if (--message.fragments_left > 0) return std::nullopt;
  completed_ = std::move(message);
  partial_.erase(partial);
  return LcmMessage{completed_.channel.c_str(), completed_.data.data(), static_cast<uint32_t>(completed_.data.size())};
}

namespace {

// A socket on the URL's group and port, bound and joined as LCM binds and joins its own
// (SO_REUSEADDR, so every process of the run binds the port), with `filter` attached before the
// bind: nothing unwanted is ever queued. Throws BusError.
int openGroupSocket(const UdpmUrl& url, const std::vector<SocketFilterInstruction>& filter) {
  const std::string where = "LCM bus udpm://" + url.group + ":" + std::to_string(url.port);
  const int fd = socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
  if (fd < 0) throw BusError(where + ": cannot open a UDP socket: " + std::strerror(errno));
  try {
    const int yes = 1;
    if (setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes) != 0) {
      throw BusError(where + ": SO_REUSEADDR: " + std::strerror(errno));
    }
    // LCM's receive thread drains its socket as datagrams come; this socket is read only when
    // its process handles messages, so the kernel's queue must hold a burst: at least 2 MB
    // (a long message's fragments, a referee's second of poses). Capped by the kernel at
    // net.core.rmem_max, as for LCM's own socket, unless the process may force it (root).
    const int buffer_bytes = std::max(url.recv_buf_size, kMinReceiveBuffer);
    if (setsockopt(fd, SOL_SOCKET, SO_RCVBUFFORCE, &buffer_bytes, sizeof buffer_bytes) != 0) {
      setsockopt(fd, SOL_SOCKET, SO_RCVBUF, &buffer_bytes, sizeof buffer_bytes);
    }
    attachFilter(fd, filter, where);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_ANY);
    address.sin_port = htons(static_cast<uint16_t>(url.port));
    if (bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0) {
      throw BusError(where + ": cannot bind the port: " + std::strerror(errno));
    }
    ip_mreq membership{};
    inet_pton(AF_INET, url.group.c_str(), &membership.imr_multiaddr);
    membership.imr_interface.s_addr = htonl(INADDR_ANY);
    if (setsockopt(fd, IPPROTO_IP, IP_ADD_MEMBERSHIP, &membership, sizeof membership) != 0) {
      throw BusError(where + ": cannot join the multicast group: " + std::strerror(errno));
    }
  } catch (...) {
    close(fd);
    throw;
  }
  return fd;
}

// LCM's sequence numbers count up per sender and wrap around.
bool before(uint32_t sequence, uint32_t other) { return static_cast<int32_t>(sequence - other) < 0; }

uint64_t senderOf(const sockaddr_in& from) {
  return (uint64_t{ntohl(from.sin_addr.s_addr)} << 16) | ntohs(from.sin_port);
}

// recvmmsg's result: how many, 0 when nothing waits, -1 when a signal interrupted it; throws on
// anything else.
int checked(int read) {
  if (read >= 0) return read;
  if (errno == EINTR) return -1;
  if (errno == EAGAIN || errno == EWOULDBLOCK) return 0;
  throw BusError(std::string("LCM bus receive: ") + std::strerror(errno));
}


// How long a doorbell's datagram is waited for on the data socket before it counts as lost
// there (its queue overflowed): the two copies are queued microseconds apart.
constexpr int kDoorbellGraceMs = 50;

}  // namespace

UdpmReceiver::UdpmReceiver(const UdpmUrl& url, const std::set<std::string>& initial_channels)
    : url_(url), batch_(kBatch) {
  for (Datagram& d : batch_) d.bytes.resize(65536);  // the largest UDP datagram
  fd_ = openGroupSocket(url, channelFilter(initial_channels));
}

UdpmReceiver::~UdpmReceiver() {
  if (fd_ >= 0) close(fd_);
  wakeOnAll();
}

void UdpmReceiver::receiveOnly(const std::set<std::string>& channels) {
  attachFilter(fd_, channelFilter(channels), std::to_string(channels.size()) + " channels");
}

void UdpmReceiver::receiveAll() {
  const int unused = 0;  // the kernel wants an int, and ignores it
  if (setsockopt(fd_, SOL_SOCKET, SO_DETACH_FILTER, &unused, sizeof unused) != 0) {
    throw BusError(std::string("cannot lift the socket filter: ") + std::strerror(errno));
  }
}

void UdpmReceiver::wakeOnly(const std::vector<SocketFilterInstruction>& doorbell_filter) {
  if (doorbell_fd_ >= 0) {
    attachFilter(doorbell_fd_, doorbell_filter, "the doorbell");
  } else {
    doorbell_fd_ = openGroupSocket(url_, doorbell_filter);
  }
}

void UdpmReceiver::wakeOnAll() {
  if (doorbell_fd_ >= 0) close(doorbell_fd_);
  doorbell_fd_ = -1;
  rung_.clear();
  last_read_.clear();
}

std::optional<LcmMessage> UdpmReceiver::next(int timeout_ms) {
  using Clock = std::chrono::steady_clock;
  const auto deadline = Clock::now() + std::chrono::milliseconds(std::max(timeout_ms, 0));
  for (;;) {
    while (next_datagram_ < datagrams_read_) {
      const Datagram& d = batch_[next_datagram_++];
      const uint64_t sender = senderOf(d.from);
      if (doorbell_fd_ >= 0 && d.size >= 8) {
        const uint32_t sequence = be32(d.bytes.data() + 4);
        last_read_[sender] = sequence;
        const auto rang = rung_.find(sender);
        if (rang != rung_.end() && !before(sequence, rang->second)) rung_.erase(rang);
      }
      if (auto message = assembler_.add(d.bytes.data(), d.size, sender)) {
        received_utime_ = wallUtime();
        return message;
      }  // else a fragment, or something malformed: read on
    }
    if (doorbell_fd_ >= 0 && doorbell_may_hold_more_) readDoorbell();
    if (!rung_.empty()) {
      // The doorbell rang for a datagram the data socket has not given yet: it is on its way.
      const int read = readBatch(MSG_DONTWAIT);
      if (read > 0) continue;
      if (read < 0) return std::nullopt;
      pollfd data{fd_, POLLIN, 0};
      if (poll(&data, 1, kDoorbellGraceMs) == 0) rung_.clear();  // lost on the data socket: go on
      continue;
    }
    if (timeout_ms < 0 && doorbell_fd_ < 0) {
      // Wait for the first datagram and take every one waiting, in one system call.
      if (readBatch(MSG_WAITFORONE) < 0) return std::nullopt;
      continue;
    }
    if (timeout_ms == 0 && data_may_hold_more_) {
      const int read = readBatch(MSG_DONTWAIT);
      if (read > 0) continue;
      if (read < 0) return std::nullopt;
    }
    // Nothing more is waiting (as far as the last reads tell): the next look reads again.
    data_may_hold_more_ = doorbell_may_hold_more_ = true;
    if (timeout_ms == 0) return std::nullopt;
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    if (timeout_ms > 0 && left <= 0) return std::nullopt;
    pollfd readable{fd(), POLLIN, 0};
    if (poll(&readable, 1, timeout_ms < 0 ? -1 : static_cast<int>(left)) <= 0) return std::nullopt;
    if (doorbell_fd_ >= 0) continue;  // the doorbell is read first, then the data up to it
    if (readBatch(MSG_DONTWAIT) < 0) return std::nullopt;
  }
}

void UdpmReceiver::readDoorbell() {
  // Only each datagram's sender and LCM header (magic, sequence number) matter: the rest of it
  // is cut off (and dropped by the kernel).
  uint8_t headers_read[kBatch][8]{};
  sockaddr_in from[kBatch]{};
  mmsghdr headers[kBatch]{};
  iovec buffers[kBatch]{};
  for (std::size_t i = 0; i < kBatch; ++i) {
    buffers[i] = iovec{headers_read[i], sizeof headers_read[i]};
    headers[i].msg_hdr.msg_iov = &buffers[i];
    headers[i].msg_hdr.msg_iovlen = 1;
    headers[i].msg_hdr.msg_name = &from[i];
    headers[i].msg_hdr.msg_namelen = sizeof from[i];
  }
  const int read = checked(recvmmsg(doorbell_fd_, headers, kBatch, MSG_DONTWAIT, nullptr));
  doorbell_may_hold_more_ = read == static_cast<int>(kBatch);
  for (int i = 0; i < read; ++i) {
    if (headers[i].msg_len < 8) continue;
    const uint64_t sender = senderOf(from[i]);
    const uint32_t sequence = be32(headers_read[i] + 4);
    const auto read_already = last_read_.find(sender);
    if (read_already == last_read_.end() || before(read_already->second, sequence)) rung_[sender] = sequence;
  }
}

int UdpmReceiver::readBatch(int flags) {
  mmsghdr headers[kBatch]{};
  iovec buffers[kBatch]{};
  for (std::size_t i = 0; i < kBatch; ++i) {
    buffers[i] = iovec{batch_[i].bytes.data(), batch_[i].bytes.size()};
    headers[i].msg_hdr.msg_iov = &buffers[i];
    headers[i].msg_hdr.msg_iovlen = 1;
    headers[i].msg_hdr.msg_name = &batch_[i].from;
    headers[i].msg_hdr.msg_namelen = sizeof batch_[i].from;
  }
  const int read = checked(recvmmsg(fd_, headers, kBatch, flags, nullptr));
  data_may_hold_more_ = read == static_cast<int>(kBatch);
  datagrams_read_ = std::max(read, 0);
  datagrams_ += datagrams_read_;
  next_datagram_ = 0;
  for (int i = 0; i < read; ++i) batch_[i].size = headers[i].msg_len;
  return read;
}

}  // namespace aula::lcmbus

#pragma once
// Sending LCM's short messages on a udpm:// URL, a burst in one system call.
//
// LCM's publish sends each message with its own sendmsg on an unconnected socket (a route looked
// up every time). A process in lockstep sends a period's messages together (the simulator: its
// sensor messages and the tick; a client: its commands and its ack); one sendmmsg puts them all on
// the group at once, so a process that sleeps until they come is woken once and runs after the
// sender has finished, instead of being switched in and out at each message. The datagrams are
// LCM's own short messages ("LC02": magic, sequence number, channel, NUL, payload), byte for byte
// what LCM sends, on the URL's group, port and TTL, looped back to this machine as LCM's are: every
// stock LCM tool reads them. A message too long for one datagram of LCM's is not sent here: the
// Bus gives it to LCM's own publish, which splits it into LCM's fragments.

#include <aula/lcm/udpm_receiver.hpp>

#include <sys/socket.h>
#include <sys/uio.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace aula::lcmbus {

class UdpmSender {
 public:
  // A UDP socket connected to the URL's group and port, with its TTL and multicast loopback on.
  // Throws BusError.
  explicit UdpmSender(const UdpmUrl& url);
  ~UdpmSender();
  UdpmSender(const UdpmSender&) = delete;
  UdpmSender& operator=(const UdpmSender&) = delete;

  // True when LCM sends a message of `size` bytes on `channel` as one short datagram (its channel,
  // NUL and payload within LCM 1.3's 1400 bytes: every LCM version sends those whole).
  static bool fitsOneDatagram(const std::string& channel, std::size_t size);

  struct Message {
    const std::string* channel;
    const uint8_t* data;
    std::size_t size;
  };
  // Sends each message (each fitsOneDatagram) as one datagram, in order, in as few sendmmsg calls
  // as the kernel takes them in: 0, or -1 when the socket refuses one (the rest are not sent).
  int send(const Message* messages, std::size_t count);

 private:
  int fd_ = -1;
  uint32_t sequence_ = 0;  // LCM's per-sender message counter
  std::vector<uint8_t> headers_;  // 8 bytes a datagram: magic, sequence number (big-endian)
  std::vector<iovec> pieces_;     // 3 a datagram: header, channel with its NUL, payload
  std::vector<mmsghdr> datagrams_;
};

}  // namespace aula::lcmbus

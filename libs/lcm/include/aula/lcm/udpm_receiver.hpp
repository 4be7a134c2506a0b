#pragma once
// Receiving LCM's UDP multicast wire format on the calling thread.
//
// LCM 1.3.1 (and LCM up to 1.5) receives a udpm:// URL on a thread of its own: every message
// costs that thread a select and a recvmsg, a write to a notify pipe, and the application a poll,
// a read of the pipe and two thread wake-ups. In a lockstep run those wake-ups sit on the
// critical path of every control period. UdpmReceiver reads the same multicast socket (bound and
// joined as LCM binds and joins it) on the thread that handles the messages: every waiting
// datagram in one recvmmsg, one wake-up. What it yields is handed to LCM's own dispatch
// (lcmbus::Bus), so the subscriptions, their decoding and their queues stay LCM's.

#include <netinet/in.h>

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace aula::lcmbus {

struct SocketFilterInstruction;  // bus.hpp

// A udpm:// URL: udpm://GROUP:PORT?ttl=N&recv_buf_size=BYTES (LCM's defaults for what it omits).
struct UdpmUrl {
  std::string group = "239.255.76.67";
  int port = 7667;
  int recv_buf_size = 0;  // bytes; 0 = the kernel's default
  int ttl = 0;            // LCM's default: the datagrams never leave the machine
};
bool isUdpmUrl(const std::string& url);
// Wall time now, in microseconds since the epoch: LCM's recv_utime.
int64_t wallUtime();
// Throws config::ConfigError naming the URL and what is wrong with it.
UdpmUrl parseUdpmUrl(const std::string& url);

// One message out of LCM's datagrams: valid until the next datagram is added.
struct LcmMessage {
  const char* channel = nullptr;  // NUL-terminated
  const uint8_t* data = nullptr;
  uint32_t size = 0;
};

// Rebuilds messages from LCM datagrams: a short message ("LC02": magic, sequence number, channel,
// NUL, payload) is one datagram; a long one ("LC03") comes in fragments, reassembled per sender
// (LCM sends a message's fragments back to back; a new message from a sender drops the unfinished
// one, as LCM's receiver does). Anything else is counted and ignored.
class LcmDatagramAssembler {
 public:
  // `sender`: the datagram's source (address and port), which keys its fragments.
  std::optional<LcmMessage> add(const uint8_t* datagram, std::size_t size, uint64_t sender);
  long long malformed() const { return malformed_; }

 private:
  struct Partial {
    uint32_t sequence = 0;
    std::string channel;
    std::vector<uint8_t> data;
    uint16_t fragments_left = 0;
  };
  std::optional<LcmMessage> addFragment(const uint8_t* datagram, std::size_t size, uint64_t sender);

  std::map<uint64_t, Partial> partial_;  // by sender
  Partial completed_;                    // the last long message completed (what add returned)
  long long malformed_ = 0;
};

// The multicast socket of a udpm:// URL, read on the caller's thread.
class UdpmReceiver {
 public:
  // Opens, binds and joins as LCM does (SO_REUSEADDR, so every process of the run binds the
  // port), with `initial_channels` let through its kernel socket filter. Throws BusError.
  UdpmReceiver(const UdpmUrl& url, const std::set<std::string>& initial_channels);
  ~UdpmReceiver();
  UdpmReceiver(const UdpmReceiver&) = delete;
  UdpmReceiver& operator=(const UdpmReceiver&) = delete;

  // Readable when a message that should wake the process waits (poll, QSocketNotifier): on the
  // doorbell socket once there is one (wakeOnly), else on the data socket. Datagrams are read in
  // batches: once it fires, take messages with next(0) until there is none.
  int fd() const { return doorbell_fd_ >= 0 ? doorbell_fd_ : fd_; }
  // The kernel socket filter (channelFilter): only these channels' short messages are queued.
  void receiveOnly(const std::set<std::string>& channels);
  // No filter: every channel (a subscription by pattern).
  void receiveAll();
  // What wakes the process: a second socket on the same group and port (the doorbell) with this
  // filter, which must pass a subset of what the data socket passes. The data socket is then
  // read only when the doorbell rings (or a wait times out): what the doorbell does not pass
  // waits there, in order, without waking anyone. The doorbell's datagrams are only a signal:
  // every message is read from the data socket, at least up to each one that rang (matched by
  // sender and LCM sequence number, so a doorbell that is a microsecond ahead is waited for).
  void wakeOnly(const std::vector<SocketFilterInstruction>& doorbell_filter);
  // Every datagram wakes the process again (no doorbell).
  void wakeOnAll();

  // The next complete message: first from the batch already read, else from what the kernel
  // holds (up to kBatch datagrams in one recvmmsg). `timeout_ms` < 0 waits for one, 0 takes only
  // what is queued, > 0 waits that long at most (a wait ends when fd() becomes readable). Nothing
  // when none came (or a signal interrupted the wait). Calls with 0 until it gives nothing read
  // each socket once more only when its last read filled a whole batch: the end of a burst costs
  // no empty read.
  std::optional<LcmMessage> next(int timeout_ms);
  // Wall time (microseconds since the epoch) at which the last message's last datagram was read:
  // LCM's recv_utime.
  int64_t receivedUtime() const { return received_utime_; }
  // Datagrams read so far (each short message is one; a long one, one per fragment).
  long long datagrams() const { return datagrams_; }

 private:
  static constexpr std::size_t kBatch = 16;
  struct Datagram {
    std::vector<uint8_t> bytes;
    sockaddr_in from{};
    std::size_t size = 0;
  };
  int readBatch(int flags);  // recvmmsg into batch_: how many, 0 if none, -1 if a signal came; throws on errors
  void readDoorbell();       // what rang: into rung_

  UdpmUrl url_;
  int fd_ = -1;
  int doorbell_fd_ = -1;
  // Per sender (address and port), the LCM sequence number of the last datagram that rang the
  // doorbell and has not been read from the data socket yet.
  std::map<uint64_t, uint32_t> rung_;
  std::map<uint64_t, uint32_t> last_read_;  // per sender, the last sequence number read from the data socket
  bool data_may_hold_more_ = true;      // its last read filled the batch (or a pass begins)
  bool doorbell_may_hold_more_ = true;
  std::vector<Datagram> batch_;
  int datagrams_read_ = 0;  // in batch_
  int next_datagram_ = 0;   // the first not yet taken
  LcmDatagramAssembler assembler_;
  int64_t received_utime_ = 0;
  long long datagrams_ = 0;
};

}  // namespace aula::lcmbus

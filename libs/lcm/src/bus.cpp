#include "aula/lcm/bus.hpp"

#include "aula/lcm/udpm_receiver.hpp"
#include "aula/lcm/udpm_sender.hpp"

#include <aula/config/config.hpp>

#include <lcm/lcm.h>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <linux/filter.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <vector>

// LCM's provider interface (lcm_internal.h, not installed; exported by liblcm from 1.3 to 1.5):
// how a provider hands a received message to the subscriptions.
extern "C" {
int lcm_try_enqueue_message(lcm_t* lcm, const char* channel);
int lcm_dispatch_handlers(lcm_t* lcm, lcm_recv_buf_t* buffer, const char* channel);
}

namespace aula::lcmbus {
namespace {

constexpr const char* kSelfTestChannel = "LCM_SELF_TEST";

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
  if (!isUdpmUrl(url)) return url;
  const size_t query = url.find('?');
  const std::string head = url.substr(0, query);
  const size_t colon = head.rfind(':');
  if (colon == std::string::npos || colon < std::strlen("udpm://") || head.substr(colon + 1) != "0") return url;
  return head.substr(0, colon + 1) + std::to_string(freeUdpPort()) + (query == std::string::npos ? "" : url.substr(query));
}

std::vector<SocketFilterInstruction> channelFilter(const std::set<std::string>& channels, const std::optional<TickGate>& gate) {
  // Offsets from the start of the UDP header, where a UDP socket's filter starts reading.
  constexpr uint32_t kMagicOffset = 8;         // after the 8-byte UDP header
  constexpr uint32_t kChannelOffset = 8 + 8;   // after LCM's short header: magic, sequence number
  constexpr uint32_t kShortMagic = 0x4c433032;  // "LC02"
  constexpr uint32_t kTypeHashSize = 8;         // before every LCM message's first field
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
    std::vector<std::size_t> name_compares;
    for (std::size_t at = 0; at < bytes.size();) {
      const std::size_t width = bytes.size() - at >= 4 ? 4 : bytes.size() - at >= 2 ? 2 : 1;
      uint32_t value = 0;
      for (std::size_t i = 0; i < width; ++i) value = (value << 8) | static_cast<unsigned char>(bytes[at + i]);
      const uint16_t size = width == 4 ? BPF_W : width == 2 ? BPF_H : BPF_B;
      block.push_back(op(BPF_LD | size | BPF_ABS, kChannelOffset + static_cast<uint32_t>(at)));
      name_compares.push_back(block.size());
      block.push_back(op(BPF_JMP | BPF_JEQ | BPF_K, value));
      at += width;
    }
    if (gate && gate->channel == channel) {
      // The message's first field, a big-endian int64 (sim_clock_t's utime), compared as two
      // unsigned words: high above the gate's, or equal and low at or above.
      const uint32_t high_offset = kChannelOffset + static_cast<uint32_t>(bytes.size()) + kTypeHashSize;
      const auto from = static_cast<uint64_t>(std::max<int64_t>(gate->from_utime_us, 0));
      const auto high = static_cast<uint32_t>(from >> 32), low = static_cast<uint32_t>(from);
      block.push_back(op(BPF_LD | BPF_W | BPF_ABS, high_offset));
      block.push_back(op(BPF_JMP | BPF_JGT | BPF_K, high, 3, 0));  // -> accept
      block.push_back(op(BPF_JMP | BPF_JEQ | BPF_K, high, 0, 3));  // -> drop
      block.push_back(op(BPF_LD | BPF_W | BPF_ABS, high_offset + 4));
      block.push_back(op(BPF_JMP | BPF_JGE | BPF_K, low, 0, 1));   // -> accept, else drop
      block.push_back(op(BPF_RET | BPF_K, kAccept));
      block.push_back(op(BPF_RET | BPF_K, kDrop));
    } else {
      block.push_back(op(BPF_RET | BPF_K, kAccept));
    }
    if (block.size() > 255) throw BusError("channel name too long for the socket filter: " + channel);
    for (const std::size_t i : name_compares) block[i].jump_if_false = static_cast<uint8_t>(block.size() - i - 1);
    program.insert(program.end(), block.begin(), block.end());
  }
  program.push_back(op(BPF_RET | BPF_K, kDrop));
  return program;
}

Bus::Bus(std::string url) : url_(std::move(url)) {
  const char* stats = std::getenv("AULA_BUS_STATS");  // bench/exercise_overhead.sh
  print_stats_ = stats != nullptr && *stats != '\0';
  const bool udpm = isUdpmUrl(url_);
  const UdpmUrl address = udpm ? parseUdpmUrl(url_) : UdpmUrl{};
  lcm_ = std::make_unique<lcm::LCM>(url_);
  if (!lcm_->good()) throw BusError("cannot open the LCM bus '" + url_ + "'");
  if (!udpm) return;
  dispatcher_ = std::make_unique<lcm::LCM>("memq://");
  if (!dispatcher_->good()) throw BusError("cannot open the LCM bus '" + url_ + "': no in-process LCM");
  receiver_ = std::make_unique<UdpmReceiver>(address, std::set<std::string>{kSelfTestChannel});
  sender_ = std::make_unique<UdpmSender>(address);
  selfTest();
  receiver_->receiveOnly(channels_);
  while (receiver_->next(0)) {
  }  // other processes' self tests, queued before the filter closed
}

Bus::~Bus() {
  if (print_stats_) {
    // One write, so that the three processes' lines do not interleave on a shared terminal.
    const std::string received =
        receiver_ ? " of " + std::to_string(receiver_->datagrams()) + " datagrams received" : std::string();
    const std::string line = std::string("aula-bus: ") + program_invocation_short_name + " handled " +
                             std::to_string(handled_) + " messages" + received + " on " + url_ + "\n";
    std::cerr.write(line.data(), static_cast<std::streamsize>(line.size())).flush();
  }
}

void Bus::selfTest() {
  // As LCM's own udpm self test: a message of ours must come back through the group. Without a
  // multicast route the publish itself fails.
  const std::string nonce = std::to_string(getpid()) + ":" + std::to_string(reinterpret_cast<std::uintptr_t>(this));
  const std::string no_route = "cannot open the LCM bus '" + url_ +
                               "': UDP multicast needs a multicast route. On a machine without a default route, run as "
                               "root: 'ip link set lo multicast on; ip route add 224.0.0.0/4 dev lo'";
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(2);
  while (std::chrono::steady_clock::now() < deadline) {
    if (send(kSelfTestChannel, nonce.data(), static_cast<unsigned int>(nonce.size())) != 0) throw BusError(no_route);
    const auto resend = std::chrono::steady_clock::now() + std::chrono::milliseconds(100);
    while (std::chrono::steady_clock::now() < resend) {
      const auto message = receiver_->next(20);
      if (message && std::string(reinterpret_cast<const char*>(message->data), message->size) == nonce) return;
    }
  }
  throw BusError(no_route + " (LCM's self test: nothing came back in 2 s)");
}

std::vector<uint8_t>& Bus::holdSlot(const std::string& channel) {
  if (held_count_ == held_.size()) held_.emplace_back();
  auto& slot = held_[held_count_++];
  slot.first = channel;
  return slot.second;
}

bool Bus::sendsItself(const std::string& channel, std::size_t size) const {
  return sender_ && UdpmSender::fitsOneDatagram(channel, size);
}

int Bus::send(const std::string& channel, const void* data, unsigned int size) {
  if (!sendsItself(channel, size)) return lcm_->publish(channel, data, size);
  const UdpmSender::Message message{&channel, static_cast<const uint8_t*>(data), size};
  return sender_->send(&message, 1);
}

int Bus::flush() {
  holding_ = false;
  int status = 0;
  burst_.clear();  // short messages in a row: one system call
  auto sendBurst = [&] {
    if (!burst_.empty() && sender_->send(burst_.data(), burst_.size()) != 0 && status == 0) status = -1;
    burst_.clear();
  };
  for (std::size_t i = 0; i < held_count_; ++i) {
    const auto& [channel, bytes] = held_[i];
    if (sendsItself(channel, bytes.size())) {
      burst_.push_back({&channel, bytes.data(), bytes.size()});
      continue;
    }
    sendBurst();  // what came before it goes first
    const int sent = send(channel, bytes.data(), static_cast<unsigned int>(bytes.size()));
    if (status == 0) status = sent;
  }
  sendBurst();
  held_count_ = 0;
  return status;
}

int Bus::getFileno() { return receiver_ ? receiver_->fd() : lcm_->getFileno(); }

void Bus::inject(const std::string& channel, const void* data, unsigned int size) {
  dispatch(LcmMessage{channel.c_str(), static_cast<const uint8_t*>(data), size}, wallUtime());
}

void Bus::dispatch(const LcmMessage& message, int64_t received_utime) {
  lcm_t* lcm = subscriptions().getUnderlyingLCM();
  lcm_recv_buf_t buffer{const_cast<uint8_t*>(message.data), message.size, received_utime, lcm};
  // What LCM's udpm provider does with a message: count it into each subscription's queue, then
  // call the handlers.
  if (lcm_try_enqueue_message(lcm, message.channel) != 0) lcm_dispatch_handlers(lcm, &buffer, message.channel);
  ++handled_;
}

int Bus::handle() {
  if (!receiver_) {
    const int status = lcm_->handle();
    if (status == 0) ++handled_;
    return status;
  }
  const auto message = receiver_->next(-1);
  if (!message) return -1;
  dispatch(*message, receiver_->receivedUtime());
  return 0;
}

int Bus::handleTimeout(int timeout_ms) {
  if (!receiver_) {
    const int status = lcm_->handleTimeout(timeout_ms);
    if (status > 0) ++handled_;
    return status;
  }
  const auto message = receiver_->next(timeout_ms);
  if (!message) return 0;
  dispatch(*message, receiver_->receivedUtime());
  return 1;
}

void Bus::unsubscribe(lcm::Subscription* subscription) {
  subscriptions().unsubscribe(subscription);
  const auto it = subscribed_.find(subscription);
  if (it == subscribed_.end()) return;
  const std::string channel = it->second;
  subscribed_.erase(it);
  if (!receiver_ || receive_all_ || listened_.count(channel) != 0) return;
  for (const auto& [other, other_channel] : subscribed_) {
    if (other_channel == channel) return;
  }
  deferred_.erase(channel);
  if (channels_.erase(channel) != 0) updateFilters();
}

void Bus::listen(const std::string& channel) {
  listened_.insert(channel);
  pass(channel);
}

void Bus::pass(const std::string& channel) {
  if (!receiver_ || receive_all_) return;
  if (isPattern(channel)) {
    receive_all_ = true;  // a recorder: every channel wakes it, nothing is deferred
    receiver_->receiveAll();
    receiver_->wakeOnAll();
    return;
  }
  if (channels_.insert(channel).second) updateFilters();
}

void Bus::deferWakeUps(const std::string& channel) {
  if (!receiver_ || receive_all_ || isPattern(channel)) return;
  channels_.insert(channel);
  if (deferred_.insert(channel).second) updateFilters();
}

void Bus::wakeOnlyFor(const std::set<std::string>& waking) {
  if (!receiver_ || receive_all_) return;
  gate_ticks_ = false;
  wake_for_ticks_from_us_ = 0;
  for (const std::string& channel : channels_) {
    if (waking.count(channel) == 0) deferred_.insert(channel);
  }
  updateFilters();
}

void Bus::wakeForTicksFrom(int64_t utime_us) {
  if (utime_us == wake_for_ticks_from_us_ || !gate_ticks_) return;
  wake_for_ticks_from_us_ = utime_us;
  if (receiver_ && !receive_all_) updateDoorbell();
}

void Bus::updateFilters() {
  receiver_->receiveOnly(channels_);
  updateDoorbell();
}

void Bus::updateDoorbell() {
  if (deferred_.empty()) return;
  std::set<std::string> waking;
  for (const std::string& channel : channels_) {
    if (deferred_.count(channel) == 0) waking.insert(channel);
  }
  receiver_->wakeOnly(channelFilter(waking, TickGate{kClockChannel, wake_for_ticks_from_us_}));
}

std::unique_ptr<Bus> openBus(const std::string& url) { return std::make_unique<Bus>(url); }

}  // namespace aula::lcmbus

#pragma once
// The key of one graded run, and what it authenticates.
//
// `aula run --headless` makes a random key per run and hands it to the simulator and the
// referee only, each through a pipe it inherits (`--key-fd=N`): never the command line or the
// environment, which every process of the user can read, and never to the component, which
// runs the student's code. The simulator stamps what the referee grades (the robot's pose and
// bumper, the clock) with HMAC-SHA256(key, the message encoded with its `auth` zeroed, then the
// channel name), and a per-channel `auth_seq`; it obeys SIM_CONTROL only when stamped the same
// way. The messages stay readable by every LCM tool: authentication adds to them, hides nothing.
//
// A message type takes part by declaring `int64_t auth_seq; byte auth[32];` (lcmtypes/).

#include <openssl/crypto.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace aula::auth {

constexpr size_t kKeyBytes = 32;
constexpr size_t kTagBytes = 32;  // HMAC-SHA256
using Key = std::array<uint8_t, kKeyBytes>;
using Tag = std::array<uint8_t, kTagBytes>;

// 32 bytes from the kernel's random source (getrandom). Throws std::runtime_error.
Key randomKey();
// A pipe's read end (close-on-exec) that holds `key` and then end-of-file: hand it to one child
// (ChildProcess's passed descriptors). Throws std::runtime_error.
int keyPipe(const Key& key);
// Reads exactly one key from `fd` and closes it. Throws std::runtime_error naming `what` when the
// descriptor is not open or holds anything but 32 bytes.
Key readKey(int fd, const std::string& what);

// HMAC-SHA256(key, bytes || channel).
Tag tagOf(const Key& key, const std::vector<uint8_t>& bytes, const std::string& channel);

// The message's encoding with its tag zeroed: what the tag covers.
template <class Message>
std::vector<uint8_t> signedBytes(Message msg) {
  std::fill(std::begin(msg.auth), std::end(msg.auth), uint8_t{0});
  std::vector<uint8_t> bytes(static_cast<size_t>(msg.getEncodedSize()));
  msg.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

template <class Message>
void sign(const Key& key, const std::string& channel, Message& msg) {
  const Tag tag = tagOf(key, signedBytes(msg), channel);
  std::copy(tag.begin(), tag.end(), std::begin(msg.auth));
}

// True when `msg` carries the tag `key` gives it on `channel` (compared in constant time).
template <class Message>
bool verify(const Key& key, const std::string& channel, const Message& msg) {
  const Tag tag = tagOf(key, signedBytes(msg), channel);
  return CRYPTO_memcmp(tag.data(), msg.auth, kTagBytes) == 0;
}

// The publishing side: numbers every message per channel (auth_seq 1, 2, ...: a receiver counts
// the gaps), and signs it when the run has a key.
class Stamper {
 public:
  explicit Stamper(std::optional<Key> key = std::nullopt) : key_(key) {}
  bool keyed() const { return key_.has_value(); }
  const std::optional<Key>& key() const { return key_; }
  template <class Message>
  void stamp(const std::string& channel, Message& msg) {
    msg.auth_seq = ++seq_[channel];
    if (key_) sign(*key_, channel, msg);
  }

 private:
  std::optional<Key> key_;
  std::map<std::string, int64_t> seq_;
};

}  // namespace aula::auth

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
// Reads exactly one key from `fd` and closes it; with `private_memory`, from then on the process
// is not dumpable (its memory unreadable to other processes of its user). Throws
// std::runtime_error naming `what` when the descriptor is not open or holds anything but 32 bytes.
Key readKey(int fd, const std::string& what, bool private_memory = true);

// The key one lockstep client of a graded run signs its registration and its acks with:
// HMAC-SHA256(run key, "lockstep client " + client). The launcher hands the component its own
// (--lockstep-key-fd); the referee derives its own; the simulator derives each client's to check
// it, and refuses a client of another run. It signs nothing else: the student's code beside it
// in the component can speak for that client of that run, never for the truth or the clock.
Key clientKey(const Key& run_key, const std::string& client);

// HMAC-SHA256 under one key, prepared once: a tag costs about 0.5 us instead of the 2.5 us of
// OpenSSL's one-shot HMAC() (which fetches the algorithm and hashes the key every time), and a
// graded vacuum run tags about 60 000 messages on each side.
class Signer {
 public:
  explicit Signer(const Key& key);  // throws std::runtime_error when OpenSSL cannot
  Signer(const Signer& other);
  Signer& operator=(const Signer& other);
  ~Signer();

  // HMAC-SHA256(key, bytes || channel).
  Tag tagOf(const std::vector<uint8_t>& bytes, const std::string& channel);

  // The message's tag: over its encoding with its `auth` zeroed, then the channel.
  template <class Message>
  Tag tagOfMessage(Message msg, const std::string& channel) {
    std::fill(std::begin(msg.auth), std::end(msg.auth), uint8_t{0});
    scratch_.resize(static_cast<size_t>(msg.getEncodedSize()));
    msg.encode(scratch_.data(), 0, static_cast<int>(scratch_.size()));
    return tagOf(scratch_, channel);
  }

 private:
  struct evp_mac_ctx_st* context_ = nullptr;  // EVP_MAC_CTX holding the key
  std::vector<uint8_t> scratch_;            // the encoding being tagged
};

template <class Message>
void sign(Signer& signer, const std::string& channel, Message& msg) {
  const Tag tag = signer.tagOfMessage(msg, channel);
  std::copy(tag.begin(), tag.end(), std::begin(msg.auth));
}

// True when `msg` carries the tag the signer's key gives it on `channel` (compared in constant time).
template <class Message>
bool verify(Signer& signer, const std::string& channel, const Message& msg) {
  const Tag tag = signer.tagOfMessage(msg, channel);
  return CRYPTO_memcmp(tag.data(), msg.auth, kTagBytes) == 0;
}

// The same with a signer made for the occasion (tests: one message, one key).
template <class Message>
void sign(Signer&& signer, const std::string& channel, Message& msg) {
  sign(signer, channel, msg);
}
template <class Message>
bool verify(Signer&& signer, const std::string& channel, const Message& msg) {
  return verify(signer, channel, msg);
}

// The publishing side: numbers every message per channel (auth_seq 1, 2, ...: a receiver counts
// the gaps), and signs it when the run has a key.
class Stamper {
 public:
  explicit Stamper(const std::optional<Key>& key = std::nullopt) {
    if (key) signer_.emplace(*key);
  }
  bool keyed() const { return signer_.has_value(); }
  // The run's key, prepared (keyed() only): what checks a message signed with it.
  Signer& signer() { return *signer_; }
  template <class Message>
  void stamp(const std::string& channel, Message& msg) {
    msg.auth_seq = ++seq_[channel];
    if (signer_) sign(*signer_, channel, msg);
  }

 private:
  std::optional<Signer> signer_;
  std::map<std::string, int64_t> seq_;
};

}  // namespace aula::auth

#include "aula/auth/run_key.hpp"

#include <openssl/evp.h>
#include <openssl/core_names.h>
#include <openssl/params.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <utility>

#include <fcntl.h>
#include <sys/random.h>
#include <sys/prctl.h>
#include <unistd.h>

namespace aula::auth {

Key randomKey() {
  Key key{};
  size_t filled = 0;
  while (filled < key.size()) {
    const ssize_t n = ::getrandom(key.data() + filled, key.size() - filled, 0);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw std::runtime_error(std::string("getrandom failed: ") + std::strerror(errno));
    filled += static_cast<size_t>(n);
  }
  return key;
}

int keyPipe(const Key& key) {
  int ends[2];
  if (::pipe2(ends, O_CLOEXEC) != 0) throw std::runtime_error(std::string("pipe2 failed: ") + std::strerror(errno));
  // 32 bytes fit in any pipe's buffer: the write never blocks, and the reader sees end-of-file.
  const ssize_t n = ::write(ends[1], key.data(), key.size());
  ::close(ends[1]);
  if (n != static_cast<ssize_t>(key.size())) {
    ::close(ends[0]);
    throw std::runtime_error("cannot write the run's key into its pipe");
  }
  return ends[0];
}

Key readKey(int fd, const std::string& what, bool private_memory) {
  // A process that holds the run's key is not dumpable: no other process of its user (a component
  // run without the sandbox) may read its memory through /proc/PID/mem or ptrace.
  if (private_memory) ::prctl(PR_SET_DUMPABLE, 0, 0, 0, 0);
  Key key{};
  size_t got = 0;
  for (;;) {
    uint8_t buffer[kKeyBytes + 1];
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      const int err = errno;
      ::close(fd);
      throw std::runtime_error(what + ": cannot read the run's key: " + std::strerror(err));
    }
    if (n == 0) break;
    if (got + static_cast<size_t>(n) > key.size()) {
      ::close(fd);
      throw std::runtime_error(what + ": more than " + std::to_string(kKeyBytes) + " bytes: not a run key");
    }
    std::memcpy(key.data() + got, buffer, static_cast<size_t>(n));
    got += static_cast<size_t>(n);
  }
  ::close(fd);
  if (got != key.size()) {
    throw std::runtime_error(what + ": " + std::to_string(got) + " bytes instead of " + std::to_string(kKeyBytes) +
                             ": not a run key");
  }
  return key;
}

Signer::Signer(const Key& key) {
  EVP_MAC* hmac = EVP_MAC_fetch(nullptr, "HMAC", nullptr);
  if (hmac != nullptr) context_ = EVP_MAC_CTX_new(hmac);
  EVP_MAC_free(hmac);  // the context holds its own reference
  char digest[] = "SHA256";
  const OSSL_PARAM params[] = {OSSL_PARAM_construct_utf8_string(OSSL_MAC_PARAM_DIGEST, digest, 0), OSSL_PARAM_construct_end()};
  if (context_ == nullptr || EVP_MAC_init(context_, key.data(), key.size(), params) != 1) {
    EVP_MAC_CTX_free(context_);
    throw std::runtime_error("HMAC-SHA256 is not available from OpenSSL");
  }
}

Signer::Signer(const Signer& other) : context_(EVP_MAC_CTX_dup(other.context_)) {
  if (context_ == nullptr) throw std::runtime_error("cannot copy an HMAC-SHA256 context");
}

Signer& Signer::operator=(const Signer& other) {
  if (this != &other) {
    Signer copy(other);
    std::swap(context_, copy.context_);
  }
  return *this;
}

Signer::~Signer() { EVP_MAC_CTX_free(context_); }

Tag Signer::tagOf(const std::vector<uint8_t>& bytes, const std::string& channel) {
  Tag tag{};
  size_t length = 0;
  // A null key restarts the MAC with the key it holds (its hashed pads), hashing nothing again.
  if (EVP_MAC_init(context_, nullptr, 0, nullptr) != 1 || EVP_MAC_update(context_, bytes.data(), bytes.size()) != 1 ||
      EVP_MAC_update(context_, reinterpret_cast<const unsigned char*>(channel.data()), channel.size()) != 1 ||
      EVP_MAC_final(context_, tag.data(), &length, tag.size()) != 1 || length != tag.size()) {
    throw std::runtime_error("HMAC-SHA256 failed");
  }
  return tag;
}

Key clientKey(const Key& run_key, const std::string& client) {
  const std::string purpose = "lockstep client ";
  return Signer(run_key).tagOf(std::vector<uint8_t>(purpose.begin(), purpose.end()), client);
}

}  // namespace aula::auth

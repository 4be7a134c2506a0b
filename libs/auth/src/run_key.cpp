#include "aula/auth/run_key.hpp"

#include <openssl/evp.h>
#include <openssl/hmac.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include <fcntl.h>
#include <sys/random.h>
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

Key readKey(int fd, const std::string& what) {
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

Tag tagOf(const Key& key, const std::vector<uint8_t>& bytes, const std::string& channel) {
  Tag tag{};
  unsigned int length = 0;
  std::vector<uint8_t> data(bytes);
  data.insert(data.end(), channel.begin(), channel.end());
  if (HMAC(EVP_sha256(), key.data(), static_cast<int>(key.size()), data.data(), data.size(), tag.data(), &length) ==
          nullptr ||
      length != tag.size()) {
    throw std::runtime_error("HMAC-SHA256 failed");
  }
  return tag;
}

}  // namespace aula::auth

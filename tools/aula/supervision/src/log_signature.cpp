#include "aula/supervision/log_signature.hpp"

#include <aula/config/config.hpp>
#include <aula/config/paths.hpp>

#include <lcm/lcm-cpp.hpp>

#include <cstdio>
#include <fstream>
#include <memory>
#include <sstream>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace aula::supervision {
namespace {

std::string hex(const uint8_t* bytes, size_t size) {
  static const char* digits = "0123456789abcdef";
  std::string out;
  for (size_t i = 0; i < size; ++i) out += {digits[bytes[i] >> 4], digits[bytes[i] & 15]};
  return out;
}

std::unique_ptr<lcm::LogFile> openLog(const std::string& path) {
  auto log = std::make_unique<lcm::LogFile>(path, "r");
  if (!log->good()) throw config::ConfigError(path + ": cannot read it as an LCM log");
  return log;
}

}  // namespace

void LogSigner::add(int64_t utime, const std::string& channel, const void* data, size_t size) {
  const auto* bytes = static_cast<const uint8_t*>(data);
  for (int shift = 0; shift < 64; shift += 8) chunk_.push_back(static_cast<uint8_t>(utime >> shift));
  chunk_.insert(chunk_.end(), channel.begin(), channel.end());
  chunk_.push_back(0);
  chunk_.insert(chunk_.end(), bytes, bytes + size);
  ++events_;
  if (++in_chunk_ == kChunkEvents) {
    const auth::Tag tag = signer_.tagOf(chunk_, std::to_string(tags_.size()));
    tags_.push_back(hex(tag.data(), tag.size()));
    chunk_.clear();
    in_chunk_ = 0;
  }
}

std::string LogSigner::finish() {
  if (in_chunk_ > 0) {
    const auth::Tag tag = signer_.tagOf(chunk_, std::to_string(tags_.size()));
    tags_.push_back(hex(tag.data(), tag.size()));
    chunk_.clear();
    in_chunk_ = 0;
  }
  std::string text = "aula log signature 1\nevents " + std::to_string(events_) + "\n";
  for (const std::string& tag : tags_) text += tag + "\n";
  return text;
}

bool isSigned(const std::string& path) {
  auto log = openLog(path);
  bool last_is_signature = false;
  while (const lcm::LogEvent* event = log->readNextEvent()) last_is_signature = event->channel == kSignatureChannel;
  return last_is_signature;
}

LogCheck checkLog(const std::string& path, const auth::Key& key) {
  auto log = openLog(path);
  LogSigner signer(key);
  LogCheck check;
  std::string signature;
  while (const lcm::LogEvent* event = log->readNextEvent()) {
    if (event->channel == kSignatureChannel) {
      signature.assign(static_cast<const char*>(event->data), static_cast<size_t>(event->datalen));
      check.is_signed = true;
      continue;
    }
    signer.add(event->timestamp, event->channel, event->data, static_cast<size_t>(event->datalen));
    ++check.events;
  }
  if (!check.is_signed) return check;
  std::istringstream expected(signature), actual(signer.finish());
  std::string want, got;
  for (size_t line = 0; std::getline(expected, want); ++line) {
    if (!std::getline(actual, got)) got.clear();
    if (want == got) continue;
    check.altered = line == 1 ? "the number of events (" + want.substr(7) + " signed, " + std::to_string(check.events) + " now)"
                    : line < 2 ? "the signature itself"
                               : "events " + std::to_string((line - 2) * kChunkEvents) + "-" +
                                     std::to_string((line - 1) * kChunkEvents - 1);
    return check;
  }
  check.intact = !std::getline(actual, got);
  if (!check.intact) check.altered = "events past the signed ones";
  return check;
}

void writeKeyFile(const std::string& path, const auth::Key& key) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
  const std::string text = hex(key.data(), key.size()) + "\n";
  const bool written = fd >= 0 && ::write(fd, text.data(), text.size()) == static_cast<ssize_t>(text.size());
  if (fd >= 0) ::close(fd);
  if (!written) throw std::runtime_error(path + ": cannot write the log's key");
}

auth::Key readKeyFile(const std::string& path) {
  std::istringstream in(config::readSmallFile(path, 4096, "key file"));
  std::string text;
  if (!(in >> text) || text.size() != 2 * auth::kKeyBytes) throw config::ConfigError(path + ": not a log's key (64 hex digits)");
  auth::Key key{};
  for (size_t i = 0; i < key.size(); ++i) {
    unsigned value = 0;
    if (std::sscanf(text.c_str() + 2 * i, "%2x", &value) != 1) throw config::ConfigError(path + ": not a log's key (64 hex digits)");
    key[i] = static_cast<uint8_t>(value);
  }
  return key;
}

}  // namespace aula::supervision

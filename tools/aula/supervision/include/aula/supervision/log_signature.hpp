#pragma once
// A recorded run's log, signed (issue 28: regrading trusts only signed logs). The recorder of a
// graded run (one with a run key) tags its events as it writes them: HMAC-SHA256 with the run's
// key over each chunk of kChunkEvents events (each event's sim-clock receive time, channel and
// bytes), and writes the tags as the log's last event, on kSignatureChannel. The key is kept
// beside the log (FILE.lcmlog.key, readable by its owner only; in a graded run the out folder,
// which no student process sees). `aula regrade` recomputes the tags and says which events
// changed.

#include <aula/auth/run_key.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace aula::supervision {

constexpr const char* kSignatureChannel = "AULA_LOG_SIGNATURE";
constexpr size_t kChunkEvents = 1000;

class LogSigner {
 public:
  explicit LogSigner(const auth::Key& key) : signer_(key) {}
  void add(int64_t utime, const std::string& channel, const void* data, size_t size);
  // The signature event's payload: every chunk's tag, in hex, one a line.
  std::string finish();

 private:
  auth::Signer signer_;
  std::vector<uint8_t> chunk_;
  size_t in_chunk_ = 0, events_ = 0;
  std::vector<std::string> tags_;
};

struct LogCheck {
  bool is_signed = false;
  bool intact = false;
  size_t events = 0;
  std::string altered;  // "events 12000-12999", when a chunk's tag differs (or "the number of events")
};

// Reads the log at `path` and checks its signature with `key` (throws config::ConfigError when
// the log cannot be read).
LogCheck checkLog(const std::string& path, const auth::Key& key);
// Whether the log ends with a signature at all (no key needed).
bool isSigned(const std::string& path);

// FILE.lcmlog.key: the key in hex, mode 0600; and reading it back (ConfigError when malformed).
void writeKeyFile(const std::string& path, const auth::Key& key);
auth::Key readKeyFile(const std::string& path);

}  // namespace aula::supervision

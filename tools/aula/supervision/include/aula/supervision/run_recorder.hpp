#pragma once
// `aula run --record=FILE.lcmlog`: the whole run in LCM's log format (lcm-logger's, written with
// LCM's own lcm::LogFile; lcm-logplayer plays it), its first Aula message (AULA_RUN,
// run_record_t) saying how to grade it again (`aula regrade FILE.lcmlog`).
//
// Not the stock lcm-logger as a child process: LCM 1.3.1's logger keeps LCM's default queue of
// 30 messages on its one subscription, so whenever it is not scheduled for a moment during a
// lockstep burst LCM drops messages silently (measured on this 2-core machine shared with
// others: 18 % of a 60 s vacuum run's poses under `ctest -j2`, 6-10 % of a 900 s one; the
// regraded report then differs). Here the subscription
// queues kQueueCapacity like every Aula subscription.

#include <aula/config/config.hpp>
#include <aula/supervision/log_signature.hpp>
#include <aula/run_record_t.hpp>
#include <aula/settings/tables.hpp>

#include <aula/lcm/bus.hpp>
#include <lcm/lcm-cpp.hpp>

#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <thread>

namespace aula::supervision {

// What the log says of its run: the exercise, the world (name, path, SHA-256), the seed and
// every setting the referee grades with (`referee_settings`, as the launcher resolved them).
aula::run_record_t runRecord(const settings::Exercise& exercise, const std::string& world_path, int64_t seed,
                             const config::Config& referee_settings);

// `aula regrade LOG [--report=FILE.json]`: the log's referee, alone and headless, grades the
// log (--replay) with the recorded settings; returns its exit code. `trace_path`: the referee's
// --trace too (the same bytes as the live run's).
int regrade(const std::string& log_path, const std::string& report_path, const std::string& bin_dir,
            const std::string& trace_path = "");

class RunRecorder {
 public:
  // Refuses a log whose folder is missing (config::ConfigError, exit 2): call it before
  // anything starts.
  static void checkPath(const std::string& path);

  // Listens to everything on the run's bus `url` and returns once the log holds `record`, so
  // it hears everything the simulator will say.
  // `key`: a graded run's key; the log is then signed (log_signature.hpp) and the key written
  // beside it (PATH.key).
  RunRecorder(const std::string& path, const std::string& url, const aula::run_record_t& record,
              const std::optional<auth::Key>& key = std::nullopt);
  ~RunRecorder();
  RunRecorder(const RunRecorder&) = delete;
  RunRecorder& operator=(const RunRecorder&) = delete;

  // After the referee has exited: lets the last messages reach the log, then closes it.
  void stop();

 private:
  void onMessage(const lcm::ReceiveBuffer* message, const std::string& channel);

  std::string path_;
  std::unique_ptr<lcm::LogFile> log_;
  std::unique_ptr<LogSigner> signer_;  // a graded run's: every event, then the signature at stop()
  int64_t last_utime_ = 0;
  std::unique_ptr<lcmbus::Bus> bus_;
  std::thread thread_;             // handles bus_ until stop_
  std::atomic<bool> stop_{false};
  bool record_written_ = false;    // the thread's, or the constructor's before it starts
  long long events_ = 0;
  int write_error_ = 0;  // errno of the first event that could not be written
};

}  // namespace aula::supervision

#pragma once
// `aula run --record=FILE.lcmlog`: the stock lcm-logger (liblcm-bin) records the whole run in
// LCM's log format, and the first Aula message in it (AULA_RUN, run_record_t) says how to grade
// it again (`aula regrade FILE.lcmlog`).

#include <aula/config/config.hpp>
#include <aula/process/child_process.hpp>
#include <aula/run_record_t.hpp>
#include <aula/settings/tables.hpp>

#include <cstdint>

#include <memory>
#include <string>

namespace aula::launcher {

// What the log says of its run: the exercise, the world (name, path, SHA-256), the seed and
// every setting the referee grades with (`referee_settings`, as the launcher resolved them).
aula::run_record_t runRecord(const settings::Exercise& exercise, const std::string& world_path, int64_t seed,
                             const config::Config& referee_settings);

// `aula regrade LOG [--report=FILE.json]`: the log's referee, alone and headless, grades the
// log (--replay) with the recorded settings; returns its exit code.
int regrade(const std::string& log_path, const std::string& report_path, const std::string& bin_dir);

class RunRecorder {
 public:
  // Refuses a log whose folder is missing (config::ConfigError, exit 2): call it before
  // anything starts.
  static void checkPath(const std::string& path);

  // Starts lcm-logger on the run's bus `url` and returns once the log holds `record`, so the
  // logger hears everything the simulator will say. A missing lcm-logger is a ConfigError.
  RunRecorder(const std::string& path, const std::string& url, const aula::run_record_t& record);
  ~RunRecorder();
  RunRecorder(const RunRecorder&) = delete;
  RunRecorder& operator=(const RunRecorder&) = delete;

  // After the referee has exited: lets the last messages reach the log, then ends lcm-logger
  // with SIGINT (it flushes and closes the file).
  void stop();

 private:
  std::string path_;
  std::unique_ptr<process::ChildProcess> logger_;
};

}  // namespace aula::launcher

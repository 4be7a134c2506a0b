#include "aula/supervision/run_recorder.hpp"

#include <aula/config/config.hpp>
#include <aula/lcm/bus.hpp>
#include <aula/config/paths.hpp>
#include <aula/desktop/window_layout.hpp>
#include <aula/lcm/log_replay.hpp>
#include <aula/process/child_process.hpp>
#include <aula/world/world_spec.hpp>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <thread>

#include <unistd.h>

namespace aula::supervision {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

constexpr auto kStartTimeout = 5s;  // the record comes back on the bus by then
constexpr auto kDrain = 200ms;      // the last datagrams of the run reach the recorder

// The recorder's own receive buffer, whatever the run's URL says: nobody waits for the recorder
// (it is no lockstep client), and a lockstep run as fast as possible sends bursts, so a starved
// launcher must find the run still queued. 64 MB holds a 300 s Autopark run's 50,000 messages
// whole (4 MB lost 14 % of its poses beside four busy loops); the kernel grants it to a process
// that may force it (root), else net.core.rmem_max.
std::string withLargeReceiveBuffer(const std::string& url) {
  if (url.rfind("udpm://", 0) != 0) return url;
  const auto question = url.find('?');
  std::string out = url.substr(0, question) + "?recv_buf_size=67108864";
  if (question == std::string::npos) return out;
  std::istringstream options(url.substr(question + 1));
  for (std::string option; std::getline(options, option, '&');) {
    if (!option.empty() && option.rfind("recv_buf_size=", 0) != 0) out += "&" + option;
  }
  return out;
}

}  // namespace

aula::run_record_t runRecord(const settings::Exercise& exercise, const std::string& world_path, int64_t seed,
                             const config::Config& referee_settings) {
  aula::run_record_t record;
  record.exercise = exercise.name;
  record.referee = exercise.referee;
  record.world = fs::path(world_path).filename().string();
  record.world_path = fs::absolute(world_path).string();
  record.world_sha256 = world::loadWorld(world_path).sha256;  // every file the world is read from
  record.seed = seed;
  std::vector<std::string> windows_keys;  // where the windows were is the desktop's, not the grading's
  for (const std::string& window : desktop::windowsOf(*exercise.referee_settings)) {
    windows_keys.insert(windows_keys.end(), {window + ".Size", window + ".Position"});
  }
  for (const std::string& key : referee_settings.keys()) {
    // The world and the bus are the run's, not the grading's: regrade names its own.
    if (key == exercise.section + ".World" || key == "Aula.LcmUrl") continue;
    if (std::find(windows_keys.begin(), windows_keys.end(), key) != windows_keys.end()) continue;
    if (exercise.referee_settings->declares(key)) record.settings.push_back(key + "=" + referee_settings.getString(key));
  }
  record.num_settings = static_cast<int32_t>(record.settings.size());
  return record;
}

int regrade(const std::string& log_path, const std::string& report_path, const std::string& bin_dir,
            const std::string& trace_path) {
  const aula::run_record_t record = lcmbus::readRunRecord(log_path);
  const settings::Exercise* exercise = settings::exerciseNamed(record.exercise);
  if (exercise == nullptr || exercise->referee != record.referee) {
    throw config::ConfigError(log_path + ": recorded for exercise '" + record.exercise + "' graded by '" +
                              record.referee + "', which this Aula does not have");
  }
  // The recorded path, else the world of that name in the data folder; the referee refuses a
  // world whose SHA-256 is not the recorded simulator's.
  std::error_code error;
  const std::string world = fs::is_regular_file(record.world_path, error)
                                ? record.world_path
                                : config::resolveWorldPath(record.world, log_path + ": world");
  std::vector<std::string> args = {bin_dir + "/" + exercise->referee, "--headless",
                                   "--replay=" + fs::absolute(log_path).string(),
                                   "--" + exercise->section + ".World=" + world};
  for (const std::string& setting : record.settings) args.push_back("--" + setting);
  if (!report_path.empty()) args.push_back("--report=" + report_path);
  if (!trace_path.empty()) args.push_back("--trace=" + trace_path);
  process::ChildProcess referee(args);
  return referee.wait(std::chrono::hours(24 * 365)).value_or(1);
}

void RunRecorder::checkPath(const std::string& path) {
  const fs::path file = fs::absolute(path);
  const fs::path folder = file.parent_path();
  std::error_code error;
  if (!fs::is_directory(folder, error)) {
    throw config::ConfigError("--record=" + path + ": the folder " + folder.string() + " does not exist");
  }
  if (access(folder.c_str(), W_OK) != 0) {
    throw config::ConfigError("--record=" + path + ": the folder " + folder.string() + " is not writable");
  }
  if (fs::is_directory(file, error)) throw config::ConfigError("--record=" + path + ": is a folder, not a file");
}

RunRecorder::RunRecorder(const std::string& path, const std::string& url, const aula::run_record_t& record,
                         const std::optional<auth::Key>& key)
    : path_(path) {
  log_ = std::make_unique<lcm::LogFile>(path_, "w");
  if (!log_->good()) throw config::ConfigError("--record=" + path_ + ": cannot write: " + std::strerror(errno));
  if (key) {
    writeKeyFile(path_ + ".key", *key);
    signer_ = std::make_unique<LogSigner>(*key);
  }
  bus_ = lcmbus::openBus(withLargeReceiveBuffer(url));
  bus_->subscribe(".*", &RunRecorder::onMessage, this);
  // A process hears what it publishes: the record is the log's first Aula message, and once it
  // is written the subscription is live for everything that follows.
  bus_->publish(lcmbus::kRunChannel, &record);
  const auto deadline = std::chrono::steady_clock::now() + kStartTimeout;
  while (!record_written_) {
    if (std::chrono::steady_clock::now() > deadline) {
      throw std::runtime_error("--record: the run's " + std::string(lcmbus::kRunChannel) + " message did not come back on " + url);
    }
    bus_->handleTimeout(50);
  }
  thread_ = std::thread([this] {
    while (!stop_) bus_->handleTimeout(50);
    while (bus_->handleTimeout(0) > 0) {  // what arrived before stop()
    }
  });
}

void RunRecorder::onMessage(const lcm::ReceiveBuffer* message, const std::string& channel) {
  lcm::LogEvent event{0, message->recv_utime, channel, static_cast<int32_t>(message->data_size), message->data};
  if (log_->writeEvent(&event) != 0 && write_error_ == 0) write_error_ = errno != 0 ? errno : EIO;
  if (signer_) signer_->add(event.timestamp, channel, message->data, message->data_size);
  last_utime_ = event.timestamp;
  ++events_;
  if (channel == lcmbus::kRunChannel) record_written_ = true;
}

RunRecorder::~RunRecorder() { stop(); }

void RunRecorder::stop() {
  if (!thread_.joinable()) return;
  std::this_thread::sleep_for(kDrain);
  stop_ = true;
  thread_.join();
  if (signer_) {  // the last event: every event's tag, chunk by chunk
    std::string signature = signer_->finish();
    lcm::LogEvent event{0, last_utime_, kSignatureChannel, static_cast<int32_t>(signature.size()), signature.data()};
    if (log_->writeEvent(&event) != 0 && write_error_ == 0) write_error_ = errno != 0 ? errno : EIO;
  }
  log_.reset();  // flushes and closes the file
  std::error_code error;
  const auto bytes = std::filesystem::file_size(path_, error);
  if (write_error_ != 0 || error) {
    std::cerr << "aula: could not write every message to " << path_ << " ("
              << std::strerror(write_error_ != 0 ? write_error_ : error.value()) << "): the log is incomplete\n";
    return;
  }
  std::cerr << "aula: run recorded in " << path_ << " (" << events_ << " messages, " << bytes / 1024 << " KiB"
            << (signer_ ? ", signed; its key in " + path_ + ".key" : "") << "); grade it again with `aula regrade " << path_
            << "`\n";
}

}  // namespace aula::supervision

#include "aula/lcm/log_replay.hpp"

#include <aula/config/config.hpp>
#include <aula/sim_clock_t.hpp>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <memory>

namespace aula::lcmbus {
namespace {

// Opens `path` for reading, or says why not.
std::unique_ptr<lcm::LogFile> openLog(const std::string& path) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) {
    throw config::ConfigError(path + ": no such file (expected an LCM log, e.g. from `aula run --record=FILE.lcmlog`)");
  }
  auto log = std::make_unique<lcm::LogFile>(path, "r");
  if (!log->good()) throw config::ConfigError(path + ": cannot read: " + std::strerror(errno));
  return log;
}

// The log's first event. It also proves the file is a log: LCM's reader skips bytes that are not
// an event, so any other file reads as an empty log.
const lcm::LogEvent* firstEvent(lcm::LogFile& log, const std::string& path) {
  const lcm::LogEvent* event = log.readNextEvent();
  if (event == nullptr) {
    throw config::ConfigError(path + ": not an LCM log (no event in it; `aula run --record=FILE.lcmlog` writes one)");
  }
  return event;
}

}  // namespace

void requireLog(const std::string& path) { firstEvent(*openLog(path), path); }

std::optional<aula::run_record_t> findRunRecord(const std::string& path) {
  const auto log = openLog(path);
  for (const lcm::LogEvent* event = log->readNextEvent(); event != nullptr; event = log->readNextEvent()) {
    aula::run_record_t record;
    if (event->channel == kRunChannel && record.decode(event->data, 0, static_cast<int>(event->datalen)) >= 0) {
      return record;
    }
  }
  return std::nullopt;
}

aula::run_record_t readRunRecord(const std::string& path) {
  requireLog(path);
  if (auto record = findRunRecord(path)) return *record;
  throw config::ConfigError(path + ": an LCM log without a run_record_t on " + std::string(kRunChannel) +
                            ": it was not recorded by `aula run --record`, so nothing says how to grade it");
}

bool replayLog(lcmbus::Bus& bus, const std::string& path, const std::function<bool()>& done,
               const std::function<void()>& after_each) {
  const auto log = openLog(path);
  const lcm::LogEvent* event = firstEvent(*log, path);
  while (!done()) {
    if (event == nullptr) return true;
    bus.publish(event->channel, event->data, event->datalen);
    // This event, then whatever its handlers published (a client's acks), before the next.
    while (!done() && bus.handleTimeout(0) > 0) {
    }
    if (after_each) after_each();
    event = log->readNextEvent();
  }
  return false;
}

std::vector<RecordedMessage> recordedMessagesOfType(const std::string& path, int64_t type_hash) {
  const auto log = openLog(path);
  std::vector<RecordedMessage> found;
  int64_t tick_us = 0;
  for (const lcm::LogEvent* event = firstEvent(*log, path); event != nullptr; event = log->readNextEvent()) {
    const auto* bytes = static_cast<const uint8_t*>(event->data);
    aula::sim_clock_t tick;
    if (event->channel == kClockChannel && tick.decode(event->data, 0, static_cast<int>(event->datalen)) >= 0) {
      tick_us = tick.utime;
    }
    if (event->datalen < 8) continue;
    uint64_t hash = 0;
    for (int i = 0; i < 8; ++i) hash = (hash << 8) | bytes[i];
    if (static_cast<int64_t>(hash) == type_hash) {
      found.push_back({tick_us, event->channel, std::vector<uint8_t>(bytes, bytes + event->datalen)});
    }
  }
  return found;
}

}  // namespace aula::lcmbus

#pragma once
// A recorded run (LCM's log format, as `aula run --record` and the stock lcm-logger write it)
// read back in-process: a referee grades the log without a simulator. Every event goes through
// the process's own subscriptions on an in-process memq:// bus, in the log's order, one at a
// time: never over UDP, where an unpaced replay loses messages.

#include <aula/run_record_t.hpp>

#include "aula/lcm/bus.hpp"
#include <lcm/lcm-cpp.hpp>

#include <functional>
#include <optional>
#include <string>
#include <vector>
#include <cstdint>

namespace aula::lcmbus {

// The bus a replaying process opens instead of the run's URL.
inline constexpr const char* kReplayUrl = "memq://";
// `aula run` says on this channel how to grade the run again (run_record_t).
inline constexpr const char* kRunChannel = "AULA_RUN";

// Throws config::ConfigError naming `path` when it is missing, unreadable or not an LCM log.
void requireLog(const std::string& path);

// The run's record (the first on kRunChannel), or nothing: an empty log (lcm-logger has not
// written it yet), another file, a log `aula run` did not record. Throws config::ConfigError
// naming `path` when it is missing or unreadable.
std::optional<aula::run_record_t> findRunRecord(const std::string& path);
// The same, or a config::ConfigError saying the file is not an LCM log or not one of Aula's.
aula::run_record_t readRunRecord(const std::string& path);

// Publishes each event of the log on `bus` (a kReplayUrl bus) and handles it before the next,
// until `done()` holds or the log ends; `after_each` runs after every event. A LockstepClient
// needs nothing special: it follows the recorded ticks, and its registrations and acks reach
// no simulator. Returns true when the log ended before `done()` held.
bool replayLog(lcmbus::Bus& bus, const std::string& path, const std::function<bool()>& done,
               const std::function<void()>& after_each);

// A recorded message, with the sim time of the last SIM_CLOCK tick before it in the log: the
// tick it answered (in lockstep a component's command answers the tick that ran its period).
struct RecordedMessage {
  int64_t tick_us = 0;
  std::string channel;
  std::vector<uint8_t> bytes;
};
// The log's messages of one LCM type (`type_hash`: its fingerprint, e.g. motors_t::getHash(),
// which begins every encoding), in order. Throws config::ConfigError as requireLog.
std::vector<RecordedMessage> recordedMessagesOfType(const std::string& path, int64_t type_hash);

}  // namespace aula::lcmbus

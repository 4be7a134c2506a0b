#pragma once
// The simulator half of lockstep: who is registered, who is due at a tick, who has acked.
// Plain bookkeeping on sim time and a wall clock passed in, so it is unit-testable.

#include <chrono>
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace aula::sim {

class LockstepServer {
 public:
  using WallClock = std::chrono::steady_clock;

  explicit LockstepServer(std::chrono::milliseconds drop_after) : drop_after_(drop_after) {}

  // Returns true when the client is new (worth a log line). `pid`: its process (0: unknown).
  bool join(const std::string& client, int64_t period_us, int pid = 0);
  bool leave(const std::string& client);
  // Marks the clients due at this tick (period divides into utime) as awaited.
  void tick(int64_t seq, int64_t utime, WallClock::time_point now);
  void ack(const std::string& client, int64_t seq);
  // True while some due client has not acked the current tick.
  bool waiting() const;
  // The clients that have not acked their tick for drop_after or more: each is listed once per
  // drop_after it stays silent (the caller decides: end the run, wait, or drop it).
  struct Silent {
    std::string client;
    int pid = 0;
    std::chrono::milliseconds silent_for{0};
  };
  std::vector<Silent> silent(WallClock::time_point now);
  // Earliest sim time after `utime` at which some client is due (INT64_MAX if none).
  int64_t nextDueAfter(int64_t utime) const;
  // World reset: time starts again from zero.
  void resetSchedule();

  std::vector<std::string> clients() const;
  // Each client's process id as it registered (0: unknown).
  std::vector<std::pair<std::string, int>> pids() const;
  std::size_t size() const { return clients_.size(); }

 private:
  struct Client {
    int64_t period_us = 1;
    int64_t next_due_us = 0;
    int64_t awaited_seq = -1;  // -1: nothing awaited
    WallClock::time_point awaited_since{};
    WallClock::time_point listed_silent_at{};  // when silent() last listed it for this tick
    int pid = 0;
  };
  std::map<std::string, Client> clients_;
  std::chrono::milliseconds drop_after_;
};

}  // namespace aula::sim

#include "aula/sim/lockstep_server.hpp"

#include <algorithm>
#include <limits>

namespace aula::sim {

bool LockstepServer::join(const std::string& client, int64_t period_us, int pid) {
  const bool is_new = clients_.count(client) == 0;
  Client& c = clients_[client];
  c.period_us = std::max<int64_t>(1, period_us);
  c.pid = pid;
  return is_new;
}

bool LockstepServer::leave(const std::string& client) { return clients_.erase(client) != 0; }

void LockstepServer::tick(int64_t seq, int64_t utime, WallClock::time_point now) {
  for (auto& [name, c] : clients_) {
    if (utime >= c.next_due_us) {
      c.next_due_us = (utime / c.period_us + 1) * c.period_us;
      c.awaited_seq = seq;
      c.awaited_since = now;
      c.listed_silent_at = now;
    }
  }
}

void LockstepServer::ack(const std::string& client, int64_t seq) {
  const auto it = clients_.find(client);
  if (it != clients_.end() && it->second.awaited_seq == seq) it->second.awaited_seq = -1;
}

bool LockstepServer::waiting() const {
  return std::any_of(clients_.begin(), clients_.end(),
                     [](const auto& kv) { return kv.second.awaited_seq >= 0; });
}

std::vector<LockstepServer::Silent> LockstepServer::silent(WallClock::time_point now) {
  std::vector<Silent> out;
  for (auto& [name, c] : clients_) {
    if (c.awaited_seq < 0 || now - c.listed_silent_at < drop_after_) continue;
    c.listed_silent_at = now;
    out.push_back({name, c.pid, std::chrono::duration_cast<std::chrono::milliseconds>(now - c.awaited_since)});
  }
  return out;
}

int64_t LockstepServer::nextDueAfter(int64_t utime) const {
  int64_t next = std::numeric_limits<int64_t>::max();
  for (const auto& [name, c] : clients_) {
    next = std::min(next, std::max(c.next_due_us, (utime / c.period_us + 1) * c.period_us));
  }
  return next;
}

void LockstepServer::resetSchedule() {
  for (auto& [name, c] : clients_) {
    c.next_due_us = 0;
    c.awaited_seq = -1;
  }
}

std::vector<std::string> LockstepServer::clients() const {
  std::vector<std::string> names;
  for (const auto& [name, c] : clients_) names.push_back(name);
  return names;
}

std::vector<std::pair<std::string, int>> LockstepServer::pids() const {
  std::vector<std::pair<std::string, int>> out;
  for (const auto& [name, c] : clients_) out.emplace_back(name, c.pid);
  return out;
}

}  // namespace aula::sim

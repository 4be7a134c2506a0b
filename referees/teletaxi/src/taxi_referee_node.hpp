#pragma once
// The TeleTaxi referee's LCM side: true pose, the component's episode events and the clock
// feed the TaxiReferee; at the end it builds the report.

#include <aula/config/config.hpp>
#include <aula/bumper_t.hpp>
#include <aula/episode_t.hpp>
#include <aula/lcm/lockstep_client.hpp>
#include <aula/pose3d_t.hpp>
#include <aula/referee/report.hpp>
#include <aula/referee/run_outcome.hpp>
#include <aula/referee/status_sender.hpp>
#include <aula/teletaxi/taxi_referee.hpp>
#include <aula/world/occupancy_map.hpp>
#include <aula/world/world_spec.hpp>

#include <aula/lcm/bus.hpp>
#include <lcm/lcm-cpp.hpp>

#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace aula::teletaxi {

class TaxiRefereeNode {
 public:
  // `run_key`: a graded run's key (--key-fd): only the truth the simulator signed is graded.
  TaxiRefereeNode(lcmbus::Bus& bus, const config::Config& cfg, const world::WorldSpec& world,
                  const std::optional<auth::Key>& run_key = std::nullopt);

  const TaxiReferee& referee() const { return referee_; }
  bool finished() const { return referee_.finished() || outcome_.ended(); }
  // The launcher says the run cannot go on (a process died...): grade what there is, and end.
  void abort(const std::string& reason);
  bool endedEarly() const { return outcome_.ended(); }
  aula::referee::Report report() const;
  std::string summary() const;  // the mark and its breakdown, for the terminal
  void writePicture(const std::string& png_path) const;  // --picture
  void poll() { clock_->poll(); }
  void leave() { clock_->leave(); }
  int64_t simTimeUs() const { return clock_->simTimeUs(); }
  long long bumps() const { return bumps_; }
  void setOnFinished(std::function<void()> hook) { on_finished_ = std::move(hook); }
  // What the windows are told (referee_status_t): the time left, and how the episode ended.
  referee::EpisodeStatus status() const;

 private:
  void onPose(const lcm::ReceiveBuffer*, const std::string&, const aula::pose3d_t* msg);
  void onEpisode(const lcm::ReceiveBuffer*, const std::string&, const aula::episode_t* msg);
  void onTick(int64_t utime);
  void onBumper(const lcm::ReceiveBuffer*, const std::string&, const aula::bumper_t* msg);

  TaxiRefereeSettings settings_;
  referee::Report rubric_;  // the report's "rubric": the preset and its numbers
  int64_t episode_from_utime_ = -1;  // truth at or before this sim time is the last episode's
  TaxiReferee referee_;
  std::string world_file_, world_sha256_;  // the file name and its content's hash
  aula::referee::RunOutcome outcome_;
  std::unique_ptr<lcmbus::LockstepClient> clock_;
  std::unique_ptr<referee::StatusSender> status_;
  std::function<void()> on_finished_;
  long long bumps_ = 0;       // contacts with walls (or anything) after GO!, counted on press
  world::WorldSpec world_;    // drawn into the picture's map only when one is asked for
  world::MapParams map_params_;
  bool pressed_ = false;
};


}  // namespace aula::teletaxi

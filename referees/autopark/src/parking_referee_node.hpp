#pragma once
// The Autopark referee's LCM side: the true pose, the bumper driver's contacts (DART), the
// component's Run and the clock feed the ParkingReferee; at the end it builds the report.

#include <aula/autopark/parking_referee.hpp>
#include <aula/bumper_t.hpp>
#include <aula/config/config.hpp>
#include <aula/world/world_spec.hpp>
#include <aula/episode_t.hpp>
#include <aula/lcm/lockstep_client.hpp>
#include <aula/pose3d_t.hpp>
#include <aula/referee/report.hpp>
#include <aula/referee/run_outcome.hpp>
#include <aula/referee/status_sender.hpp>

#include <aula/lcm/bus.hpp>
#include <lcm/lcm-cpp.hpp>

#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace aula::autopark {

class ParkingRefereeNode {
 public:
  // `run_key`: a graded run's key (--key-fd): only the truth the simulator signed is graded.
  ParkingRefereeNode(lcmbus::Bus& bus, const config::Config& cfg, const world::WorldSpec& world,
                     const std::optional<auth::Key>& run_key = std::nullopt);

  const ParkingReferee& referee() const { return *referee_; }
  bool finished() const { return referee_->finished() || outcome_.ended(); }
  // The launcher says the run cannot go on (a process died...): grade what there is, and end.
  void abort(const std::string& reason);
  bool endedEarly() const { return outcome_.ended(); }
  aula::referee::Report report() const;
  std::string summary() const;
  void writePicture(const std::string& png_path) const;  // --picture
  void poll() { clock_->poll(); }
  void leave() { clock_->leave(); }
  void setOnFinished(std::function<void()> hook) { on_finished_ = std::move(hook); }
  // What the windows are told (referee_status_t): the time left, and how the episode ended.
  referee::EpisodeStatus status() const;

 private:
  void onPose(const lcm::ReceiveBuffer*, const std::string&, const aula::pose3d_t* msg);
  void onBumper(const lcm::ReceiveBuffer*, const std::string&, const aula::bumper_t* msg);
  void onEpisode(const lcm::ReceiveBuffer*, const std::string&, const aula::episode_t* msg);
  void onTick(int64_t utime);

  ParkingScene scene_;
  ParkingRefereeSettings settings_;
  referee::Report rubric_;  // the report's "rubric": the preset and its numbers
  int64_t episode_from_utime_ = -1;  // truth at or before this sim time is the last episode's
  std::unique_ptr<ParkingReferee> referee_;
  aula::referee::RunOutcome outcome_;
  std::unique_ptr<lcmbus::LockstepClient> clock_;
  std::unique_ptr<referee::StatusSender> status_;
  std::function<void()> on_finished_;
  std::string world_file_, world_sha256_;  // the file name and its content's hash
  world::WorldSpec world_;  // the street, drawn into the picture only when one is asked for
};

}  // namespace aula::autopark

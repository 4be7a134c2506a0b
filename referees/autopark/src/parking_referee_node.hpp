#pragma once
// The Autopark referee on every exercise's RefereeNode: the true pose, the bumper driver's
// contacts (DART), the component's Run and the clock feed the ParkingReferee.

#include <aula/autopark/parking_referee.hpp>
#include <aula/config/config.hpp>
#include <aula/referee/referee_node.hpp>
#include <aula/world/world_spec.hpp>

#include <memory>
#include <optional>
#include <string>

namespace aula::autopark {

class ParkingRefereeNode : public referee::RefereeNode {
 public:
  // `run_key`: a graded run's key (--key-fd): only the truth the simulator signed is graded.
  ParkingRefereeNode(lcmbus::Bus& bus, const config::Config& cfg, const world::WorldSpec& world,
                     const std::optional<auth::Key>& run_key = std::nullopt);

  const ParkingReferee& referee() const { return *referee_; }
  referee::EpisodeStatus status() const override;

 private:
  bool gradedToEnd() const override { return referee_->finished(); }
  void onTruePose(const aula::pose3d_t& msg) override;
  void onContact(int64_t utime, bool pressed) override;
  void startNewEpisode(int64_t utime) override;
  void onEpisode(const aula::episode_t& msg) override;
  void onClockTick(int64_t utime) override;
  double mark() const override { return referee_->scores().mark; }
  void addGrading(referee::Report& report) const override;
  std::vector<std::string> measures() const override {
    return {"park_time_s", "front_gap_m", "rear_gap_m", "curb_gap_m"};
  }
  std::string gradeSummary() const override;
  cv::Mat picture(const std::vector<std::string>& notes) const override;
  void addTrace(referee::Report& trace) const override;
  void traceEnd(int64_t utime);  // the end, and the points each final measure earned

  ParkingScene scene_;
  ParkingRefereeSettings settings_;
  std::unique_ptr<ParkingReferee> referee_;
  world::WorldSpec world_;  // the street, drawn into the picture (and the trace) only when one is asked for
  long open_contact_ = -1;  // the trace's event of the contact under way
};

}  // namespace aula::autopark

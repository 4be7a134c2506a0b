#pragma once
// The TeleTaxi referee on every exercise's RefereeNode: the true pose, the bumper, the
// component's episode events (GO!, the destination) and the clock feed the TaxiReferee.

#include <aula/config/config.hpp>
#include <aula/referee/referee_node.hpp>
#include <aula/teletaxi/taxi_referee.hpp>
#include <aula/world/occupancy_map.hpp>
#include <aula/world/world_spec.hpp>

#include <optional>
#include <string>

namespace aula::teletaxi {

class TaxiRefereeNode : public referee::RefereeNode {
 public:
  // `run_key`: a graded run's key (--key-fd): only the truth the simulator signed is graded.
  TaxiRefereeNode(lcmbus::Bus& bus, const config::Config& cfg, const world::WorldSpec& world,
                  const std::optional<auth::Key>& run_key = std::nullopt);

  const TaxiReferee& referee() const { return referee_; }
  long long bumps() const { return bumps_; }
  referee::EpisodeStatus status() const override;

 private:
  bool gradedToEnd() const override { return referee_.finished(); }
  void onTruePose(const aula::pose3d_t& msg) override;
  void onContact(int64_t utime, bool pressed) override;
  void startNewEpisode(int64_t utime) override;
  void onEpisode(const aula::episode_t& msg) override;
  void onClockTick(int64_t utime) override;
  double mark() const override { return grade().mark; }
  void addGrading(referee::Report& report) const override;
  std::vector<std::string> measures() const override { return {"driving_time_s", "final_distance_m", "path_length_m"}; }
  std::string gradeSummary() const override;
  cv::Mat picture(const std::vector<std::string>& notes) const override;
  void addTrace(referee::Report& trace) const override;
  TaxiGrade grade() const { return referee_.finished() ? referee_.grade() : referee_.provisionalGrade(); }

  TaxiRefereeSettings settings_;
  TaxiReferee referee_;
  long long bumps_ = 0;       // contacts with walls (or anything) after GO!, counted on press
  world::WorldSpec world_;    // drawn into the picture's (and the trace's) map only when one is asked for
  double start_x_m_ = 0, start_y_m_ = 0;  // where the taxi stood at GO!, for the trace
  world::MapParams map_params_;
  bool pressed_ = false;
};

}  // namespace aula::teletaxi

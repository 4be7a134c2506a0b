#include "aula/component/episode_sender.hpp"

#include <aula/episode_t.hpp>
#include <aula/lcm/bus.hpp>
#include <aula/sim_control_t.hpp>

namespace aula::component {

void EpisodeSender::tick(int64_t utime, const EpisodeState& state) {
  if (state.status != last_status_ || state.not_the_seeds_run != last_not_the_seeds_run_) changed_ = true;
  if (!changed_ && utime - last_utime_ < 1'000'000) return;
  aula::episode_t msg;
  msg.utime = utime;
  msg.exercise = exercise_;
  msg.algorithm = host_.name();
  msg.goal_set = state.goal_xy_m.has_value();
  msg.goal_x = state.goal_xy_m ? state.goal_xy_m->first : 0.0;
  msg.goal_y = state.goal_xy_m ? state.goal_xy_m->second : 0.0;
  msg.running = state.running;
  msg.started_utime = state.started_utime;
  msg.fault = host_.fault();
  msg.non_finite_commands = host_.nonFiniteCommands();
  msg.generation = generation_;
  msg.status = state.status;
  msg.not_the_seeds_run = state.not_the_seeds_run;
  last_status_ = state.status;
  last_not_the_seeds_run_ = state.not_the_seeds_run;
  bus_.publish(channel_, &msg);
  last_utime_ = utime;
  changed_ = false;
}

void EpisodeSender::restart(const StartPose& start) {
  aula::sim_control_t teleport{};
  teleport.command = aula::sim_control_t::SET_POSE;
  teleport.robot = start.robot;
  teleport.x = start.x_m;
  teleport.y = start.y_m;
  teleport.yaw = start.yaw_rad;
  bus_.publish(lcmbus::kControlChannel, &teleport);
  ++generation_;
  changed_ = true;
}

}  // namespace aula::component

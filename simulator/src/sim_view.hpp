#pragma once
// aula-sim --gui: a 3D view of the running world with DART's OpenSceneGraph viewer, like
// Gazebo's client. The view only draws; the simulator keeps stepping the world itself. Its code
// is the module lib/aula/libaula_sim_view.so, opened only here: a headless simulator never loads
// OpenSceneGraph.

#include <aula/desktop/window_layout.hpp>

#include <dart/simulation/World.hpp>

#include <Eigen/Core>
#include <memory>
#include <string>

namespace aula::sim {

class SimView {
 public:
  // Opens a window ("Aula 3D view", of `window`'s size and place: Simulator.Window.*) looking at
  // `center_m` from a distance fitting `size_m`. Throws config::ConfigError when the module
  // cannot be loaded.
  SimView(const dart::simulation::WorldPtr& world, const Eigen::Vector3d& center_m, double size_m,
          const desktop::Placement& window);
  ~SimView();
  SimView(const SimView&) = delete;
  SimView& operator=(const SimView&) = delete;

  // Renders one frame; false once the window was closed.
  bool frame();
  // Saves the next rendered frame as a PNG.
  void captureNextFrame(const std::string& png_path);

 private:
  struct Module;
  std::unique_ptr<Module> module_;
  void* view_ = nullptr;
};

}  // namespace aula::sim

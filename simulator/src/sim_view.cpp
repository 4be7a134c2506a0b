#include "sim_view.hpp"

#include <aula/config/config.hpp>
#include <aula/config/paths.hpp>

#include <dlfcn.h>

#include <string>

namespace aula::sim {

// The view's code is a module (sim_view_osg.cpp): its functions, found once it is opened.
struct SimView::Module {
  void* (*open)(const dart::simulation::WorldPtr&, const Eigen::Vector3d&, double, const int (&)[4]) = nullptr;
  bool (*frame)(void*) = nullptr;
  void (*capture)(void*, const std::string&) = nullptr;
  void (*close)(void*) = nullptr;
};

namespace {

template <class Function>
void resolve(void* library, const char* name, const std::string& module, Function& function) {
  function = reinterpret_cast<Function>(dlsym(library, name));
  if (function == nullptr) throw config::ConfigError(module + " has no " + name);
}

}  // namespace

SimView::SimView(const dart::simulation::WorldPtr& world, const Eigen::Vector3d& center_m, double size_m,
                 const desktop::Placement& window)
    : module_(std::make_unique<Module>()) {
  const std::string module = config::libDir() + "/libaula_sim_view.so";
  void* library = dlopen(module.c_str(), RTLD_NOW | RTLD_LOCAL);  // kept open: OpenSceneGraph's globals live on
  if (library == nullptr) throw config::ConfigError(std::string("--gui: cannot load the 3D view: ") + dlerror());
  resolve(library, "aula_sim_view_open", module, module_->open);
  resolve(library, "aula_sim_view_frame", module, module_->frame);
  resolve(library, "aula_sim_view_capture", module, module_->capture);
  resolve(library, "aula_sim_view_close", module, module_->close);
  // Without a place from the launcher, the view's old corner (the window manager may move it).
  const desktop::Point corner = window.frame_corner.value_or(desktop::Point{50, 50});
  const int frame[4] = {corner.x_px, corner.y_px, window.size.width_px, window.size.height_px};
  view_ = module_->open(world, center_m, size_m, frame);
}

SimView::~SimView() {
  if (view_ != nullptr) module_->close(view_);
}

bool SimView::frame() { return module_->frame(view_); }

void SimView::captureNextFrame(const std::string& png_path) { module_->capture(view_, png_path); }

}  // namespace aula::sim

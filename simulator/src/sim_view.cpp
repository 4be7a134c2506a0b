#include "sim_view.hpp"

#include <aula/config/config.hpp>

#include <dlfcn.h>

#include <filesystem>
#include <string>

namespace aula::sim {

// The view's code is a module (sim_view_osg.cpp): its functions, found once it is opened.
struct SimView::Module {
  void* (*open)(const dart::simulation::WorldPtr&, const Eigen::Vector3d&, double) = nullptr;
  bool (*frame)(void*) = nullptr;
  void (*capture)(void*, const std::string&) = nullptr;
  void (*close)(void*) = nullptr;
};

namespace {

template <class Function>
void find(void* library, const char* name, const std::string& module, Function& function) {
  function = reinterpret_cast<Function>(dlsym(library, name));
  if (function == nullptr) throw config::ConfigError(module + " has no " + name);
}

}  // namespace

SimView::SimView(const dart::simulation::WorldPtr& world, const Eigen::Vector3d& center_m, double size_m)
    : module_(std::make_unique<Module>()) {
  std::error_code error;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  const std::string module = (self.parent_path().parent_path() / "lib" / "aula" / "libaula_sim_view.so").string();
  void* library = dlopen(module.c_str(), RTLD_NOW | RTLD_LOCAL);  // kept open: OpenSceneGraph's globals live on
  if (library == nullptr) throw config::ConfigError(std::string("--gui: cannot load the 3D view: ") + dlerror());
  find(library, "aula_sim_view_open", module, module_->open);
  find(library, "aula_sim_view_frame", module, module_->frame);
  find(library, "aula_sim_view_capture", module, module_->capture);
  find(library, "aula_sim_view_close", module, module_->close);
  view_ = module_->open(world, center_m, size_m);
}

SimView::~SimView() {
  if (view_ != nullptr) module_->close(view_);
}

bool SimView::frame() { return module_->frame(view_); }

void SimView::captureNextFrame(const std::string& png_path) { module_->capture(view_, png_path); }

}  // namespace aula::sim

// aula-sim --gui's 3D view, a module of its own (lib/aula/libaula_sim_view.so) that SimView opens
// only when a window is asked for: OpenSceneGraph, OpenGL and X11 are 17 libraries whose loading
// and symbol binding cost every headless simulator about 10 ms of its start-up.
#include <dart/dynamics/BodyNode.hpp>
#include <dart/dynamics/ShapeNode.hpp>
#include <dart/dynamics/Skeleton.hpp>
#include <dart/gui/osg/Viewer.hpp>
#include <dart/gui/osg/WorldNode.hpp>
#include <dart/simulation/World.hpp>

#include <osgGA/TrackballManipulator>
#include <osgViewer/GraphicsWindow>

#include <Eigen/Core>

namespace {

struct View {
  ::osg::ref_ptr<dart::gui::osg::WorldNode> node;
  ::osg::ref_ptr<dart::gui::osg::Viewer> viewer;
};

}  // namespace

#define AULA_MODULE_API extern "C" __attribute__((visibility("default")))

// `window`: x, y of the frame's top-left corner, width, height (px).
AULA_MODULE_API void* aula_sim_view_open(const dart::simulation::WorldPtr& world, const Eigen::Vector3d& center_m,
                                         double size_m, const int (&window)[4]) {
  // Colours: buildings and furniture light grey, robots orange.
  for (std::size_t i = 0; i < world->getNumSkeletons(); ++i) {
    auto skeleton = world->getSkeleton(i);
    const bool statics = skeleton->getName().rfind("statics", 0) == 0;
    for (std::size_t b = 0; b < skeleton->getNumBodyNodes(); ++b) {
      // By index: getShapeNodesWith() is deprecated in DART 6.13 (eachShapeNodeWith is not in 6.12).
      auto* body = skeleton->getBodyNode(b);
      for (std::size_t n = 0; n < body->getNumShapeNodes(); ++n) {
        if (auto* visual = body->getShapeNode(n)->getVisualAspect()) {
          visual->setColor(statics ? Eigen::Vector3d(0.75, 0.75, 0.78) : Eigen::Vector3d(0.95, 0.55, 0.1));
        }
      }
    }
  }
  auto* view = new View;
  view->node = new dart::gui::osg::WorldNode(world);
  view->node->simulate(false);
  view->viewer = new dart::gui::osg::Viewer;
  view->viewer->allowSimulation(false);
  view->viewer->addWorldNode(view->node);
  view->viewer->setUpViewInWindow(window[0], window[1], window[2], window[3]);
  view->viewer->getCameraManipulator()->setHomePosition(
      ::osg::Vec3d(center_m.x(), center_m.y() - 0.9 * size_m, 0.8 * size_m),
      ::osg::Vec3d(center_m.x(), center_m.y(), 0.0), ::osg::Vec3d(0, 0, 1));
  view->viewer->setCameraManipulator(view->viewer->getCameraManipulator());
  // One thread: the draw callback that writes a screenshot reads the file name captureScreen()
  // sets; with OSG's default threads it may read it mid-assignment (a garbage file name, no
  // picture, seen on a loaded machine).
  view->viewer->setThreadingModel(::osgViewer::ViewerBase::SingleThreaded);
  view->viewer->realize();
  ::osgViewer::ViewerBase::Windows windows;
  view->viewer->getWindows(windows);
  for (auto* shown : windows) shown->setWindowName("Aula 3D view");  // found by its title, like the others
  return view;
}

AULA_MODULE_API bool aula_sim_view_frame(void* opened) {
  auto* view = static_cast<View*>(opened);
  if (view->viewer->done()) return false;
  view->viewer->frame();
  return !view->viewer->done();
}

AULA_MODULE_API void aula_sim_view_capture(void* opened, const std::string& png_path) {
  static_cast<View*>(opened)->viewer->captureScreen(png_path);
}

AULA_MODULE_API void aula_sim_view_close(void* opened) { delete static_cast<View*>(opened); }

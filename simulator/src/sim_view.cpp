#include "sim_view.hpp"

#include <dart/dynamics/BodyNode.hpp>
#include <dart/dynamics/ShapeNode.hpp>
#include <dart/dynamics/Skeleton.hpp>
#include <dart/gui/osg/Viewer.hpp>
#include <dart/gui/osg/WorldNode.hpp>

#include <osgGA/TrackballManipulator>

namespace aula::sim {

struct SimView::Impl {
  ::osg::ref_ptr<dart::gui::osg::WorldNode> node;
  ::osg::ref_ptr<dart::gui::osg::Viewer> viewer;
};

SimView::SimView(const dart::simulation::WorldPtr& world, const Eigen::Vector3d& center_m, double size_m)
    : impl_(std::make_unique<Impl>()) {
  // Colours: buildings and furniture light grey, robots orange.
  for (std::size_t i = 0; i < world->getNumSkeletons(); ++i) {
    auto skeleton = world->getSkeleton(i);
    const bool statics = skeleton->getName().rfind("statics", 0) == 0;
    for (std::size_t b = 0; b < skeleton->getNumBodyNodes(); ++b) {
      for (auto* node : skeleton->getBodyNode(b)->getShapeNodesWith<dart::dynamics::VisualAspect>()) {
        node->getVisualAspect()->setColor(statics ? Eigen::Vector3d(0.75, 0.75, 0.78)
                                                  : Eigen::Vector3d(0.95, 0.55, 0.1));
      }
    }
  }
  impl_->node = new dart::gui::osg::WorldNode(world);
  impl_->node->simulate(false);
  impl_->viewer = new dart::gui::osg::Viewer;
  impl_->viewer->allowSimulation(false);
  impl_->viewer->addWorldNode(impl_->node);
  impl_->viewer->setUpViewInWindow(50, 50, 1024, 768);
  impl_->viewer->getCameraManipulator()->setHomePosition(
      ::osg::Vec3d(center_m.x(), center_m.y() - 0.9 * size_m, 0.8 * size_m),
      ::osg::Vec3d(center_m.x(), center_m.y(), 0.0), ::osg::Vec3d(0, 0, 1));
  impl_->viewer->setCameraManipulator(impl_->viewer->getCameraManipulator());
  impl_->viewer->realize();
}

SimView::~SimView() = default;

bool SimView::frame() {
  if (impl_->viewer->done()) return false;
  impl_->viewer->frame();
  return !impl_->viewer->done();
}

}  // namespace aula::sim

namespace aula::sim {
void SimView::captureNextFrame(const std::string& png_path) { impl_->viewer->captureScreen(png_path); }
}  // namespace aula::sim

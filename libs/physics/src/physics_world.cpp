#include "aula/physics/physics_world.hpp"

#include <dart/collision/CollisionGroup.hpp>
#include <dart/collision/CollisionObject.hpp>
#include <dart/collision/CollisionResult.hpp>
#include <dart/collision/bullet/BulletCollisionDetector.hpp>
#include <dart/constraint/ConstraintSolver.hpp>
#include <dart/dynamics/BodyNode.hpp>
#include <dart/dynamics/BoxShape.hpp>
#include <dart/dynamics/CylinderShape.hpp>
#include <dart/dynamics/Inertia.hpp>
#include <dart/dynamics/MeshShape.hpp>
#include <dart/dynamics/PlanarJoint.hpp>
#include <dart/dynamics/ShapeNode.hpp>
#include <dart/dynamics/WeldJoint.hpp>

#include <assimp/scene.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace aula::physics {
namespace {

using dart::dynamics::BodyNode;
using dart::dynamics::BoxShape;
using dart::dynamics::CollisionAspect;
using dart::dynamics::CylinderShape;
using dart::dynamics::DynamicsAspect;
using dart::dynamics::ShapePtr;
using dart::dynamics::VisualAspect;

// Servo limits: how hard a robot's motors can push, as accelerations of its own mass and
// inertia. Finite limits are what make contacts win over commands (an unlimited servo drives
// through walls).
constexpr double kMaxLinearAccel = 10.0;   // m/s^2
constexpr double kMaxAngularAccel = 30.0;  // rad/s^2
// Sub-stepping keeps fast robots from sinking into (or tunnelling through) thin walls: a
// physics step is split so that no robot travels more than this per sub-step.
constexpr double kMaxTravelPerSubstep = 0.01;  // m
// Coulomb friction of every contact (DART takes the smaller of the two shapes' values). Low, so
// that a robot pushing against a wall at an angle slides along it, as bumpers and car bodies do.
constexpr double kFriction = 0.3;

ShapePtr makeShape(const world::Shape& s) {
  if (s.kind == world::ShapeKind::Cylinder) return std::make_shared<CylinderShape>(s.radius_m, s.length_m);
  return std::make_shared<BoxShape>(s.box_size_m);
}

// A static mesh's collision triangles are cut into tiles of this size (by each triangle's centre),
// each one shape of the near set: a robot in a 500 m mesh city meets the triangles of the tiles
// around it, not the whole city (bench/mesh_city.sh).
constexpr double kMeshTile_m = 10.0;

// DART's MeshShape of triangles given as corner triples (3 per triangle), in the frame it is
// placed in. DART reads an assimp scene (Bullet takes its meshes' triangles as they are, without
// node transforms): one mesh, one default material; the MeshShape frees it (aiReleaseImport
// deletes a scene it did not import).
std::shared_ptr<dart::dynamics::MeshShape> meshShapeOf(const std::vector<Eigen::Vector3d>& corners) {
  auto* mesh = new aiMesh;
  mesh->mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
  mesh->mNumVertices = static_cast<unsigned>(corners.size());
  mesh->mVertices = new aiVector3D[corners.size()];
  for (std::size_t i = 0; i < corners.size(); ++i) {
    mesh->mVertices[i] = aiVector3D(static_cast<ai_real>(corners[i].x()), static_cast<ai_real>(corners[i].y()),
                                    static_cast<ai_real>(corners[i].z()));
  }
  mesh->mNumFaces = static_cast<unsigned>(corners.size() / 3);
  mesh->mFaces = new aiFace[mesh->mNumFaces];
  for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
    mesh->mFaces[f].mNumIndices = 3;
    mesh->mFaces[f].mIndices = new unsigned[3]{3 * f, 3 * f + 1, 3 * f + 2};
  }
  auto* scene = new aiScene;
  scene->mNumMeshes = 1;
  scene->mMeshes = new aiMesh*[1]{mesh};
  scene->mNumMaterials = 1;
  scene->mMaterials = new aiMaterial*[1]{new aiMaterial};
  scene->mRootNode = new aiNode;
  scene->mRootNode->mNumMeshes = 1;
  scene->mRootNode->mMeshes = new unsigned[1]{0};
  return std::make_shared<dart::dynamics::MeshShape>(Eigen::Vector3d::Ones(), scene);
}

// The heights any robot's body spans (world z): a planar robot touches nothing outside them.
std::pair<double, double> robotsZBand(const world::WorldSpec& spec) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const auto& r : spec.robots) {
    const double z = r.pose.translation().z() + r.shape_offset.translation().z();
    const double half = r.shape.kind == world::ShapeKind::Box ? r.shape.box_size_m.z() / 2 : r.shape.length_m / 2;
    lo = std::min(lo, z - half);
    hi = std::max(hi, z + half);
  }
  return {lo, hi};
}

}  // namespace

struct PhysicsWorld::Robot {
  world::RobotSpec spec;
  dart::dynamics::SkeletonPtr skeleton;
  dart::dynamics::PlanarJoint* joint = nullptr;
  BodyNode* body = nullptr;
  double v = 0, w = 0, l = 0;  // held body-frame command
  double reach_m = 0;          // footprint radius about the body origin
  Eigen::Vector2d anchor_m = Eigen::Vector2d::Constant(1e300);  // position at the last near-set rebuild
};

struct PhysicsWorld::StaticPrimitive {
  std::string name;
  ShapePtr shape;
  Eigen::Isometry3d pose;
  Eigen::Vector2d lo, hi;  // footprint bounds
};

PhysicsWorld::PhysicsWorld(const world::WorldSpec& spec, double step_s) {
  if (!(step_s > 0)) throw world::WorldError("physics step must be > 0");
  step_us_ = std::max<int64_t>(1, std::llround(step_s * 1e6));
  world_ = dart::simulation::World::create(spec.name.empty() ? "aula" : spec.name);
  world_->setTimeStep(step_us_ / 1e6);
  world_->getConstraintSolver()->setCollisionDetector(dart::collision::BulletCollisionDetector::create());

  // All static geometry as visuals (for a viewer) in one immobile skeleton; the collision
  // detector sees only the near set, kept in a second immobile skeleton.
  auto statics = dart::dynamics::Skeleton::create("statics");
  auto* ground = statics->createJointAndBodyNodePair<dart::dynamics::WeldJoint>().second;
  // A mesh's floor would hold every robot in contact (its bumper always pressed), as a ground
  // plane would: a triangle counts only where it reaches above the robots' bottoms (1 cm up) and
  // below their tops.
  const auto [robots_bottom_m, robots_top_m] = robotsZBand(spec);
  constexpr double kFloorClearance_m = 0.01;
  for (const auto& o : spec.statics) {
    if (o.shape.kind == world::ShapeKind::Mesh) {
      const world::TriangleMesh& mesh = *o.shape.mesh;
      std::map<std::pair<long, long>, std::vector<Eigen::Vector3d>> tiles;
      for (const auto& t : mesh.triangles) {
        const Eigen::Vector3d a = o.pose * mesh.vertices_m[t[0]], b = o.pose * mesh.vertices_m[t[1]],
                              c = o.pose * mesh.vertices_m[t[2]];
        if (std::max({a.z(), b.z(), c.z()}) <= robots_bottom_m + kFloorClearance_m) continue;
        if (std::min({a.z(), b.z(), c.z()}) >= robots_top_m) continue;
        const Eigen::Vector3d centre = (a + b + c) / 3;
        auto& tile = tiles[{std::lround(std::floor(centre.x() / kMeshTile_m)), std::lround(std::floor(centre.y() / kMeshTile_m))}];
        tile.insert(tile.end(), {a, b, c});
      }
      for (auto& [cell, corners] : tiles) {
        StaticPrimitive p;
        p.name = o.name + "@" + std::to_string(cell.first) + "," + std::to_string(cell.second);
        p.shape = meshShapeOf(corners);
        p.pose = Eigen::Isometry3d::Identity();
        p.lo = p.hi = corners.front().head<2>();
        for (const auto& v : corners) p.lo = p.lo.cwiseMin(v.head<2>()), p.hi = p.hi.cwiseMax(v.head<2>());
        statics_.push_back(p);
      }
      // The whole mesh, floor and all, for a viewer.
      std::vector<Eigen::Vector3d> corners;
      corners.reserve(3 * mesh.triangles.size());
      for (const auto& t : mesh.triangles) corners.insert(corners.end(), {mesh.vertices_m[t[0]], mesh.vertices_m[t[1]], mesh.vertices_m[t[2]]});
      auto* node = ground->createShapeNodeWith<VisualAspect>(meshShapeOf(corners), o.name);
      node->setRelativeTransform(o.pose);
      continue;
    }
    StaticPrimitive p;
    p.name = o.name;
    p.shape = makeShape(o.shape);
    p.pose = o.pose;
    const Eigen::Vector2d c = o.pose.translation().head<2>();
    Eigen::Vector2d half;
    if (o.shape.kind == world::ShapeKind::Cylinder) {
      half = Eigen::Vector2d::Constant(o.shape.radius_m);
    } else {
      // Bounds of the rotated box's footprint (any rotation: use the 3D box's extent).
      const Eigen::Matrix3d r = o.pose.linear().cwiseAbs();
      half = (r * (o.shape.box_size_m / 2)).head<2>();
    }
    p.lo = c - half;
    p.hi = c + half;
    statics_.push_back(p);
    auto* node = ground->createShapeNodeWith<VisualAspect>(p.shape, o.name);
    node->setRelativeTransform(o.pose);
  }
  statics->setMobile(false);
  world_->addSkeleton(statics);
  auto near = dart::dynamics::Skeleton::create("statics_near");
  near_body_ = near->createJointAndBodyNodePair<dart::dynamics::WeldJoint>().second;
  near->setMobile(false);
  world_->addSkeleton(near);

  for (const auto& r : spec.robots) {
    const std::string where = spec.source_path + ": robot '" + r.name + "'";
    if (r.shape.kind == world::ShapeKind::Box && (r.shape.box_size_m.array() <= 0).any()) {
      throw world::WorldError(where + ": box size must be positive");
    }
    if (r.shape.kind == world::ShapeKind::Cylinder && !(r.shape.radius_m > 0 && r.shape.length_m > 0)) {
      throw world::WorldError(where + ": cylinder radius and length must be positive");
    }
    Robot robot;
    robot.spec = r;
    robot.skeleton = dart::dynamics::Skeleton::create(r.name);
    dart::dynamics::PlanarJoint::Properties joint_props;
    joint_props.mName = r.name + "_planar";
    auto pair = robot.skeleton->createJointAndBodyNodePair<dart::dynamics::PlanarJoint>(
        nullptr, joint_props, BodyNode::AspectProperties(r.name + "_body"));
    robot.joint = pair.first;
    robot.body = pair.second;
    robot.joint->setXYPlane();
    // The joint frame sits at the robot's initial height; x, y, yaw are its coordinates.
    Eigen::Isometry3d lift = Eigen::Isometry3d::Identity();
    lift.translation().z() = r.pose.translation().z();
    robot.joint->setTransformFromParentBodyNode(lift);

    auto shape = makeShape(r.shape);
    auto* node = robot.body->createShapeNodeWith<VisualAspect, CollisionAspect, DynamicsAspect>(shape, r.name + "_shape");
    node->setRelativeTransform(r.shape_offset);
    node->getDynamicsAspect()->setFrictionCoeff(kFriction);
    const Eigen::Matrix3d moment = shape->computeInertia(r.mass_kg);
    robot.body->setInertia(dart::dynamics::Inertia(r.mass_kg, r.shape_offset.translation(),
                                                    r.shape_offset.linear() * moment * r.shape_offset.linear().transpose()));

    robot.joint->setActuatorType(dart::dynamics::Joint::SERVO);
    const double force = r.mass_kg * kMaxLinearAccel;
    const double torque = std::max(1e-3, moment(2, 2) * kMaxAngularAccel);
    robot.joint->setForceUpperLimit(0, force);
    robot.joint->setForceLowerLimit(0, -force);
    robot.joint->setForceUpperLimit(1, force);
    robot.joint->setForceLowerLimit(1, -force);
    robot.joint->setForceUpperLimit(2, torque);
    robot.joint->setForceLowerLimit(2, -torque);
    if (r.shape.kind == world::ShapeKind::Cylinder) {
      robot.reach_m = r.shape_offset.translation().head<2>().norm() + r.shape.radius_m;
    } else {
      robot.reach_m = r.shape_offset.translation().head<2>().norm() + r.shape.box_size_m.head<2>().norm() / 2;
    }
    robots_.push_back(std::move(robot));
    world_->addSkeleton(robots_.back().skeleton);
    setRobotPose(static_cast<int>(robots_.size()) - 1, r.pose.translation().x(), r.pose.translation().y(),
                 world::yawOf(r.pose));
  }
}

PhysicsWorld::~PhysicsWorld() = default;

int PhysicsWorld::robotCount() const { return static_cast<int>(robots_.size()); }

int PhysicsWorld::robotIndex(const std::string& name) const {
  for (size_t i = 0; i < robots_.size(); ++i) {
    if (robots_[i].spec.name == name) return static_cast<int>(i);
  }
  return -1;
}

const world::RobotSpec& PhysicsWorld::robotSpec(int robot) const { return robots_.at(robot).spec; }

void PhysicsWorld::commandVelocity(int robot, double v_mps, double w_radps, double lateral_mps) {
  Robot& r = robots_.at(robot);
  r.v = v_mps;
  r.w = w_radps;
  r.l = lateral_mps;
}

RobotState PhysicsWorld::robotState(int robot) const {
  const Robot& r = robots_.at(robot);
  RobotState s;
  const Eigen::Vector3d q = r.joint->getPositions();
  const Eigen::Vector3d dq = r.joint->getVelocities();
  s.position_m = Eigen::Vector3d(q[0], q[1], r.joint->getTransformFromParentBodyNode().translation().z());
  // DART's unbounded joint angle as a heading in (-pi, pi]: atan2's rounding is part of every
  // recorded run (geometry::wrapAngle rounds differently and changes the Ackermann runs).
  s.yaw_rad = std::atan2(std::sin(q[2]), std::cos(q[2]));
  s.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(s.yaw_rad, Eigen::Vector3d::UnitZ()));
  s.velocity_mps = Eigen::Vector2d(dq[0], dq[1]);
  s.yaw_rate_radps = dq[2];
  return s;
}

ContactState PhysicsWorld::contact(int robot) const {
  const Robot& r = robots_.at(robot);
  ContactState c;
  const auto& result = world_->getLastCollisionResult();
  if (!result.inCollision(r.body)) return c;
  c.in_contact = true;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  const Eigen::Isometry3d to_body = r.body->getWorldTransform().inverse();
  for (const auto& contact : result.getContacts()) {
    auto belongs = [&](const dart::collision::CollisionObject* o) {
      const auto* node = o->getShapeFrame()->asShapeNode();
      return node != nullptr && node->getBodyNodePtr().get() == r.body;
    };
    if (!belongs(contact.collisionObject1) && !belongs(contact.collisionObject2)) continue;
    sum += to_body * contact.point;
    ++c.contact_points;
  }
  if (c.contact_points > 0) {
    sum /= c.contact_points;
    c.bearing_rad = std::atan2(sum.y(), sum.x());
  }
  return c;
}

void PhysicsWorld::setRobotPose(int robot, double x_m, double y_m, double yaw_rad) {
  Robot& r = robots_.at(robot);
  r.joint->setPositions(Eigen::Vector3d(x_m, y_m, yaw_rad));
  r.joint->setVelocities(Eigen::Vector3d::Zero());
  r.joint->setCommands(Eigen::Vector3d::Zero());
  r.v = r.w = r.l = 0;
  refreshNearStatics(true);
}

void PhysicsWorld::refreshNearStatics(bool force) {
  bool moved = force;
  for (const auto& r : robots_) {
    const Eigen::Vector3d q = r.joint->getPositions();
    moved = moved || (Eigen::Vector2d(q[0], q[1]) - r.anchor_m).norm() > kNearRefresh_m;
  }
  if (!moved) return;
  std::vector<int> wanted;
  for (auto& r : robots_) {
    const Eigen::Vector3d q = r.joint->getPositions();
    r.anchor_m = Eigen::Vector2d(q[0], q[1]);
  }
  for (size_t i = 0; i < statics_.size(); ++i) {
    for (const auto& r : robots_) {
      const double reach = r.reach_m + kNearMargin_m;
      const Eigen::Vector2d lo = r.anchor_m.array() - reach, hi = r.anchor_m.array() + reach;
      if ((statics_[i].lo.array() <= hi.array()).all() && (statics_[i].hi.array() >= lo.array()).all()) {
        wanted.push_back(static_cast<int>(i));
        break;
      }
    }
  }
  if (wanted == near_set_) return;
  near_set_ = std::move(wanted);
  // Detach the old shapes from the collision group while they still exist: DART 6.12 would
  // otherwise destroy their collision objects after the shape frames are gone (use after free).
  // Then remove them one by one from a list taken first: DART 6.13's removeAllShapeNodes()
  // removes while it iterates and leaves every other node (on Debian 13 the old shapes piled up
  // on the body, each new one with a duplicate name that DART renamed and printed).
  const auto group = world_->getConstraintSolver()->getCollisionGroup();
  // By index: getShapeNodes() is deprecated in DART 6.13 (eachShapeNode is not in 6.12).
  std::vector<dart::dynamics::ShapeNode*> old_nodes;
  for (std::size_t n = 0; n < near_body_->getNumShapeNodes(); ++n) old_nodes.push_back(near_body_->getShapeNode(n));
  for (auto* node : old_nodes) {
    group->removeShapeFrame(node);
    node->remove();
  }
  for (const int i : near_set_) {
    auto* node = near_body_->createShapeNodeWith<CollisionAspect, DynamicsAspect>(statics_[i].shape, statics_[i].name);
    node->setRelativeTransform(statics_[i].pose);
    node->getDynamicsAspect()->setFrictionCoeff(kFriction);
    group->addShapeFrame(node);  // explicit: the group does not reliably pick up new nodes
  }
}

void PhysicsWorld::reset() {
  world_->reset();
  for (size_t i = 0; i < robots_.size(); ++i) {
    const auto& p = robots_[i].spec.pose;
    setRobotPose(static_cast<int>(i), p.translation().x(), p.translation().y(), world::yawOf(p));
  }
  time_us_ = 0;
}

void PhysicsWorld::step() {
  // Split the step when a robot is (or is commanded to be) fast.
  double fastest = 0.0;
  for (const auto& r : robots_) {
    const Eigen::Vector3d dq = r.joint->getVelocities();
    fastest = std::max({fastest, std::hypot(dq[0], dq[1]), std::hypot(r.v, r.l)});
  }
  const double dt = step_us_ / 1e6;
  const int substeps = std::clamp(static_cast<int>(std::ceil(fastest * dt / kMaxTravelPerSubstep)), 1, 100);
  if (substeps > 1) world_->setTimeStep(dt / substeps);
  for (int k = 0; k < substeps; ++k) {
    refreshNearStatics(false);
    for (auto& r : robots_) {
      const double yaw = r.joint->getPositions()[2];
      const double c = std::cos(yaw), s = std::sin(yaw);
      // The planar joint's x/y rates are in the world frame.
      r.joint->setCommand(0, r.v * c - r.l * s);
      r.joint->setCommand(1, r.v * s + r.l * c);
      r.joint->setCommand(2, r.w);
    }
    world_->step();
  }
  if (substeps > 1) world_->setTimeStep(dt);
  time_us_ += step_us_;
}

}  // namespace aula::physics

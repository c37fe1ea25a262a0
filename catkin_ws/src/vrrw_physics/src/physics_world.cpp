#include <vrrw_physics/joint_row_solver.h>
#include <vrrw_physics/multibody_world.h>
#include <vrrw_physics/physics_world.h>
#include <vrrw_physics/self_collision_filter.h>

#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>
#include <BulletCollision/CollisionDispatch/btCollisionDispatcher.h>
#include <BulletCollision/CollisionDispatch/btDefaultCollisionConfiguration.h>
#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyConstraintSolver.h>
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>

#include <urdf_parser/urdf_parser.h>

#include <cmath>
#include <sstream>

#include "bullet_conversions.h"

namespace vrrw_physics
{
namespace
{
/// Initial positions of every joint of `robot` (mimic joints from their masters).
std::vector<double> initialPositions(const ArticulatedRobot& robot, const vrrw_scene::Robot& spec)
{
  const auto& joints = robot.joints();
  std::vector<double> q(joints.size(), 0.0);
  for (std::size_t j = 0; j < joints.size(); ++j)
  {
    const auto it = spec.initial_positions.find(joints[j].name);
    if (it != spec.initial_positions.end())
      q[j] = it->second;
  }
  return robot.withMimics(q);
}
}  // namespace

DriveScheme parseDriveScheme(const std::string& text)
{
  if (text == "constraint")
    return DriveScheme::Constraint;
  if (text == "stable_pd")
    return DriveScheme::StablePd;
  throw std::invalid_argument("drive scheme '" + text + "': expected constraint or stable_pd");
}

PhysicsWorld::PhysicsWorld(const vrrw_scene::Scene& scene, const WorldOptions& options)
  : options_(options), scene_(scene)
{
  if (!(options_.dt > 0.0) || !std::isfinite(options_.dt))
    throw std::runtime_error("dt: must be a positive number of seconds");
  if (!(options_.target_timeout >= 0.0) || !(options_.hand_timeout >= 0.0))
    throw std::runtime_error("target_timeout, hand_timeout: must be >= 0 s (0: never)");
  build();
  initial_ = snapshot();
  last_good_ = initial_;
}

PhysicsWorld::~PhysicsWorld()
{
  tearDown();
}

void PhysicsWorld::build()
{
  createBulletWorld();
  operator_ = std::make_unique<OperatorInput>(*world_, time_, options_.dt, options_.hand_timeout);
  addRobots(scene_);
  addObjects(scene_);
  if (options_.floor)
    addFloor();
}

void PhysicsWorld::tearDown()
{
  operator_.reset();
  if (floor_)
    world_->removeRigidBody(floor_.get());
  objects_.clear();
  robots_.clear();
  floor_.reset();
  floor_shape_.reset();
  world_.reset();
  solver_.reset();
  broadphase_.reset();
  self_collision_filter_.reset();
  dispatcher_.reset();
  collision_config_.reset();
}

void PhysicsWorld::createBulletWorld()
{
  collision_config_ = std::make_unique<btDefaultCollisionConfiguration>();
  dispatcher_ = std::make_unique<btCollisionDispatcher>(collision_config_.get());
  broadphase_ = std::make_unique<btDbvtBroadphase>();
  if (options_.bullet_reference)
  {
    solver_ = std::make_unique<btMultiBodyConstraintSolver>();
    world_ = std::make_unique<btMultiBodyDynamicsWorld>(dispatcher_.get(), broadphase_.get(), solver_.get(),
                                                        collision_config_.get());
  }
  else
  {
    self_collision_filter_ = std::make_unique<SelfCollisionFilter>();
    broadphase_->getOverlappingPairCache()->setOverlapFilterCallback(self_collision_filter_.get());
    solver_ = std::make_unique<JointRowSolver>(options_.joint_rows_last);
    world_ = std::make_unique<MultiBodyWorld>(dispatcher_.get(), broadphase_.get(), solver_.get(),
                                              collision_config_.get());
  }
  world_->setGravity(toBullet(options_.gravity));
  world_->getSolverInfo().m_numIterations = options_.solver_iterations;
  world_->getSolverInfo().m_numNonContactInnerIterations = options_.solver_inner_iterations;
  world_->getSolverInfo().m_leastSquaresResidualThreshold = btScalar(options_.solver_residual);
  world_->getSolverInfo().m_timeStep = btScalar(options_.dt);
}

void PhysicsWorld::addRobots(const vrrw_scene::Scene& scene)
{
  if (scene.robots.empty())
    return;
  const urdf::ModelInterfaceSharedPtr model = urdf::parseURDF(scene.urdf);
  if (!model)
    throw std::runtime_error("scene " + scene.name + ": combined URDF does not parse");
  LinkMaterial material;
  material.friction = options_.link_friction;
  const bool constraints = options_.drive_scheme == DriveScheme::Constraint;
  for (const vrrw_scene::Robot& spec : scene.robots)
  {
    RobotEntry e;
    e.spec = spec;
    const std::string base = spec.base_link.empty() ? spec.name + "_base_link" : spec.base_link;
    e.robot = std::make_unique<ArticulatedRobot>(*model, spec.name, base, material);
    e.gravity_compensation = options_.gravity_compensation;
    const std::vector<double> q = initialPositions(*e.robot, spec);
    e.robot->setState(q, std::vector<double>(q.size(), 0.0));
    for (std::size_t j = 0; j < q.size(); ++j)
      if (e.robot->joints()[j].drive >= 0)
        e.robot->drives()[std::size_t(e.robot->joints()[j].drive)]->setTarget(q[j], 0.0);
    e.robot->addToWorld(world_.get(), constraints);
    if (!options_.bullet_reference && options_.joint_space_dynamics)
      static_cast<MultiBodyWorld*>(world_.get())->setJointSpaceDynamics(e.robot->body(), &e.robot->response());
    if (!constraints)
      e.stable_pd = std::make_unique<StablePd>(*e.robot);
    e.drives = std::make_unique<RobotDrives>(spec, *e.robot, options_.mode, options_.max_joint_speed);
    operator_->addRobot(e.robot.get(), spec.name, spec.tcp_link.empty() ? spec.name + "_tool0" : spec.tcp_link);
    robots_.push_back(std::move(e));
  }
}

void PhysicsWorld::addObjects(const vrrw_scene::Scene& scene)
{
  for (const vrrw_scene::Object& spec : scene.objects)
  {
    objects_.push_back(std::make_unique<RigidObject>(spec));
    objects_.back()->addToWorld(world_.get());
    operator_->addObject(objects_.back().get());
  }
}

void PhysicsWorld::addFloor()
{
  // A slab rather than a plane: a plane's bounds would overlap every link in the broadphase.
  constexpr double kHalfThickness = 0.5;
  floor_shape_ = std::make_unique<btBoxShape>(
      btVector3(btScalar(kWorldExtent), btScalar(kWorldExtent), btScalar(kHalfThickness)));
  floor_shape_->setMargin(btScalar(0.001));
  btRigidBody::btRigidBodyConstructionInfo info(0, nullptr, floor_shape_.get());
  info.m_startWorldTransform.setIdentity();
  info.m_startWorldTransform.setOrigin(btVector3(0, 0, btScalar(-kHalfThickness)));
  info.m_friction = btScalar(0.8);
  floor_ = std::make_unique<btRigidBody>(info);
  world_->addRigidBody(floor_.get(), int(btBroadphaseProxy::StaticFilter), kMovableObjectGroup);
}

void PhysicsWorld::applyJointTorques()
{
  for (RobotEntry& e : robots_)
  {
    const JointMatrix& inertia = e.robot->updateDynamics();
    e.robot->followMasters();
    e.robot->clearFeedForward();
    std::vector<double> external =
        e.robot->gravityTorques(options_.gravity, options_.payload_compensation ? e.held : std::vector<PointLoad>());
    if (e.gravity_compensation)
      for (std::size_t j = 0; j < external.size(); ++j)
      {
        e.robot->addJointTorque(j, -external[j]);
        external[j] = 0.0;
      }
    if (e.stable_pd)
    {
      const std::vector<double> tau = e.stable_pd->torques(options_.dt, inertia, external);
      for (std::size_t j = 0; j < tau.size(); ++j)
        if (tau[j] != 0.0)
          e.robot->addJointTorque(j, tau[j]);
    }
  }
}

bool PhysicsWorld::step()
{
  if (stopped_)
    return false;
  for (RobotEntry& e : robots_)
    if (e.drives->holdIfStale(time_, options_.target_timeout))
    {
      std::ostringstream line;
      line << e.spec.name << ": no drive targets for " << options_.target_timeout
           << " s: holding the last target positions at rest";
      reports_.push_back(line.str());
    }
    else
      e.drives->advance(time_);
  applyJointTorques();
  for (std::string& line : operator_->apply())
    reports_.push_back(std::move(line));
  world_->getSolverInfo().m_numNonContactInnerIterations = robotInContact() ? options_.solver_inner_iterations : 1;
  world_->stepSimulation(btScalar(options_.dt), 0, btScalar(options_.dt));
  for (RobotEntry& e : robots_)
    e.robot->refreshFrames();
  findHeldObjects();
  time_ += options_.dt;
  ++steps_;
  const std::string why = insaneState();
  if (!why.empty())
  {
    recoverFrom(why);
    return false;
  }
  if (options_.snapshot_interval > 0 && steps_ % std::uint64_t(options_.snapshot_interval) == 0)
  {
    last_good_ = snapshot();
    if (!tripped_since_snapshot_)
      trips_in_a_row_ = 0;
    tripped_since_snapshot_ = false;
  }
  return true;
}

bool PhysicsWorld::robotInContact() const
{
  btDispatcher* dispatcher = world_->getDispatcher();
  for (int m = 0; m < dispatcher->getNumManifolds(); ++m)
  {
    const btPersistentManifold* manifold = dispatcher->getInternalManifoldPointer()[m];
    if (manifold->getNumContacts() > 0 && (btMultiBodyLinkCollider::upcast(manifold->getBody0()) ||
                                           btMultiBodyLinkCollider::upcast(manifold->getBody1())))
      return true;
  }
  return false;
}

std::vector<std::string> PhysicsWorld::takeReports()
{
  std::vector<std::string> out;
  out.swap(reports_);
  return out;
}

std::vector<std::string> PhysicsWorld::robotNames() const
{
  std::vector<std::string> names;
  for (const RobotEntry& e : robots_)
    names.push_back(e.spec.name);
  return names;
}

PhysicsWorld::RobotEntry& PhysicsWorld::entry(const std::string& robot)
{
  for (RobotEntry& e : robots_)
    if (e.spec.name == robot)
      return e;
  throw InputError("robot '" + robot + "': not in the scene");
}

const PhysicsWorld::RobotEntry& PhysicsWorld::entry(const std::string& robot) const
{
  return const_cast<PhysicsWorld*>(this)->entry(robot);
}

const ArticulatedRobot& PhysicsWorld::robot(const std::string& name) const
{
  return *entry(name).robot;
}

JointStates PhysicsWorld::jointStates(const std::string& robot) const
{
  const ArticulatedRobot& r = *entry(robot).robot;
  JointStates s;
  for (const SimJoint& j : r.joints())
    s.name.push_back(j.name);
  s.position = r.positions();
  s.velocity = r.velocities();
  s.effort = r.efforts(options_.dt);
  return s;
}

void PhysicsWorld::setDriveTargets(const std::string& robot, const std::vector<std::string>& joints,
                                   const std::vector<double>& positions, const std::vector<double>& velocities,
                                   const std::vector<double>& efforts)
{
  entry(robot).drives->setTargets(joints, positions, velocities, efforts, time_);
}

void PhysicsWorld::setDriveTargetsByIndex(const std::string& robot, const std::vector<std::size_t>& drives,
                                   const std::vector<double>& positions, const std::vector<double>& velocities,
                                   const std::vector<double>& efforts)
{
  entry(robot).drives->setTargetsByIndex(drives, positions, velocities, efforts, time_);
}

std::vector<std::size_t> PhysicsWorld::drives(const std::string& robot, const std::vector<std::string>& joints) const
{
  return entry(robot).drives->drives(joints);
}

void PhysicsWorld::setMode(const std::string& robot, DriveMode mode)
{
  entry(robot).drives->setMode(mode);
}

DriveMode PhysicsWorld::mode(const std::string& robot) const
{
  return entry(robot).drives->mode();
}

void PhysicsWorld::setGains(const std::string& robot, const std::vector<std::string>& joints,
                            const std::vector<double>& stiffness, const std::vector<double>& damping,
                            const std::vector<double>& max_force)
{
  entry(robot).drives->setGains(joints, stiffness, damping, max_force);
}

DriveGains PhysicsWorld::gains(const std::string& robot, const std::string& joint) const
{
  return entry(robot).drives->gains(joint);
}

void PhysicsWorld::setGravityCompensation(const std::string& robot, bool on)
{
  entry(robot).gravity_compensation = on;
}

std::vector<std::string> PhysicsWorld::heldObjects(const std::string& robot) const
{
  return entry(robot).held_objects;
}

std::vector<std::string> PhysicsWorld::objectNames() const
{
  std::vector<std::string> names;
  for (const auto& o : objects_)
    names.push_back(o->name());
  return names;
}

RigidObject& PhysicsWorld::object(const std::string& name) const
{
  for (const auto& o : objects_)
    if (o->name() == name)
      return *o;
  throw InputError("object '" + name + "': not in the scene");
}

Eigen::Isometry3d PhysicsWorld::objectPose(const std::string& name) const
{
  return object(name).pose();
}

void PhysicsWorld::setObjectPose(const std::string& name, const Eigen::Isometry3d& pose)
{
  RigidObject& o = object(name);
  if (o.fixed())
    throw InputError("object '" + name + "': fixed, it does not move");
  requireWorkspacePose(pose, "object '" + name + "'");
  o.setPose(pose);
}

Eigen::Isometry3d PhysicsWorld::framePose(const std::string& frame) const
{
  for (const RobotEntry& e : robots_)
    if (e.robot->hasLink(frame))
      return e.robot->linkPose(frame);
  return object(frame).pose();
}
}  // namespace vrrw_physics

#include <vrrw_physics/joint_row_solver.h>
#include <vrrw_physics/multibody_world.h>
#include <vrrw_physics/physics_world.h>
#include <vrrw_physics/self_collision_filter.h>

#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>
#include <BulletCollision/CollisionDispatch/btCollisionDispatcher.h>
#include <BulletCollision/CollisionDispatch/btDefaultCollisionConfiguration.h>
#include <BulletCollision/CollisionShapes/btSphereShape.h>
#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyConstraintSolver.h>
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>
#include <BulletDynamics/Featherstone/btMultiBodyFixedConstraint.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>
#include <LinearMath/btDefaultMotionState.h>

#include <urdf_parser/urdf_parser.h>

#include <cmath>
#include <sstream>
#include <sys/stat.h>

namespace vrrw_physics
{
namespace
{
bool fileExists(const std::string& path)
{
  struct stat info;
  return !path.empty() && stat(path.c_str(), &info) == 0;
}

std::string unprefixed(const std::string& joint, const std::string& robot)
{
  const std::string prefix = robot + "_";
  return joint.compare(0, prefix.size(), prefix) == 0 ? joint.substr(prefix.size()) : joint;
}

btTransform toBullet(const Eigen::Isometry3d& t)
{
  const Eigen::Quaterniond q(t.rotation());
  const Eigen::Vector3d p = t.translation();
  return btTransform(btQuaternion(btScalar(q.x()), btScalar(q.y()), btScalar(q.z()), btScalar(q.w())),
                     btVector3(btScalar(p.x()), btScalar(p.y()), btScalar(p.z())));
}

Eigen::Matrix4d toEigenTransform(const btTransform& t)
{
  Eigen::Isometry3d e = Eigen::Isometry3d::Identity();
  const btQuaternion q = t.getRotation();
  e.translate(Eigen::Vector3d(t.getOrigin().x(), t.getOrigin().y(), t.getOrigin().z()));
  e.rotate(Eigen::Quaterniond(q.w(), q.x(), q.y(), q.z()));
  return e.matrix();
}

void requireFinite(double value, const std::string& what)
{
  if (!std::isfinite(value))
    throw InputError(what + ": not finite");
}

DriveGainTable loadTables(const vrrw_scene::Robot& robot)
{
  DriveGainTable table;
  if (fileExists(robot.config_file))
    table = loadDriveGains(robot.config_file);
  if (fileExists(robot.gripper_config_file))
  {
    const DriveGainTable gripper = loadDriveGains(robot.gripper_config_file);
    for (const std::string& joint : robot.gripper_joints)
    {
      const std::string name = unprefixed(joint, robot.name);
      table.rigid[name] = gripper.gains(name, DriveMode::Rigid);
      table.compliant[name] = gripper.gains(name, DriveMode::Compliant);
    }
  }
  return table;
}
}  // namespace

PhysicsWorld::PhysicsWorld(const vrrw_scene::Scene& scene, const WorldOptions& options) : options_(options)
{
  if (!(options_.dt > 0.0) || !std::isfinite(options_.dt))
    throw std::runtime_error("dt: must be a positive number of seconds");
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
    solver_ = std::make_unique<JointRowSolver>();
    world_ = std::make_unique<MultiBodyWorld>(dispatcher_.get(), broadphase_.get(), solver_.get(),
                                              collision_config_.get());
  }
  const Eigen::Vector3d& g = options_.gravity;
  world_->setGravity(btVector3(btScalar(g.x()), btScalar(g.y()), btScalar(g.z())));
  world_->getSolverInfo().m_numIterations = options_.solver_iterations;
  world_->getSolverInfo().m_numNonContactInnerIterations = options_.solver_inner_iterations;
  world_->getSolverInfo().m_leastSquaresResidualThreshold = btScalar(options_.solver_residual);
  world_->getSolverInfo().m_timeStep = btScalar(options_.dt);

  if (!scene.robots.empty())
  {
    const urdf::ModelInterfaceSharedPtr model = urdf::parseURDF(scene.urdf);
    if (!model)
      throw std::runtime_error("scene " + scene.name + ": combined URDF does not parse");
    LinkMaterial material;
    material.friction = options_.link_friction;
    for (const vrrw_scene::Robot& spec : scene.robots)
    {
      RobotEntry e;
      e.spec = spec;
      const std::string base = spec.base_link.empty() ? spec.name + "_base_link" : spec.base_link;
      e.robot = std::make_unique<ArticulatedRobot>(*model, spec.name, base, material);
      e.table = loadTables(spec);
      e.gravity_compensation = options_.gravity_compensation;
      const auto& joints = e.robot->joints();
      e.arm_joint.assign(joints.size(), false);
      for (const std::string& arm : spec.arm_joints)
      {
        const int j = e.robot->jointIndex(arm);
        if (j < 0)
          throw std::runtime_error("robot " + spec.name + ": arm joint '" + arm + "' is not a movable joint");
        e.arm_joint[std::size_t(j)] = true;
      }
      std::vector<double> q(joints.size(), 0.0);
      for (std::size_t j = 0; j < joints.size(); ++j)
      {
        auto it = spec.initial_positions.find(joints[j].name);
        if (it == spec.initial_positions.end())
          it = spec.initial_positions.find(unprefixed(joints[j].name, spec.name));
        if (it != spec.initial_positions.end())
          q[j] = it->second;
      }
      q = e.robot->withMimics(q);
      e.robot->setState(q, std::vector<double>(q.size(), 0.0));
      for (std::size_t j = 0; j < joints.size(); ++j)
        if (joints[j].drive >= 0)
          e.robot->drives()[std::size_t(joints[j].drive)]->setTarget(q[j], 0.0);
      const bool constraints = options_.drive_scheme == DriveScheme::Constraint;
      e.robot->addToWorld(world_.get(), constraints);
      if (!options_.bullet_reference && options_.joint_space_dynamics)
        static_cast<MultiBodyWorld*>(world_.get())->setJointSpaceDynamics(e.robot->body(), &e.robot->response());
      if (!constraints)
        e.stable_pd = std::make_unique<StablePd>(*e.robot);
      applyMode(e);
      robots_.push_back(std::move(e));
    }
  }
  for (const vrrw_scene::Object& spec : scene.objects)
  {
    objects_.push_back(std::make_unique<RigidObject>(spec));
    objects_.back()->addToWorld(world_.get());
  }
  initial_ = snapshot();
  last_good_ = initial_;
}

PhysicsWorld::~PhysicsWorld()
{
  for (auto& a : assists_)
    world_->removeMultiBodyConstraint(a.second.get());
  assists_.clear();
  removeHand();
  objects_.clear();
  robots_.clear();
}

void PhysicsWorld::applyMode(RobotEntry& e)
{
  const auto& joints = e.robot->joints();
  for (std::size_t j = 0; j < joints.size(); ++j)
  {
    if (joints[j].drive < 0)
      continue;
    JointDrive& drive = *e.robot->drives()[std::size_t(joints[j].drive)];
    const DriveMode mode = e.arm_joint[j] ? e.mode : DriveMode::Rigid;
    if (mode == DriveMode::Custom)
      continue;
    const DriveGains g = e.table.gains(unprefixed(joints[j].name, e.spec.name), mode);
    drive.setGains(g.stiffness, g.damping);
    drive.setForceLimit(g.max_force > 0.0 ? g.max_force : (joints[j].max_effort > 0.0 ? joints[j].max_effort : 1e9));
  }
}

bool PhysicsWorld::step()
{
  for (RobotEntry& e : robots_)
  {
    const JointMatrix& inertia = e.robot->updateDynamics();
    e.robot->followMasters();
    e.robot->clearFeedForward();
    std::vector<double> external = e.robot->gravityTorques(options_.gravity);
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
  applySprings();
  world_->getSolverInfo().m_numNonContactInnerIterations = robotInContact() ? options_.solver_inner_iterations : 1;
  world_->stepSimulation(btScalar(options_.dt), 0, btScalar(options_.dt));
  for (RobotEntry& e : robots_)
    e.robot->refreshFrames();
  time_ += options_.dt;
  ++steps_;
  if (!stateIsSane())
  {
    restore(last_good_);
    return false;
  }
  if (options_.snapshot_interval > 0 && steps_ % std::uint64_t(options_.snapshot_interval) == 0)
    last_good_ = snapshot();
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

bool PhysicsWorld::stateIsSane()
{
  // Checked every step: no allocation or stream unless something is wrong.
  std::string why;
  bool bad = false;
  for (const RobotEntry& e : robots_)
  {
    const btMultiBody& body = *e.robot->body();
    const auto& joints = e.robot->joints();
    for (std::size_t j = 0; j < joints.size(); ++j)
    {
      const double q = body.getJointPos(joints[j].link);
      const double v = body.getJointVel(joints[j].link);
      if (!std::isfinite(q) || !std::isfinite(v) || std::abs(v) > options_.max_joint_speed)
      {
        std::ostringstream text;
        text << "joint " << joints[j].name << ": velocity " << v << " (limit " << options_.max_joint_speed << ")";
        why = text.str();
        bad = true;
        break;
      }
    }
    if (bad)
      break;
  }
  for (const auto& o : objects_)
  {
    if (bad)
      break;
    const Eigen::Vector3d p = o->pose().translation();
    const double speed = o->linearVelocity().norm();
    if (!p.allFinite() || !std::isfinite(speed) || speed > options_.max_object_speed)
    {
      std::ostringstream text;
      text << "object " << o->name() << ": speed " << speed << " m/s (limit " << options_.max_object_speed << ")";
      why = text.str();
      bad = true;
    }
  }
  if (!bad)
    return true;
  std::ostringstream message;
  message << "physics guard at t=" << time_ << " s: " << why << "; step rejected, state restored to t="
          << last_good_.time << " s";
  last_error_ = message.str();
  return false;
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
                                   const std::vector<double>& positions, const std::vector<double>& velocities)
{
  RobotEntry& e = entry(robot);
  if (positions.size() != joints.size())
    throw InputError("drive targets for " + robot + ": " + std::to_string(joints.size()) + " joint names but " +
                     std::to_string(positions.size()) + " positions");
  if (!velocities.empty() && velocities.size() != joints.size())
    throw InputError("drive targets for " + robot + ": " + std::to_string(joints.size()) + " joint names but " +
                     std::to_string(velocities.size()) + " velocities");
  std::vector<int> drives;
  for (std::size_t i = 0; i < joints.size(); ++i)
  {
    const int j = e.robot->jointIndex(joints[i]);
    if (j < 0)
      throw InputError("drive target: joint '" + joints[i] + "' is not a movable joint of robot " + robot);
    const SimJoint& joint = e.robot->joints()[std::size_t(j)];
    if (joint.drive < 0)
      throw InputError("drive target: joint '" + joints[i] + "' is a mimic joint; drive the joint it mimics");
    requireFinite(positions[i], "drive target: joint '" + joints[i] + "' position");
    if (!velocities.empty())
      requireFinite(velocities[i], "drive target: joint '" + joints[i] + "' velocity");
    drives.push_back(joint.drive);
  }
  for (std::size_t i = 0; i < joints.size(); ++i)
    e.robot->drives()[std::size_t(drives[i])]->setTarget(positions[i], velocities.empty() ? 0.0 : velocities[i]);
}

void PhysicsWorld::setMode(const std::string& robot, DriveMode mode)
{
  RobotEntry& e = entry(robot);
  e.mode = mode;
  applyMode(e);
}

DriveMode PhysicsWorld::mode(const std::string& robot) const
{
  return entry(robot).mode;
}

void PhysicsWorld::setGains(const std::string& robot, const std::vector<std::string>& joints,
                            const std::vector<double>& stiffness, const std::vector<double>& damping,
                            const std::vector<double>& max_force)
{
  RobotEntry& e = entry(robot);
  std::vector<std::string> names = joints;
  if (names.empty())
    names = e.spec.arm_joints;
  const std::string what = "gains for " + robot + ": ";
  if (stiffness.size() != names.size() || damping.size() != names.size() ||
      (!max_force.empty() && max_force.size() != names.size()))
    throw InputError(what + std::to_string(names.size()) + " joints but " + std::to_string(stiffness.size()) +
                     " stiffness, " + std::to_string(damping.size()) + " damping, " +
                     std::to_string(max_force.size()) + " max_force values");
  std::vector<JointDrive*> drives;
  for (std::size_t i = 0; i < names.size(); ++i)
  {
    const int j = e.robot->jointIndex(names[i]);
    if (j < 0 || e.robot->joints()[std::size_t(j)].drive < 0)
      throw InputError(what + "joint '" + names[i] + "' is not a driven joint of robot " + robot);
    for (double value : { stiffness[i], damping[i], max_force.empty() ? 1.0 : max_force[i] })
      if (!std::isfinite(value) || value < 0.0)
        throw InputError(what + "joint '" + names[i] + "': gains must be finite and >= 0");
    if (stiffness[i] + damping[i] <= 0.0)
      throw InputError(what + "joint '" + names[i] + "': stiffness and damping are both 0");
    drives.push_back(e.robot->drives()[std::size_t(e.robot->joints()[std::size_t(j)].drive)].get());
  }
  e.mode = DriveMode::Custom;
  for (std::size_t i = 0; i < names.size(); ++i)
  {
    drives[i]->setGains(stiffness[i], damping[i]);
    if (!max_force.empty())
      drives[i]->setForceLimit(max_force[i]);
  }
}

DriveGains PhysicsWorld::gains(const std::string& robot, const std::string& joint) const
{
  const RobotEntry& e = entry(robot);
  const int j = e.robot->jointIndex(joint);
  if (j < 0 || e.robot->joints()[std::size_t(j)].drive < 0)
    throw InputError("joint '" + joint + "' is not a driven joint of robot " + robot);
  const JointDrive& d = *e.robot->drives()[std::size_t(e.robot->joints()[std::size_t(j)].drive)];
  return { d.stiffness(), d.damping(), d.forceLimit() };
}

void PhysicsWorld::setGravityCompensation(const std::string& robot, bool on)
{
  entry(robot).gravity_compensation = on;
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
  if (!pose.matrix().allFinite())
    throw InputError("object '" + name + "': pose is not finite");
  o.setPose(pose);
}

bool PhysicsWorld::frameExists(const std::string& frame) const
{
  for (const RobotEntry& e : robots_)
    if (e.robot->hasLink(frame))
      return true;
  for (const auto& o : objects_)
    if (o->name() == frame)
      return true;
  return false;
}

Eigen::Isometry3d PhysicsWorld::framePose(const std::string& frame) const
{
  for (const RobotEntry& e : robots_)
    if (e.robot->hasLink(frame))
      return e.robot->linkPose(frame);
  return object(frame).pose();
}

void PhysicsWorld::attachSpring(const std::string& id, const OperatorSpring& spring)
{
  if (!frameExists(spring.body))
    throw InputError("spring '" + id + "': link or object '" + spring.body + "' not in the scene");
  for (double value : { spring.stiffness, spring.damping, spring.angular_stiffness, spring.angular_damping,
                        spring.max_force })
    if (!std::isfinite(value) || value < 0.0)
      throw InputError("spring '" + id + "': gains must be finite and >= 0");
  if (!spring.point.allFinite() || !spring.target.matrix().allFinite() || !spring.target_velocity.allFinite())
    throw InputError("spring '" + id + "': point or target is not finite");
  releaseSpring(id);
  springs_.push_back({ id, spring });
  springs_.back().spring.active = true;
}

void PhysicsWorld::moveSpring(const std::string& id, const Eigen::Isometry3d& target, const Eigen::Vector3d& velocity)
{
  if (!target.matrix().allFinite() || !velocity.allFinite())
    throw InputError("spring '" + id + "': target is not finite");
  for (SpringEntry& s : springs_)
    if (s.id == id)
    {
      s.spring.target = target;
      s.spring.target_velocity = velocity;
      return;
    }
  throw InputError("spring '" + id + "': not attached");
}

void PhysicsWorld::releaseSpring(const std::string& id)
{
  for (auto it = springs_.begin(); it != springs_.end(); ++it)
    if (it->id == id)
    {
      springs_.erase(it);
      return;
    }
}

void PhysicsWorld::applySprings()
{
  for (const SpringEntry& s : springs_)
  {
    const OperatorSpring& sp = s.spring;
    bool on_robot = false;
    for (RobotEntry& e : robots_)
      if (e.robot->hasLink(sp.body))
      {
        const Eigen::Isometry3d pose = e.robot->linkPose(sp.body);
        const Eigen::Vector3d f = sp.force(pose * sp.point, e.robot->pointVelocity(sp.body, sp.point));
        const Eigen::Vector3d t = sp.torque(pose.rotation(), e.robot->angularVelocity(sp.body));
        e.robot->applyWrench(sp.body, sp.point, f, t);
        on_robot = true;
        break;
      }
    if (on_robot)
      continue;
    RigidObject& o = object(sp.body);
    const Eigen::Isometry3d pose = o.pose();
    o.applyWrench(sp.point, sp.force(pose * sp.point, o.pointVelocity(sp.point)),
                  sp.torque(pose.rotation(), o.angularVelocity()));
  }
}

void PhysicsWorld::setGraspAssist(const std::string& robot, const std::string& object, bool on)
{
  RobotEntry& e = entry(robot);
  RigidObject& o = this->object(object);
  const std::string key = robot + "/" + object;
  const auto existing = assists_.find(key);
  if (existing != assists_.end())
  {
    world_->removeMultiBodyConstraint(existing->second.get());
    assists_.erase(existing);
  }
  if (!on)
    return;
  if (o.fixed())
    throw InputError("grasp assist: object '" + object + "' is fixed");
  const std::string tcp = e.spec.tcp_link.empty() ? robot + "_tool0" : e.spec.tcp_link;
  if (!e.robot->hasLink(tcp))
    throw InputError("grasp assist: robot " + robot + " has no link '" + tcp + "'");
  const int link = e.robot->bulletLink(tcp);
  if (link < 0)
    throw InputError("grasp assist: '" + tcp + "' is fixed to the base of " + robot);
  const Eigen::Isometry3d link_T_object = e.robot->bodyPose(link).inverse() *
                                          Eigen::Isometry3d(toEigenTransform(o.body()->getWorldTransform()));
  const btTransform in_link = toBullet(link_T_object);
  auto weld = std::make_unique<btMultiBodyFixedConstraint>(e.robot->body(), link, o.body(), in_link.getOrigin(),
                                                           btVector3(0, 0, 0), in_link.getBasis(),
                                                           btMatrix3x3::getIdentity());
  weld->setMaxAppliedImpulse(btScalar(1e3 * options_.dt));
  world_->addMultiBodyConstraint(weld.get());
  assists_[key] = std::move(weld);
}

std::vector<std::string> PhysicsWorld::graspAssists() const
{
  std::vector<std::string> keys;
  for (const auto& a : assists_)
    keys.push_back(a.first);
  return keys;
}

void PhysicsWorld::setHandPose(const Eigen::Isometry3d& pose, double radius)
{
  if (!pose.matrix().allFinite() || !(radius > 0.0))
    throw InputError("hand: pose not finite or radius not positive");
  if (!hand_)
  {
    hand_shape_ = std::make_unique<btSphereShape>(btScalar(radius));
    hand_motion_ = std::make_unique<btDefaultMotionState>(toBullet(pose));
    btRigidBody::btRigidBodyConstructionInfo info(0, hand_motion_.get(), hand_shape_.get());
    info.m_friction = btScalar(1.0);
    hand_ = std::make_unique<btRigidBody>(info);
    hand_->setCollisionFlags(hand_->getCollisionFlags() | btCollisionObject::CF_KINEMATIC_OBJECT);
    hand_->setActivationState(DISABLE_DEACTIVATION);
    world_->addRigidBody(hand_.get());
  }
  hand_motion_->setWorldTransform(toBullet(pose));
}

void PhysicsWorld::removeHand()
{
  if (!hand_)
    return;
  world_->removeRigidBody(hand_.get());
  hand_.reset();
  hand_motion_.reset();
  hand_shape_.reset();
}

WorldState PhysicsWorld::snapshot() const
{
  WorldState s;
  s.time = time_;
  s.steps = steps_;
  for (const RobotEntry& e : robots_)
  {
    s.positions.push_back(e.robot->positions());
    s.velocities.push_back(e.robot->velocities());
    std::vector<double> tp, tv;
    for (const auto& d : e.robot->drives())
    {
      tp.push_back(d->targetPosition());
      tv.push_back(d->targetVelocity());
    }
    s.target_positions.push_back(tp);
    s.target_velocities.push_back(tv);
  }
  for (const auto& o : objects_)
  {
    s.object_poses.push_back(o->pose());
    s.object_linear.push_back(o->linearVelocity());
    s.object_angular.push_back(o->angularVelocity());
  }
  return s;
}

void PhysicsWorld::restore(const WorldState& s)
{
  time_ = s.time;
  steps_ = s.steps;
  for (std::size_t r = 0; r < robots_.size() && r < s.positions.size(); ++r)
  {
    ArticulatedRobot& robot = *robots_[r].robot;
    robot.setState(s.positions[r], s.velocities[r]);
    for (std::size_t d = 0; d < robot.drives().size(); ++d)
      robot.drives()[d]->setTarget(s.target_positions[r][d], s.target_velocities[r][d]);
  }
  for (std::size_t o = 0; o < objects_.size() && o < s.object_poses.size(); ++o)
  {
    objects_[o]->setPose(s.object_poses[o]);
    objects_[o]->setVelocity(s.object_linear[o], s.object_angular[o]);
  }
}

void PhysicsWorld::reset()
{
  springs_.clear();
  for (auto& a : assists_)
    world_->removeMultiBodyConstraint(a.second.get());
  assists_.clear();
  removeHand();
  restore(initial_);
  last_good_ = initial_;
}
}  // namespace vrrw_physics

#include <vrrw_physics/articulated_robot.h>
#include <vrrw_physics/input_limits.h>
#include <vrrw_physics/operator_input.h>
#include <vrrw_physics/rigid_object.h>

#include <BulletDynamics/Dynamics/btRigidBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>
#include <BulletDynamics/Featherstone/btMultiBodyFixedConstraint.h>

#include <sstream>

#include "bullet_conversions.h"
#include "kinematic_hand.h"

namespace vrrw_physics
{
namespace
{
template <class Map>
std::vector<std::string> keys(const Map& map)
{
  std::vector<std::string> out;
  for (const auto& entry : map)
    out.push_back(entry.first);
  return out;
}
}  // namespace

OperatorInput::OperatorInput(btMultiBodyDynamicsWorld& world, const double& clock, double dt, double hand_timeout)
  : world_(world), clock_(clock), dt_(dt), hand_timeout_(hand_timeout)
{
}

OperatorInput::~OperatorInput()
{
  releaseAll();
}

void OperatorInput::addRobot(ArticulatedRobot* robot, const std::string& name, const std::string& tcp_link)
{
  robots_.push_back({ robot, name, tcp_link });
}

void OperatorInput::addObject(RigidObject* object)
{
  objects_.push_back(object);
}

ArticulatedRobot* OperatorInput::robotWithLink(const std::string& link) const
{
  for (const RobotRef& r : robots_)
    if (r.robot->hasLink(link))
      return r.robot;
  return nullptr;
}

RigidObject* OperatorInput::object(const std::string& name) const
{
  for (RigidObject* o : objects_)
    if (o->name() == name)
      return o;
  return nullptr;
}

void OperatorInput::checkSpring(const std::string& id, const OperatorSpring& s) const
{
  const std::string what = "spring '" + id + "'";
  if (id.empty())
    throw InputError("spring: the id is empty");
  const RigidObject* o = object(s.body);
  if (!robotWithLink(s.body) && !o)
    throw InputError(what + ": link or object '" + s.body + "' not in the scene");
  if (o && o->fixed())
    throw InputError(what + ": object '" + s.body + "' is fixed");
  requireInRange(s.stiffness, 0.0, kMaxSpringStiffness, what + " stiffness", "N/m");
  requireInRange(s.damping, 0.0, kMaxSpringDamping, what + " damping", "N s/m");
  requireInRange(s.angular_stiffness, 0.0, kMaxSpringAngularStiffness, what + " angular_stiffness", "N m/rad");
  requireInRange(s.angular_damping, 0.0, kMaxSpringAngularDamping, what + " angular_damping", "N m s/rad");
  requireInRange(s.max_force, 1e-6, kMaxSpringForce, what + " max_force", "N");
  if (!s.point.allFinite())
    throw InputError(what + ": point is not finite");
  requireInRange(s.point.norm(), 0.0, kMaxSpringPointOffset, what + " point (distance from the body's frame)", "m");
  requireWorkspacePose(s.target, what + " target");
  requireInRange(s.target_velocity.norm(), 0.0, kMaxTargetSpeed, what + " target velocity", "m/s");
}

void OperatorInput::attachSpring(const std::string& id, const OperatorSpring& spring)
{
  checkSpring(id, spring);
  springs_[id] = spring;
}

void OperatorInput::moveSpring(const std::string& id, const Eigen::Isometry3d& target, const Eigen::Vector3d& velocity)
{
  const auto it = springs_.find(id);
  if (it == springs_.end())
    throw InputError("spring '" + id + "': not attached");
  OperatorSpring moved = it->second;
  moved.target = target;
  moved.target_velocity = velocity;
  checkSpring(id, moved);
  it->second = moved;
}

void OperatorInput::releaseSpring(const std::string& id)
{
  springs_.erase(id);
}

std::vector<std::string> OperatorInput::springs() const
{
  return keys(springs_);
}

void OperatorInput::applySpring(const OperatorSpring& sp)
{
  if (ArticulatedRobot* robot = robotWithLink(sp.body))
  {
    const Eigen::Isometry3d pose = robot->linkPose(sp.body);
    const Eigen::Vector3d f = sp.force(pose * sp.point, robot->pointVelocity(sp.body, sp.point));
    const Eigen::Vector3d t = sp.torque(pose.rotation(), robot->angularVelocity(sp.body));
    robot->applyWrench(sp.body, sp.point, f, t);
    return;
  }
  RigidObject& o = *object(sp.body);
  const Eigen::Isometry3d pose = o.pose();
  o.applyWrench(sp.point, sp.force(pose * sp.point, o.pointVelocity(sp.point)),
                sp.torque(pose.rotation(), o.angularVelocity()));
}

void OperatorInput::setGraspAssist(const std::string& robot, const std::string& object_name, bool on)
{
  const RobotRef* r = nullptr;
  for (const RobotRef& candidate : robots_)
    if (candidate.name == robot)
      r = &candidate;
  if (!r)
    throw InputError("grasp assist: robot '" + robot + "': not in the scene");
  RigidObject* o = object(object_name);
  if (!o)
    throw InputError("grasp assist: object '" + object_name + "': not in the scene");
  const std::string key = robot + "/" + object_name;
  const auto existing = assists_.find(key);
  if (existing != assists_.end())
  {
    world_.removeMultiBodyConstraint(existing->second.get());
    assists_.erase(existing);
  }
  if (!on)
    return;
  if (o->fixed())
    throw InputError("grasp assist: object '" + object_name + "' is fixed");
  if (!r->robot->hasLink(r->tcp_link))
    throw InputError("grasp assist: robot " + robot + " has no link '" + r->tcp_link + "'");
  const int link = r->robot->bulletLink(r->tcp_link);
  if (link < 0)
    throw InputError("grasp assist: '" + r->tcp_link + "' is fixed to the base of " + robot);
  const Eigen::Isometry3d link_T_object = r->robot->bodyPose(link).inverse() * toEigen(o->body()->getWorldTransform());
  const btTransform in_link = toBullet(link_T_object);
  auto weld = std::make_unique<btMultiBodyFixedConstraint>(r->robot->body(), link, o->body(), in_link.getOrigin(),
                                                           btVector3(0, 0, 0), in_link.getBasis(),
                                                           btMatrix3x3::getIdentity());
  // At most 1 kN: a weld that would take more gives way instead of flinging the robot.
  weld->setMaxAppliedImpulse(btScalar(1e3 * dt_));
  world_.addMultiBodyConstraint(weld.get());
  assists_[key] = std::move(weld);
}

std::vector<std::string> OperatorInput::graspAssists() const
{
  return keys(assists_);
}

void OperatorInput::setHand(const std::string& id, const Eigen::Isometry3d& pose, double radius)
{
  if (id.empty())
    throw InputError("hand: the id is empty");
  requireInRange(radius, 0.0, kMaxHandRadius, "hand '" + id + "' radius", "m (0 removes the hand)");
  if (radius == 0.0)
    return removeHand(id);
  requireWorkspacePose(pose, "hand '" + id + "'");
  auto it = hands_.find(id);
  if (it != hands_.end() && it->second->radius() != radius)
  {
    hands_.erase(it);
    it = hands_.end();
  }
  if (it == hands_.end())
    hands_[id] = std::make_unique<KinematicHand>(world_, radius, pose, clock_);
  else
    it->second->track(pose, clock_);
}

void OperatorInput::removeHand(const std::string& id)
{
  hands_.erase(id);
}

std::vector<std::string> OperatorInput::hands() const
{
  return keys(hands_);
}

std::string OperatorInput::handName(const btCollisionObject* object) const
{
  for (const auto& [id, hand] : hands_)
    if (hand->body() == object)
      return "hand/" + id;
  return "";
}

std::vector<std::string> OperatorInput::apply()
{
  std::vector<std::string> removed;
  for (auto it = hands_.begin(); it != hands_.end();)
  {
    const double silent = clock_ - it->second->lastUpdate();
    if (hand_timeout_ > 0.0 && silent > hand_timeout_)
    {
      std::ostringstream line;
      line << "hand '" << it->first << "': no pose for " << silent << " s (limit " << hand_timeout_ << " s): removed";
      removed.push_back(line.str());
      it = hands_.erase(it);
      continue;
    }
    it->second->advance(clock_, dt_);
    ++it;
  }
  for (const auto& entry : springs_)
    applySpring(entry.second);
  return removed;
}

void OperatorInput::releaseHandsAndSprings()
{
  springs_.clear();
  hands_.clear();
}

void OperatorInput::releaseAll()
{
  releaseHandsAndSprings();
  for (auto& a : assists_)
    world_.removeMultiBodyConstraint(a.second.get());
  assists_.clear();
}
}  // namespace vrrw_physics

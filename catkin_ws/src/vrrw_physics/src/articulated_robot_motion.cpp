#include <vrrw_physics/articulated_robot.h>

#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>

#include <algorithm>
#include <stdexcept>

#include "bullet_conversions.h"

namespace vrrw_physics
{
int ArticulatedRobot::jointIndex(const std::string& joint) const
{
  for (std::size_t i = 0; i < joints_.size(); ++i)
    if (joints_[i].name == joint)
      return int(i);
  return -1;
}

std::vector<double> ArticulatedRobot::jointValues(btScalar (btMultiBody::*value)(int) const) const
{
  std::vector<double> values;
  values.reserve(joints_.size());
  for (const SimJoint& j : joints_)
    values.push_back(((*body_).*value)(j.link));
  return values;
}

std::vector<double> ArticulatedRobot::positions() const
{
  return jointValues(&btMultiBody::getJointPos);
}

std::vector<double> ArticulatedRobot::velocities() const
{
  return jointValues(&btMultiBody::getJointVel);
}

std::vector<double> ArticulatedRobot::efforts(double dt) const
{
  std::vector<double> e(joints_.size(), 0.0);
  for (std::size_t i = 0; i < joints_.size(); ++i)
  {
    if (joints_[i].drive >= 0 && drive_constraints_)
      e[i] = drives_[std::size_t(joints_[i].drive)]->getAppliedImpulse(0) / dt;
    else if (coupling_of_joint_[i] >= 0)
    {
      e[i] = couplings_[std::size_t(coupling_of_joint_[i])]->getAppliedImpulse(0) / dt;
      if (drive_constraints_)
        e[i] += mimic_drives_[std::size_t(joints_[i].mimic_drive)]->getAppliedImpulse(0) / dt;
    }
    e[i] += feed_forward_[i];
  }
  return e;
}

void ArticulatedRobot::followMasters()
{
  for (const SimJoint& joint : joints_)
  {
    if (joint.mimic_drive < 0)
      continue;
    double factor = joint.multiplier, offset = joint.offset;
    const SimJoint* master = &joints_[std::size_t(joint.mimic)];
    while (master->mimic >= 0)
    {
      offset += factor * master->offset;
      factor *= master->multiplier;
      master = &joints_[std::size_t(master->mimic)];
    }
    const JointDrive& lead = *drives_[std::size_t(master->drive)];
    JointDrive& follower = *mimic_drives_[std::size_t(joint.mimic_drive)];
    follower.setGains(lead.stiffness(), lead.damping());
    // A lowered master limit (a gripper's max effort) bounds every finger of the linkage.
    follower.setForceLimit(joint.max_effort > 0.0 ? std::min(joint.max_effort, lead.forceLimit()) : lead.forceLimit());
    follower.setTarget(factor * lead.targetPosition() + offset, factor * lead.targetVelocity());
  }
}

std::vector<double> ArticulatedRobot::withMimics(std::vector<double> positions) const
{
  for (std::size_t i = 0; i < joints_.size(); ++i)
    if (joints_[i].mimic >= 0)
      positions[i] = joints_[i].multiplier * positions[std::size_t(joints_[i].mimic)] + joints_[i].offset;
  return positions;
}

void ArticulatedRobot::setState(const std::vector<double>& positions, const std::vector<double>& velocities)
{
  for (std::size_t i = 0; i < joints_.size(); ++i)
  {
    body_->setJointPos(joints_[i].link, btScalar(positions[i]));
    body_->setJointVel(joints_[i].link, btScalar(velocities[i]));
  }
  btAlignedObjectArray<btQuaternion> rotations;
  btAlignedObjectArray<btVector3> origins;
  body_->forwardKinematics(rotations, origins);
  body_->updateCollisionObjectWorldTransforms(rotations, origins);
  response_.invalidate();
  refreshFrames();
}

void ArticulatedRobot::refreshFrames()
{
  poses_.resize(colliders_.size());
  for (std::size_t i = 0; i < colliders_.size(); ++i)
    toEigen(colliders_[i]->getWorldTransform(), poses_[i]);
}

const JointMatrix& ArticulatedRobot::updateDynamics()
{
  inertia_ = jointSpaceInertia(*body_, poses_);
  response_.setInertia(inertia_);
  return inertia_;
}

const ArticulatedRobot::LinkFrame& ArticulatedRobot::linkFrame(const std::string& link) const
{
  const auto it = links_.find(link);
  if (it == links_.end())
    throw std::runtime_error("robot " + name_ + ": unknown link '" + link + "'");
  return it->second;
}

const std::string& ArticulatedRobot::shapeLink(int body, int shape) const
{
  const ShapeLinks& links = shape_links_[std::size_t(body + 1)];
  return shape >= 0 && std::size_t(shape) < links.shapes.size() ? links.shapes[std::size_t(shape)] : links.body_link;
}

Eigen::Isometry3d ArticulatedRobot::linkPose(const std::string& link) const
{
  const LinkFrame& frame = linkFrame(link);
  return bodyPose(frame.body) * frame.body_T_link;
}

std::pair<Eigen::Vector3d, Eigen::Vector3d> ArticulatedRobot::bodyVelocity(int body) const
{
  const int n = body_->getNumLinks();
  std::vector<btVector3> omega(std::size_t(n + 1)), vel(std::size_t(n + 1));
  body_->compTreeLinkVelocities(omega.data(), vel.data());
  const Eigen::Matrix3d r = bodyPose(body).rotation();
  return { r * toEigen(omega[std::size_t(body + 1)]), r * toEigen(vel[std::size_t(body + 1)]) };
}

Eigen::Vector3d ArticulatedRobot::pointVelocity(const std::string& link, const Eigen::Vector3d& point) const
{
  const LinkFrame& frame = linkFrame(link);
  const auto velocity = bodyVelocity(frame.body);
  const Eigen::Vector3d arm = linkPose(link) * point - bodyPose(frame.body).translation();
  return velocity.second + velocity.first.cross(arm);
}

Eigen::Vector3d ArticulatedRobot::angularVelocity(const std::string& link) const
{
  return bodyVelocity(linkFrame(link).body).first;
}

void ArticulatedRobot::applyWrench(const std::string& link, const Eigen::Vector3d& point, const Eigen::Vector3d& force,
                                   const Eigen::Vector3d& torque)
{
  const LinkFrame& frame = linkFrame(link);
  if (frame.body < 0)
    return;
  const Eigen::Vector3d arm = linkPose(link) * point - bodyPose(frame.body).translation();
  body_->addLinkForce(frame.body, toBullet(force));
  body_->addLinkTorque(frame.body, toBullet(Eigen::Vector3d(arm.cross(force) + torque)));
}

void ArticulatedRobot::addJointTorque(std::size_t joint, double torque)
{
  feed_forward_[joint] += torque;
  body_->addJointTorque(joints_[joint].link, btScalar(torque));
}

void ArticulatedRobot::clearFeedForward()
{
  std::fill(feed_forward_.begin(), feed_forward_.end(), 0.0);
}

std::vector<double> ArticulatedRobot::gravityTorques(const Eigen::Vector3d& gravity,
                                                     const std::vector<PointLoad>& loads) const
{
  const int n = body_->getNumLinks();
  double mass[kMaxJoints];  // one Bullet link per movable joint: at most kMaxJoints
  Eigen::Vector3d moment[kMaxJoints];
  for (int k = 0; k < n; ++k)
  {
    mass[std::size_t(k)] = body_->getLinkMass(k);
    moment[std::size_t(k)] = mass[std::size_t(k)] * bodyPose(k).translation();
  }
  for (const PointLoad& load : loads)
    if (load.body >= 0 && load.body < n)
    {
      mass[std::size_t(load.body)] += load.mass;
      moment[std::size_t(load.body)] += load.mass * load.centre;
    }
  for (int k = n - 1; k >= 0; --k)
  {
    const int parent = body_->getParent(k);
    if (parent >= 0)
    {
      mass[std::size_t(parent)] += mass[std::size_t(k)];
      moment[std::size_t(parent)] += moment[std::size_t(k)];
    }
  }
  std::vector<double> torques(joints_.size(), 0.0);
  for (std::size_t i = 0; i < joints_.size(); ++i)
  {
    const std::size_t k = std::size_t(joints_[i].link);
    const btMultibodyLink& link = body_->getLink(int(k));
    const Eigen::Isometry3d& frame = bodyPose(int(k));
    if (joints_[i].prismatic)
      torques[i] = (frame.rotation() * toEigen(link.getAxisBottom(0))).dot(mass[k] * gravity);
    else
    {
      const Eigen::Vector3d axis = frame.rotation() * toEigen(link.getAxisTop(0));
      const Eigen::Vector3d pivot = frame * (-toEigen(link.m_dVector));
      torques[i] = axis.cross(moment[k] - mass[k] * pivot).dot(gravity);
    }
  }
  return torques;
}

int ArticulatedRobot::commonAncestor(const std::vector<int>& bodies) const
{
  if (bodies.empty())
    return -1;
  std::vector<int> chain;  // the first body and its ancestors, nearest first
  for (int k = bodies.front(); k >= 0; k = body_->getParent(k))
    chain.push_back(k);
  std::size_t deepest = 0;  // index in chain of the common ancestor so far
  for (const int b : bodies)
  {
    int k = b;
    while (k >= 0 && std::find(chain.begin() + long(deepest), chain.end(), k) == chain.end())
      k = body_->getParent(k);
    if (k < 0)
      return -1;
    deepest = std::size_t(std::find(chain.begin(), chain.end(), k) - chain.begin());
  }
  return chain[deepest];
}
}  // namespace vrrw_physics

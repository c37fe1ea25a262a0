#include <vrrw_physics/articulated_robot.h>
#include <vrrw_physics/input_limits.h>
#include <vrrw_physics/robot_drives.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace vrrw_physics
{
namespace
{
/// The force limit a drive has without custom gains: the config's, else the URDF effort, else none.
double configuredLimit(const DriveGains& gains, const SimJoint& joint)
{
  if (gains.max_force > 0.0)
    return gains.max_force;
  return joint.max_effort > 0.0 ? joint.max_effort : 1e9;
}

void requireSameLength(std::size_t names, std::size_t values, const std::string& what, const std::string& field)
{
  if (values != names)
    throw InputError(what + ": " + std::to_string(names) + " joint names but " + std::to_string(values) + " " + field);
}
}  // namespace

RobotDrives::RobotDrives(const vrrw_scene::Robot& spec, ArticulatedRobot& robot, DriveMode mode, double max_speed)
  : name_(spec.name), robot_(robot), mode_(mode), max_speed_(max_speed), arm_joints_(spec.arm_joints)
{
  const auto& joints = robot.joints();
  joint_of_drive_.resize(robot.drives().size());
  streamed_.resize(robot.drives().size());
  for (std::size_t j = 0; j < joints.size(); ++j)
    if (joints[j].drive >= 0)
      joint_of_drive_[std::size_t(joints[j].drive)] = j;
  for (const std::size_t j : joint_of_drive_)
  {
    const auto gains = spec.drive_gains.find(joints[j].name);
    config_.push_back(gains == spec.drive_gains.end() ? vrrw_scene::JointGains() : gains->second);
    arm_.push_back(std::count(spec.arm_joints.begin(), spec.arm_joints.end(), joints[j].name) > 0);
    force_limit_.push_back(configuredLimit(config_.back().rigid, joints[j]));
  }
  for (const std::string& arm : spec.arm_joints)
    drive(arm, "robot " + spec.name + ": arm joint");
  reset(mode);
}

std::size_t RobotDrives::drive(const std::string& joint, const std::string& what) const
{
  const int j = robot_.jointIndex(joint);
  if (j < 0)
    throw InputError(what + " '" + joint + "': not a movable joint of robot " + name_);
  const SimJoint& sim = robot_.joints()[std::size_t(j)];
  if (sim.drive < 0)
    throw InputError(what + " '" + joint + "': a mimic joint of robot " + name_ + "; drive the joint it mimics");
  return std::size_t(sim.drive);
}

std::vector<std::size_t> RobotDrives::drives(const std::vector<std::string>& joints) const
{
  std::vector<std::size_t> out;
  std::set<std::string> named;
  for (const std::string& joint : joints)
  {
    out.push_back(drive(joint, "drive target: joint"));
    if (!named.insert(joint).second)
      throw InputError("drive target: joint '" + joint + "': named twice");
  }
  return out;
}

void RobotDrives::setTargets(const std::vector<std::string>& joints, const std::vector<double>& positions,
                             const std::vector<double>& velocities, const std::vector<double>& efforts, double now)
{
  const std::string what = "drive targets for " + name_;
  requireSameLength(joints.size(), positions.size(), what, "positions");
  setTargetsByIndex(drives(joints), positions, velocities, efforts, now);
}

void RobotDrives::setTargetsByIndex(const std::vector<std::size_t>& drives, const std::vector<double>& positions,
                             const std::vector<double>& velocities, const std::vector<double>& efforts, double now)
{
  const std::string what = "drive targets for " + name_;
  requireSameLength(drives.size(), positions.size(), what, "positions");
  if (!velocities.empty())
    requireSameLength(drives.size(), velocities.size(), what, "velocities");
  if (!efforts.empty())
    requireSameLength(drives.size(), efforts.size(), what, "efforts");
  for (std::size_t i = 0; i < drives.size(); ++i)
  {
    const SimJoint& sim = robot_.joints()[joint_of_drive_.at(drives[i])];
    const bool bad = !std::isfinite(positions[i]) ||
                     (sim.limited && (positions[i] < sim.lower - kJointLimitMargin * (sim.upper - sim.lower) ||
                                      positions[i] > sim.upper + kJointLimitMargin * (sim.upper - sim.lower))) ||
                     (!velocities.empty() && !(std::abs(velocities[i]) <= max_speed_)) ||
                     (!efforts.empty() && !(efforts[i] >= 0.0 && efforts[i] <= kMaxDriveForce));
    if (bad)
      checkTarget(sim, positions[i], velocities.empty() ? 0.0 : velocities[i], efforts.empty() ? 0.0 : efforts[i]);
  }
  for (std::size_t i = 0; i < drives.size(); ++i)
  {
    JointDrive& d = *robot_.drives()[drives[i]];
    const double velocity = velocities.empty() ? 0.0 : velocities[i];
    d.setTarget(positions[i], velocity);
    streamed_[drives[i]] = { true, positions[i], velocity, now };
    const double limit = force_limit_[drives[i]];
    d.setForceLimit(!efforts.empty() && efforts[i] > 0.0 ? std::min(efforts[i], limit) : limit);
  }
  last_targets_ = now;
  streaming_ = true;
}

void RobotDrives::checkTarget(const SimJoint& sim, double position, double velocity, double effort) const
{
  const std::string joint = "drive target: joint '" + sim.name + "'";
  const std::string unit = sim.prismatic ? "m" : "rad";
  if (!std::isfinite(position))
    throw InputError(joint + ": position is not finite");
  if (sim.limited)
  {
    const double margin = kJointLimitMargin * (sim.upper - sim.lower);
    requireInRange(position, sim.lower - margin, sim.upper + margin, joint + " position",
                   unit + " (the joint limits and 5 % of the range)");
  }
  requireInRange(velocity, -max_speed_, max_speed_, joint + " velocity", unit + "/s (the guard's limit)");
  requireInRange(effort, 0.0, kMaxDriveForce, joint + " effort", sim.prismatic ? "N" : "N m");
}

bool RobotDrives::holdIfStale(double now, double timeout)
{
  if (!streaming_ || timeout <= 0.0 || now - last_targets_ <= timeout)
    return false;
  // at the last targets' own positions: not carried on along a velocity nobody confirms any more
  for (std::size_t d = 0; d < robot_.drives().size(); ++d)
    robot_.drives()[d]->setTarget(streamed_[d].active ? streamed_[d].position : robot_.drives()[d]->targetPosition(), 0.0);
  endStream();
  streaming_ = false;
  return true;
}

void RobotDrives::advance(double now)
{
  for (std::size_t d = 0; d < streamed_.size(); ++d)
    if (streamed_[d].active && streamed_[d].velocity != 0.0)
    {
      const double ahead = std::clamp(now - streamed_[d].time, 0.0, kTargetExtrapolation);
      robot_.drives()[d]->setTarget(streamed_[d].position + streamed_[d].velocity * ahead, streamed_[d].velocity);
    }
}

void RobotDrives::setMode(DriveMode mode)
{
  mode_ = mode;
  applyMode();
  holdArm();
}

void RobotDrives::setGains(const std::vector<std::string>& joints, const std::vector<double>& stiffness,
                           const std::vector<double>& damping, const std::vector<double>& max_force)
{
  const std::vector<std::string>& names = joints.empty() ? arm_joints_ : joints;
  const std::string what = "gains for " + name_;
  requireSameLength(names.size(), stiffness.size(), what, "stiffness values");
  requireSameLength(names.size(), damping.size(), what, "damping values");
  if (!max_force.empty())
    requireSameLength(names.size(), max_force.size(), what, "max_force values");
  std::vector<std::size_t> drives;
  for (std::size_t i = 0; i < names.size(); ++i)
  {
    drives.push_back(drive(names[i], what + ": joint"));
    const std::string joint = what + ": joint '" + names[i] + "'";
    const bool prismatic = robot_.joints()[joint_of_drive_[drives.back()]].prismatic;
    requireInRange(stiffness[i], 0.0, kMaxDriveStiffness, joint + " stiffness", prismatic ? "N/m" : "N m/rad");
    requireInRange(damping[i], 0.0, kMaxDriveDamping, joint + " damping", prismatic ? "N s/m" : "N m s/rad");
    if (!max_force.empty())
      requireInRange(max_force[i], 1e-6, kMaxDriveForce, joint + " max_force", prismatic ? "N" : "N m");
    if (stiffness[i] + damping[i] <= 0.0)
      throw InputError(joint + ": stiffness and damping are both 0: the drive would not act");
  }
  mode_ = DriveMode::Custom;
  for (std::size_t i = 0; i < names.size(); ++i)
  {
    JointDrive& d = *robot_.drives()[drives[i]];
    d.setGains(stiffness[i], damping[i]);
    if (!max_force.empty())
      force_limit_[drives[i]] = max_force[i];
    d.setForceLimit(force_limit_[drives[i]]);
  }
  holdArm();
}

DriveGains RobotDrives::gains(const std::string& joint) const
{
  const JointDrive& d = *robot_.drives()[drive(joint, "joint")];
  return { d.stiffness(), d.damping(), d.forceLimit() };
}

void RobotDrives::reset(DriveMode mode)
{
  // Rigid first: it puts the config's gains back on joints a Custom mode leaves alone.
  mode_ = DriveMode::Rigid;
  applyMode();
  mode_ = mode;
  applyMode();
  streaming_ = false;
  endStream();
}

void RobotDrives::applyMode()
{
  for (std::size_t d = 0; d < config_.size(); ++d)
  {
    const DriveMode mode = arm_[d] ? mode_ : DriveMode::Rigid;
    if (mode == DriveMode::Custom)
      continue;
    const DriveGains& g = mode == DriveMode::Compliant ? config_[d].compliant : config_[d].rigid;
    force_limit_[d] = configuredLimit(g, robot_.joints()[joint_of_drive_[d]]);
    robot_.drives()[d]->setGains(g.stiffness, g.damping);
    robot_.drives()[d]->setForceLimit(force_limit_[d]);
  }
}

void RobotDrives::holdArm()
{
  const std::vector<double> q = robot_.positions();
  for (std::size_t d = 0; d < config_.size(); ++d)
    if (arm_[d])
    {
      robot_.drives()[d]->setTarget(q[joint_of_drive_[d]], 0.0);
      streamed_[d] = Streamed();
    }
}
}  // namespace vrrw_physics

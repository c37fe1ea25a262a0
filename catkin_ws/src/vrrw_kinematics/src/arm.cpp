#include <vrrw_kinematics/arm.h>

#include <vrrw_kinematics/scene_state.h>
#include <vrrw_kinematics/state_checker.h>

namespace vrrw_kinematics
{
namespace
{
const std::vector<std::string>& armJoints(const vrrw_scene::Robot& robot)
{
  if (robot.arm_joints.empty())
    throw KinematicsError(ErrorCode::InvalidArgument, "robot " + robot.name + ": no arm joints");
  return robot.arm_joints;
}
}  // namespace

Arm::Arm(const CollisionWorld& world, const vrrw_scene::Robot& robot)
  : world_(world), robot_(robot), bounds_(world.model(), armJoints(robot))
{
  const RobotModel& model = world.model();
  base_link_ = model.links()[model.joints()[model.jointIndex(robot.arm_joints.front())].parent_link].name;
  for (const std::string& joint : robot.arm_joints)
  {
    variables_.push_back(model.variableIndex(joint));
    timing_.max_velocity.push_back(model.joints()[model.jointIndex(joint)].max_velocity);
  }
  timing_.max_acceleration = armAccelerationLimits(robot);
  ikSolver();
}

std::string Arm::linkOrTcp(const std::string& link) const
{
  return link.empty() ? robot_.tcp_link : link;
}

Eigen::VectorXd Arm::jointValues(const Eigen::VectorXd& world_state) const
{
  Eigen::VectorXd q(static_cast<Eigen::Index>(variables_.size()));
  for (std::size_t i = 0; i < variables_.size(); ++i)
    q[static_cast<Eigen::Index>(i)] = world_state[variables_[i]];
  return q;
}

Eigen::VectorXd Arm::withJointValues(const Eigen::VectorXd& world_state, const Eigen::VectorXd& q) const
{
  Eigen::VectorXd state = world_state;
  for (std::size_t i = 0; i < variables_.size(); ++i)
    state[variables_[i]] = q[static_cast<Eigen::Index>(i)];
  return state;
}

Eigen::Isometry3d Arm::basePose(const Eigen::VectorXd& world_state) const
{
  return world_.model().relativeTransform(world_state, world_.model().links()[0].name, base_link_);
}

const IkSolver& Arm::ikSolver(const std::string& link)
{
  const std::string tip = linkOrTcp(link);
  auto it = solvers_.find(tip);
  if (it == solvers_.end())
  {
    const KinematicChain chain(world_.model(), base_link_, tip);
    if (chain.jointNames() != robot_.arm_joints)
      throw KinematicsError(ErrorCode::NotSerialChain, "chain " + base_link_ + " -> " + tip +
                                                           ": its movable joints are not the arm of " + robot_.name);
    it = solvers_.emplace(tip, std::make_unique<IkSolver>(chain)).first;
  }
  return *it->second;
}

CollisionTest Arm::collisionTest(const Eigen::VectorXd& world_state)
{
  // The fast checker freezes everything but the arm and costs a few hundred checks to build: it is built
  // once the rest of the world holds still (the same state twice in a row); while other robots move, each
  // state is checked against the whole world instead.
  Eigen::VectorXd frozen = withJointValues(world_state, Eigen::VectorXd::Zero(static_cast<Eigen::Index>(size())));
  const bool same = frozen.size() == checker_state_.size() && frozen == checker_state_ &&
                    checker_revision_ == world_.revision();
  if (!same)
  {
    checker_.reset();
    checker_state_ = std::move(frozen);
    checker_revision_ = world_.revision();
    return [this, world_state](const Eigen::VectorXd& q) { return world_.check(withJointValues(world_state, q), robot_.name); };
  }
  if (!checker_)
    checker_ = std::make_unique<StateChecker>(world_, robot_.arm_joints, world_state);
  return [this](const Eigen::VectorXd& q) { return checker_->check(q); };
}

Contact Arm::check(const Eigen::VectorXd& q, const Eigen::VectorXd& world_state)
{
  return collisionTest(world_state)(q);
}

IkResult Arm::solveCollisionFree(const Eigen::Isometry3d& target, const Eigen::VectorXd& seed,
                                 const Eigen::VectorXd& world_state, const IkOptions& options, const std::string& link)
{
  const IkSolver& solver = ikSolver(link);
  return solver.solveCollisionFree(basePose(world_state).inverse() * target, seed, options, collisionTest(world_state));
}

TrajectoryResult Arm::planTrajectory(const TrajectoryRequest& request, const Eigen::VectorXd& world_state,
                                     const std::string& link)
{
  MotionPlanner planner(world_, robot_.arm_joints, linkOrTcp(link), world_state);
  return vrrw_kinematics::planTrajectory(planner, timing_, request);
}
}  // namespace vrrw_kinematics

#pragma once
#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <map>
#include <memory>
#include <string>
#include <vector>
#include <vrrw_scene/scene.h>

#include <vrrw_kinematics/collision_world.h>
#include <vrrw_kinematics/ik_solver.h>
#include <vrrw_kinematics/joint_bounds.h>
#include <vrrw_kinematics/time_parameterization.h>
#include <vrrw_kinematics/trajectory_planning.h>

namespace vrrw_kinematics
{
/// \brief One robot's arm in a scene's CollisionWorld, for callers that hold the state of the whole world
/// (the planning node, the operator-interaction node): the arm's joints in the world's variable vector,
/// IK for a link at its end, IK the scene accepts, and timed trajectories through waypoints.
///
/// Each query takes `world_state` (the model's variable vector) for everything but the arm: other robots,
/// the arm's own gripper, and the objects attached to links; free objects are where the world has them.
/// Not thread-safe: it keeps its IK solvers and a collision checker between calls.
class Arm
{
public:
  /// \brief The arm of `robot` in `world` (which must outlive it); throws KinematicsError: InvalidArgument
  /// (no arm joints, a joint without an acceleration limit), NotSerialChain (base -> tcp is not the arm).
  Arm(const CollisionWorld& world, const vrrw_scene::Robot& robot);

  /// \brief The scene's description of the robot.
  const vrrw_scene::Robot& robot() const { return robot_; }
  /// \brief The arm joints, base to tip.
  const std::vector<std::string>& jointNames() const { return robot_.arm_joints; }
  /// \brief Number of arm joints.
  std::size_t size() const { return variables_.size(); }
  /// \brief Parent link of the first arm joint: the base of every chain the arm solves IK for.
  const std::string& baseLink() const { return base_link_; }
  /// \brief The arm's joint limits.
  const JointBounds& bounds() const { return bounds_; }
  /// \brief Velocity (URDF) and acceleration (scene config) limits the arm's trajectories keep.
  const TimingOptions& timing() const { return timing_; }

  /// \brief The arm's joint values in a world state.
  Eigen::VectorXd jointValues(const Eigen::VectorXd& world_state) const;
  /// \brief `world_state` with the arm's joints at `q`.
  Eigen::VectorXd withJointValues(const Eigen::VectorXd& world_state, const Eigen::VectorXd& q) const;
  /// \brief Pose of the base link in the world at `world_state`.
  Eigen::Isometry3d basePose(const Eigen::VectorXd& world_state) const;

  /// \brief IK of the chain base -> `link` ("" = the tcp), built on first use; throws KinematicsError
  /// (UnknownLink, NotSerialChain when the chain's movable joints are not exactly the arm's).
  const IkSolver& ikSolver(const std::string& link = "");
  /// \brief The first pair the arm at `q` touches, the rest of the world at `world_state` (limits unchecked).
  Contact check(const Eigen::VectorXd& q, const Eigen::VectorXd& world_state);
  /// \brief The configuration nearest `seed` that puts `link` ("" = the tcp) at `target` (world frame),
  /// moves no joint more than options.max_jump from the seed, and touches nothing with the rest of the
  /// world at `world_state`. Failure codes as IkSolver::solveCollisionFree (NoSolution with the residual,
  /// JointJump, InCollision with the pair).
  IkResult solveCollisionFree(const Eigen::Isometry3d& target, const Eigen::VectorXd& seed,
                              const Eigen::VectorXd& world_state, const IkOptions& options = {},
                              const std::string& link = "");
  /// \brief A collision-free trajectory from request.plan.start through the waypoints to the goal (a pose
  /// goal is one of `link`, "" = the tcp, in the world frame), the rest of the world at `world_state`; see
  /// planTrajectory().
  TrajectoryResult planTrajectory(const TrajectoryRequest& request, const Eigen::VectorXd& world_state,
                                  const std::string& link = "");

private:
  /// \brief Collision test of arm configurations against the rest of the world at `world_state`.
  CollisionTest collisionTest(const Eigen::VectorXd& world_state);
  std::string linkOrTcp(const std::string& link) const;

  const CollisionWorld& world_;
  vrrw_scene::Robot robot_;
  std::string base_link_;
  std::vector<int> variables_;  ///< index of each arm joint in the world's variable vector
  JointBounds bounds_;
  TimingOptions timing_;
  std::map<std::string, std::unique_ptr<IkSolver>> solvers_;
  std::unique_ptr<StateChecker> checker_;
  Eigen::VectorXd checker_state_;
  std::uint64_t checker_revision_ = 0;
};
}  // namespace vrrw_kinematics

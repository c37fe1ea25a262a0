#pragma once
#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <vrrw_kinematics/ik_options.h>
#include <vrrw_kinematics/ik_solver.h>
#include <vrrw_kinematics/joint_bounds.h>
#include <vrrw_kinematics/segment_checker.h>
#include <vrrw_kinematics/state_checker.h>
#include <vrrw_trajectory/joint_trajectory.h>

namespace ompl
{
namespace base
{
class SpaceInformation;
class RealVectorStateSpace;
}  // namespace base
}  // namespace ompl

namespace vrrw_kinematics
{
/// \brief A planning query for one joint group.
struct PlanRequest
{
  Eigen::VectorXd start;
  std::optional<Eigen::VectorXd> goal_joints;
  std::optional<Eigen::Isometry3d> goal_pose;  ///< of the planner's tip link, in the world (root) frame
  std::string planner = "RRTConnect";
  double time_limit = 1.0;  ///< s, IK goal sampling included
  bool simplify = true;       ///< drop every waypoint a straight valid segment can skip
  /// Random shortcuts after that: in paper_multibot 10 give 9% shorter paths for 30% more p95 time.
  int shortcut_attempts = 0;
  std::uint64_t seed = 1;
  IkOptions ik;
};

/// \brief A collision-free joint path, or why there is none.
struct PlanResult
{
  bool success = false;
  ErrorCode code = ErrorCode::PlanningFailed;
  std::string message;
  Contact contact;                    ///< on InCollision: the colliding pair
  std::vector<Eigen::VectorXd> path;  ///< waypoints, start first
  double planning_time = 0.0;         ///< s
  double path_length = 0.0;           ///< joint-space length (rad, m)
};

/// \brief Geometric motion planning for one joint group with OMPL, the other robots and objects frozen.
///
/// Motions are checked at a resolution such that no point of a moving body travels more than
/// `resolution` metres between two checked states (per-joint reach bounds, see StateChecker::reach()); in
/// between, a motion may graze something, half of that deep past a face (SegmentChecker gives the bounds),
/// as MoveIt's discrete motion checks may: pad the scene's objects where a graze matters.
/// Continuous joints have no limits: they take any value, and plan within pi of their start value.
class MotionPlanner
{
public:
  /// \brief `joints` of world.model(); `tip_link` for pose goals; `world_state` fixes every other joint.
  MotionPlanner(const CollisionWorld& world, const std::vector<std::string>& joints, const std::string& tip_link,
                const Eigen::VectorXd& world_state, double resolution = 0.01);
  ~MotionPlanner();

  PlanResult plan(const PlanRequest& request);

  /// \brief Number of joints of the group.
  std::size_t size() const { return bounds_.size(); }
  /// \brief The group's joints, in the order of its joint vectors.
  const std::vector<std::string>& jointNames() const { return bounds_.names(); }
  /// \brief The group's joint limits.
  const JointBounds& bounds() const { return bounds_; }
  /// \brief Success when `q` has the group's size, lies within the limits and touches nothing; else
  /// InvalidArgument, OutsideLimits or InCollision (with the pair), the message starting with "<label>: ".
  PlanResult checkEndpoint(const Eigen::VectorXd& q, const std::string& label);
  const Eigen::VectorXd& lowerLimits() const { return bounds_.lower(); }
  const Eigen::VectorXd& upperLimits() const { return bounds_.upper(); }
  const IkSolver& ik() const { return *ik_; }
  /// \brief Pose of the chain base in the world, for pose goals.
  const Eigen::Isometry3d& chainBasePose() const { return chain_base_pose_; }
  /// \brief Collision state of the group at q (limits not checked).
  Contact check(const Eigen::VectorXd& q) { return checker_.check(q); }
  bool stateValid(const Eigen::VectorXd& q);
  /// \brief The longest travel (m) of any point between two checked states (SegmentChecker).
  double resolution() const { return segments_.resolution(); }
  /// \brief Number of steps the straight segment a-b is checked in (SegmentChecker::steps).
  std::size_t segmentSteps(const Eigen::VectorXd& a, const Eigen::VectorXd& b) const { return segments_.steps(a, b); }
  /// \brief SegmentChecker::valid: every step of the straight segment a-b (b included, a not).
  bool segmentValid(const Eigen::VectorXd& a, const Eigen::VectorXd& b, double* valid_fraction = nullptr)
  {
    return segments_.valid(a, b, valid_fraction);
  }
  /// \brief True when every segment of `path` is valid.
  bool pathValid(const std::vector<Eigen::VectorXd>& path);
  /// \brief True when the motion between consecutive trajectory samples is valid (blended corners leave
  /// the planned polyline, so a timed trajectory is checked again).
  bool trajectoryValid(const vrrw_trajectory::JointTrajectory& trajectory);

private:
  PlanResult fail(ErrorCode code, const std::string& message, const Contact& contact = {}) const;
  bool goalStates(const PlanRequest& request, double budget, std::vector<Eigen::VectorXd>& goals, PlanResult& error);

  StateChecker checker_;
  JointBounds bounds_;
  SegmentChecker segments_;
  std::unique_ptr<IkSolver> ik_;
  Eigen::Isometry3d chain_base_pose_ = Eigen::Isometry3d::Identity();
  std::shared_ptr<ompl::base::RealVectorStateSpace> space_;
  std::shared_ptr<ompl::base::SpaceInformation> si_;
  std::uint64_t sampler_seed_ = 1;
};

/// \brief Joint-space length of a path.
double pathLength(const std::vector<Eigen::VectorXd>& path);
}  // namespace vrrw_kinematics

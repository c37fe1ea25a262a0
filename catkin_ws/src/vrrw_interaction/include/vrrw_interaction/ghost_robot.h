#pragma once
#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <functional>
#include <optional>
#include <string>
#include <vector>
#include <vrrw_kinematics/arm.h>

#include <vrrw_interaction/presets.h>

namespace vrrw_interaction
{
/// \brief What a ghost request did: success and one line (what was done, or which field was wrong and why).
struct Outcome
{
  bool success = false;
  std::string message;
};

/// \brief A robot's ghost (the paper's semi-transparent double): an arm configuration the operator poses by
/// joints, TCP pose or preset, the waypoints collected on the way, and the last plan from the robot through
/// them to the ghost. Every request that would put the ghost outside its limits or into the scene is refused
/// and leaves it where it was. ROS-free; not thread-safe (it uses the Arm's solvers).
class GhostRobot
{
public:
  /// \brief The ghost of `arm` (which must outlive it) at `q`.
  GhostRobot(vrrw_kinematics::Arm& arm, Presets presets, const Eigen::VectorXd& q);

  const vrrw_kinematics::Arm& arm() const { return arm_; }
  const Presets& presets() const { return presets_; }
  /// \brief The ghost's arm joints (base to tip).
  const Eigen::VectorXd& joints() const { return q_; }
  /// \brief World pose of the ghost's TCP, the rest of the world at `world_state`.
  Eigen::Isometry3d tcpPose(const Eigen::VectorXd& world_state);

  /// \brief names empty: `positions` holds every arm joint in order; else the named (prefixed) joints.
  Outcome setJoints(const std::vector<std::string>& names, const std::vector<double>& positions,
                    const Eigen::VectorXd& world_state);
  /// \brief The TCP at `target` (world) by IK nearest the ghost, no joint moving more than `max_jump`.
  /// On refusal `residual` (when given) gets the IK's position and orientation error (m, rad).
  Outcome setPose(const Eigen::Isometry3d& target, const Eigen::VectorXd& world_state, double max_jump,
                  Eigen::Vector2d* residual = nullptr);
  /// \brief The preset's joints exactly; refused only outside the limits (a colliding preset is taken and
  /// the message says what it touches).
  Outcome preset(const std::string& name, const Eigen::VectorXd& world_state);
  /// \brief The ghost equals the robot (its arm in `world_state`); waypoints and plan stay.
  Outcome reset(const Eigen::VectorXd& world_state);

  /// \brief Appends the ghost's configuration to the waypoints.
  Outcome addWaypoint();
  Outcome clearWaypoints();
  const std::vector<Eigen::VectorXd>& waypoints() const { return waypoints_; }

  /// \brief While set, called with true before the ghost's own pose is checked (setPose, setJoints) and
  /// before the plan's last leg (the place: last waypoint to ghost) is planned, and with false after: the
  /// node lets the object the robot holds touch the surface it is set down on there (as MoveIt's place lets
  /// it touch its support surface), while every earlier leg keeps it clear.
  std::function<void(bool)> place_contact;

  /// \brief Collision-free from the robot (its arm in `world_state`) through every waypoint in order to the
  /// ghost; kept as the last plan when it succeeds. time_limit <= 0: 1 s (for each of the two plans when
  /// place_contact splits off the last leg).
  vrrw_kinematics::TrajectoryResult plan(const Eigen::VectorXd& world_state, double time_limit,
                                         const vrrw_kinematics::SpeedScaling& scaling = {},
                                         vrrw_kinematics::TimeProfile profile = vrrw_kinematics::TimeProfile::TimeOptimal);
  /// \brief The last successful plan, if any.
  const std::optional<vrrw_trajectory::JointTrajectory>& lastPlan() const { return last_plan_; }
  /// \brief Forgets the last plan (it was executed, or the robot moved away from its start).
  void clearPlan() { last_plan_.reset(); }

private:
  /// \brief Takes `q` when it is within limits and touches nothing, else says why.
  Outcome moveTo(const Eigen::VectorXd& q, const Eigen::VectorXd& world_state, const std::string& what);

  vrrw_kinematics::Arm& arm_;
  Presets presets_;
  Eigen::VectorXd q_;
  std::vector<Eigen::VectorXd> waypoints_;
  std::optional<vrrw_trajectory::JointTrajectory> last_plan_;
};

/// \brief One line for a refused IK: "unreachable (residual 0.12 m, 0.30 rad)", "joint jump ...",
/// "collision: A - B".
std::string ikRefusal(const vrrw_kinematics::IkResult& ik);
}  // namespace vrrw_interaction

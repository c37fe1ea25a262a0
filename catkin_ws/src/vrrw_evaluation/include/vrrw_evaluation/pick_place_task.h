#pragma once
#include <Eigen/Geometry>
#include <array>
#include <string>
#include <vrrw_kinematics/time_parameterization.h>

namespace vrrw_evaluation
{
/// \brief The paper's pick-and-place instruction set (section III-C), in order.
inline const std::array<std::string, 6> kInstructions = { "move_to_near_pick", "move_to_pick", "close_gripper",
                                                          "back_to_near_pick", "move_to_final", "open_gripper" };
/// \brief True for the two gripper instructions (GripperCommand goals); the others move the arm.
bool isGripperInstruction(const std::string& name);

/// \brief How the drill is taken: from above, fingers across the motor housing over the centre of mass
/// (vrrw_physics' grasp test: 1 mm from the TCP, 0.45 mm slip), the tool's y axis along the drill's y.
struct GraspGeometry
{
  Eigen::Vector3d grasp_point{ 0.03, 0.0, 0.203 };  ///< in the drill's frame: the TCP there when closed
  double approach = 0.12;        ///< m above the grasp point: near-pick
  double finger_open = 0.0;      ///< finger_joint, rad
  double finger_closed = 0.8;    ///< rad: past the 64 mm housing, so the grip stalls on it
  double grip_force = 70.0;      ///< N per pad (GripperCommand max_effort); the drill weighs 14.7 N
  /// m the drill's base is above the table when the gripper opens; below 0: pressed onto it, so a drill
  /// swinging about the pads' axis (a two-finger grip cannot hold that rotation) stands flat before release
  double release_height = -0.002;
};

/// \brief TCP pose (world) that holds the drill standing at `drill` (world pose of its frame).
Eigen::Isometry3d tcpAtGrasp(const Eigen::Isometry3d& drill, const GraspGeometry& grasp);
/// \brief The TCP `grasp.approach` straight above tcpAtGrasp: near-pick.
Eigen::Isometry3d tcpAtNearPick(const Eigen::Isometry3d& drill, const GraspGeometry& grasp);
/// \brief Where the drill is when the TCP is at `tcp` holding it as tcpAtGrasp says.
Eigen::Isometry3d drillInHand(const Eigen::Isometry3d& tcp, const Eigen::Isometry3d& drill_at_grasp,
                              const Eigen::Isometry3d& tcp_at_grasp);

/// \brief Straight line from `from` to `to` (orientation by slerp) at blend `s` in [0, 1].
Eigen::Isometry3d interpolatePose(const Eigen::Isometry3d& from, const Eigen::Isometry3d& to, double s);
/// \brief The TCP lines' blend (vrrw_kinematics' minimum jerk).
using vrrw_kinematics::minimumJerk;
}  // namespace vrrw_evaluation

#pragma once
#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vrrw_kinematics/arm.h>

#include <vrrw_interaction/grab_target.h>

namespace vrrw_interaction
{
/// \brief One tracked 6-DoF hand (a VR controller, a mocap marker, a script): its pose, its grip, and the
/// point it holds. Closing the grip (crossing 0.5 upwards) asks for a grab, opening it releases; a hand
/// whose pose is older than the stale time lets go (a lost tracker must not keep pulling). ROS-free.
class Hand
{
public:
  enum class GripChange { None, Close, Open };

  explicit Hand(std::string id) : id_(std::move(id)) {}
  const std::string& id() const { return id_; }

  /// \brief A new pose (world) at time `t` (s).
  void setPose(const Eigen::Isometry3d& pose, double t);
  bool hasPose() const { return has_pose_; }
  /// \brief The time of the last pose (setPose's `t`).
  double poseTime() const { return stamp_; }
  const Eigen::Isometry3d& pose() const { return pose_; }
  /// \brief True when the last pose is older than `timeout` at `now` (or there is none).
  bool stale(double now, double timeout = 0.5) const { return !has_pose_ || now - stamp_ > timeout; }

  /// \brief A new grip value (checked by gripError first): whether it closed or opened the hand.
  GripChange setGrip(double grip);
  bool closed() const { return closed_; }

  /// \brief Takes hold of `target`, keeping the offset from the hand to the touched point.
  void hold(const GrabTarget& target);
  void release() { held_.reset(); }
  const std::optional<GrabTarget>& held() const { return held_; }
  /// \brief Where the held point belongs now: carried rigidly with the hand since the grab.
  Eigen::Vector3d heldPointTarget() const { return pose_ * point_in_hand_; }
  /// \brief `at_grab` (a pose at the moment of the grab) carried rigidly with the hand since then.
  Eigen::Isometry3d carried(const Eigen::Isometry3d& at_grab) const { return pose_ * pose_at_grab_.inverse() * at_grab; }

private:
  std::string id_;
  Eigen::Isometry3d pose_ = Eigen::Isometry3d::Identity();
  double stamp_ = 0.0;
  bool has_pose_ = false;
  bool closed_ = false;
  std::optional<GrabTarget> held_;
  Eigen::Vector3d point_in_hand_ = Eigen::Vector3d::Zero();
  Eigen::Isometry3d pose_at_grab_ = Eigen::Isometry3d::Identity();
};

/// \brief The world pose of `arm`'s TCP at `world_state`.
Eigen::Isometry3d tcpPose(vrrw_kinematics::Arm& arm, const Eigen::VectorXd& world_state);

/// \brief Free-drive without physics (fake mode): the arm configuration nearest the live one that puts the TCP
/// where `hand` has carried it since the grab (`tcp_at_grab`), collision-free, no joint moving more than
/// `max_jump` (a branch flip is refused, as for the ghost's marker).
vrrw_kinematics::IkResult armFollowingHand(vrrw_kinematics::Arm& arm, const Hand& hand,
                                           const Eigen::Isometry3d& tcp_at_grab, const Eigen::VectorXd& world_state,
                                           double max_jump = 0.5);

/// \brief "" when `grip` is a usable grip value (finite, 0 open .. 1 closed), else the reason.
std::string gripError(double grip);
}  // namespace vrrw_interaction

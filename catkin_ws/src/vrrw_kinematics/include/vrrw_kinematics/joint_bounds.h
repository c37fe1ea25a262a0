#pragma once
#include <Eigen/Dense>
#include <string>
#include <vector>

#include <vrrw_kinematics/robot_model.h>

namespace vrrw_kinematics
{
/// \brief The limits of a group of joints (an arm) as planning and IK treat them: continuous joints have
/// none and take any value.
class JointBounds
{
public:
  /// \brief Limits of `joints` of `model`, in that order; throws KinematicsError(InvalidArgument) for a joint
  /// the model does not have.
  JointBounds(const RobotModel& model, const std::vector<std::string>& joints);

  /// \brief Number of joints.
  std::size_t size() const { return names_.size(); }
  /// \brief The joints, in the order of the group's joint vectors.
  const std::vector<std::string>& names() const { return names_; }
  /// \brief Lower limits (rad, m); meaningless for continuous joints.
  const Eigen::VectorXd& lower() const { return lower_; }
  /// \brief Upper limits (rad, m); meaningless for continuous joints.
  const Eigen::VectorXd& upper() const { return upper_; }
  /// \brief True for a continuous joint.
  bool continuous(std::size_t i) const { return continuous_[i]; }
  /// \brief "" when `q` has one finite value per joint, each within its limits (1e-9 slack), else the first
  /// problem ("joint elbow_joint = 4.000000 outside [-3.141593, 3.141593]").
  std::string violation(const Eigen::VectorXd& q) const;
  /// \brief `q` with every continuous joint moved by whole turns to within pi of `reference`.
  Eigen::VectorXd nearestTurn(const Eigen::VectorXd& q, const Eigen::VectorXd& reference) const;

private:
  std::vector<std::string> names_;
  Eigen::VectorXd lower_;
  Eigen::VectorXd upper_;
  std::vector<bool> continuous_;
};
}  // namespace vrrw_kinematics

#pragma once
#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <random>
#include <string>
#include <vector>

#include "vrrw_kinematics/robot_model.h"

namespace vrrw_kinematics
{
/// \brief One movable joint of a serial chain, with the fixed transform that precedes it.
struct ChainJoint
{
  std::string name;
  bool prismatic = false;
  bool continuous = false;
  Eigen::Isometry3d before = Eigen::Isometry3d::Identity();  ///< previous joint's child frame to this joint frame
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();           ///< in the joint frame
  double lower = 0.0;
  double upper = 0.0;
  double max_velocity = 0.0;
};

/// \brief A serial chain from a base link to a tip link of a URDF (any joints: revolute, continuous,
/// prismatic, fixed; no mimic or floating joints), with FK and the geometric Jacobian.
class KinematicChain
{
public:
  /// \brief Chain of `model` from `base` down to `tip`; throws KinematicsError (UnknownLink, NotSerialChain).
  KinematicChain(const RobotModel& model, const std::string& base, const std::string& tip);
  /// \brief Parses `urdf_xml` (urdfdom) and builds the chain base to tip.
  static KinematicChain fromUrdf(const std::string& urdf_xml, const std::string& base, const std::string& tip);

  const std::string& baseLink() const { return base_; }
  const std::string& tipLink() const { return tip_; }
  std::size_t size() const { return joints_.size(); }
  const std::vector<ChainJoint>& joints() const { return joints_; }
  std::vector<std::string> jointNames() const;
  /// \brief Links from base to tip, in order.
  const std::vector<std::string>& linkNames() const { return link_names_; }
  const Eigen::Isometry3d& tipOffset() const { return after_; }

  Eigen::VectorXd lowerLimits() const;
  Eigen::VectorXd upperLimits() const;
  Eigen::VectorXd midLimits() const;
  /// \brief True when every q_i is finite and within its limits (with `tolerance`); continuous joints have none.
  bool withinLimits(const Eigen::VectorXd& q, double tolerance = 1e-9) const;
  /// \brief Name of the first joint outside its limits, or "" when none.
  std::string jointOutsideLimits(const Eigen::VectorXd& q, double tolerance = 1e-9) const;
  /// \brief Uniform sample within limits ([-pi, pi] for continuous joints).
  Eigen::VectorXd randomState(std::mt19937_64& rng) const;

  /// \brief Pose of the tip in the base frame.
  Eigen::Isometry3d fk(const Eigen::VectorXd& q) const;
  /// \brief Pose of any link of the chain in the base frame; throws KinematicsError(UnknownLink).
  Eigen::Isometry3d fk(const Eigen::VectorXd& q, const std::string& link) const;
  /// \brief Tip pose and 6xN geometric Jacobian (linear rows first) in the base frame.
  void jacobian(const Eigen::VectorXd& q, Eigen::Isometry3d& tip, Eigen::Matrix<double, 6, Eigen::Dynamic>& jac) const;

private:
  struct ChainLink
  {
    int joint = -1;  ///< last movable joint at or above this link; -1 for links fixed to the base
    Eigen::Isometry3d offset = Eigen::Isometry3d::Identity();
  };

  std::string base_;
  std::string tip_;
  std::vector<ChainJoint> joints_;
  std::vector<std::string> link_names_;
  std::vector<ChainLink> links_;
  Eigen::Isometry3d after_ = Eigen::Isometry3d::Identity();
};

/// \brief Rotation error as a rotation vector: log(R_target * R_current^T), in the base frame.
Eigen::Vector3d rotationError(const Eigen::Matrix3d& target, const Eigen::Matrix3d& current);
}  // namespace vrrw_kinematics

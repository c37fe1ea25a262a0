#pragma once
#include <Eigen/Geometry>
#include <vector>

class btMultiBody;
struct btMultiBodyJacobianData;
struct btMultiBodySolverConstraint;

namespace vrrw_physics
{
/// \brief Most movable joints of one robot (storage of joint-space matrices is fixed, no heap).
constexpr int kMaxJoints = 32;
using JointMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxJoints, kMaxJoints>;
using JointVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxJoints, 1>;

/// \brief Joint-space inertia M of a fixed-base multibody whose link k is joint k (one revolute or
/// prismatic dof per link, as ArticulatedRobot builds them), by the composite rigid body algorithm on the
/// world poses of its Bullet frames (`frames[0]` the base, `frames[k + 1]` link k, as
/// ArticulatedRobot::framePoses()). Featherstone, "Rigid Body Dynamics Algorithms", 2008, ch. 6.
JointMatrix jointSpaceInertia(const btMultiBody& body, const std::vector<Eigen::Isometry3d>& frames);

/// \brief M^-1 of one robot for the current step, so solver rows on joint coordinates need no
/// articulated-body pass each (Bullet's fillMultiBodyConstraint does two per row).
class JointSpaceResponse
{
public:
  /// \brief M of the current configuration; its inverse is computed on first use.
  void setInertia(const JointMatrix& inertia);
  void invalidate() { valid_ = false; }
  /// \brief false: rows fall back to Bullet's own fill.
  bool valid() const { return valid_; }
  const JointMatrix& inverse() const;

  std::vector<int> joint_of_dof;  ///< Bullet dof index -> joint index

private:
  const JointMatrix* inertia_ = nullptr;
  mutable JointMatrix inverse_;
  mutable bool inverted_ = false;
  bool valid_ = false;
};

/// \brief true when jointSpaceAccelerations can step `body` with `response`: a fixed base, one
/// revolute or prismatic dof per link, body-local velocities, no joint feedback, Euler integration, a
/// valid M of the current configuration.
bool supportsJointSpaceAccelerations(const btMultiBody& body, const JointSpaceResponse& response);

/// \brief The accelerations of Bullet's articulated-body pass (computeAccelerationsArticulatedBodyAlgorithmMultiDof
/// with isConstraintPass false: joint torques, link forces and torques, gravity as link forces, damping and
/// gyroscopic terms) as qdd = M^-1 (tau - c): c by one recursive Newton-Euler pass in Bullet's link frames with
/// qdd = 0 (Featherstone 2008, ch. 5), M^-1 from `response`. `qdd` has 6 + dofs entries (the base's 6 are 0).
/// Equal to Bullet's up to rounding; unlike Bullet's pass it caches nothing for contact rows.
void jointSpaceAccelerations(const btMultiBody& body, const JointSpaceResponse& response, double* qdd);

/// \brief Fills one solver row acting on up to two joint coordinates of `body` (coefficients on
/// Bullet links link_a / link_b, link_b < 0 for none): the row drives the coordinate rate to
/// `goal_velocity` with softness `cfm` (0: hard) inside [lower, upper] impulse bounds.
/// Returns the current rate of the coordinate.
double fillJointRow(btMultiBodySolverConstraint& row, btMultiBodyJacobianData& data, btMultiBody* body,
                    const JointSpaceResponse& response, int link_a, double coeff_a, int link_b, double coeff_b,
                    double goal_velocity, double cfm, double lower, double upper);
}  // namespace vrrw_physics

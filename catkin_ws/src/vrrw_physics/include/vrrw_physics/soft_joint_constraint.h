#pragma once
#include <BulletDynamics/Featherstone/btMultiBodyConstraint.h>
#include <vrrw_physics/joint_space_inertia.h>

namespace vrrw_physics
{
/// \brief Constraint-space softness of an implicit spring-damper over one step h.
///
/// The drive impulse over a step is lambda = h*(K*(e - h*v) + D*(v_target - v)), with e the
/// position error at the start of the step and v the velocity at its end (positions are integrated
/// with the new velocity, semi-implicit Euler). Solving for v gives the velocity constraint
///   v + cfm*lambda = (erp/h)*e + (1 - erp)*v_target,
///   erp = h*K / (h*K + D),  cfm = 1 / (h*(h*K + D)),
/// which the sequential-impulse solver satisfies exactly for one row and by Gauss-Seidel iteration
/// for coupled rows. It is implicit Euler on the spring-damper, stable for any K, D >= 0 and h > 0
/// (Catto, "Soft Constraints", GDC 2011; Tan, Liu, Turk, "Stable Proportional-Derivative
/// Controllers", 2011).
struct Softness
{
  double erp = 0.0;
  double cfm = 0.0;
};

/// \brief erp and cfm of an implicit spring (K) and damper (D) over a step h; K, D >= 0, K + D > 0.
Softness implicitSpringDamper(double h, double stiffness, double damping);

/// \brief One row acting on a combination of joint coordinates of one btMultiBody:
/// c = sum_i a_i * q_i, driven towards its target by an implicit spring-damper with a force limit.
///
/// Base for JointDrive (one coordinate) and JointCoupling (mimic: q_mimic - m*q_master).
class SoftJointConstraint : public btMultiBodyConstraint
{
public:
  /// \brief body: the robot; links and coefficients: up to two 1-dof joints and their weights;
  /// response: the robot's M^-1 for the step (may be null: Bullet computes the row's response).
  SoftJointConstraint(btMultiBody* body, int link_a, double coeff_a, int link_b, double coeff_b, int type,
                      const JointSpaceResponse* response);

  void finalizeMultiDof() override;
  int getIslandIdA() const override;
  int getIslandIdB() const override;
  void createConstraintRows(btMultiBodyConstraintArray& rows, btMultiBodyJacobianData& data,
                            const btContactSolverInfo& info) override;
  void debugDraw(btIDebugDraw*) override {}

  /// \brief Spring stiffness (N/m or Nm/rad) and damping (N s/m or Nm s/rad), both >= 0.
  void setGains(double stiffness, double damping);
  /// \brief Largest force or torque the row may apply (> 0).
  void setForceLimit(double max_force);
  /// \brief Target of the combination c and of its rate.
  void setTarget(double position, double velocity);

  double stiffness() const { return stiffness_; }
  double damping() const { return damping_; }
  double forceLimit() const { return max_force_; }
  double targetPosition() const { return target_position_; }
  double targetVelocity() const { return target_velocity_; }
  /// \brief Current value of the combination c.
  double position() const;
  /// \brief Current rate of the combination c.
  double velocity() const;

private:
  const JointSpaceResponse* response_;
  int link_b_;
  double coeff_a_;
  double coeff_b_;
  double stiffness_ = 0.0;
  double damping_ = 0.0;
  double max_force_ = 1e9;
  double target_position_ = 0.0;
  double target_velocity_ = 0.0;
};
}  // namespace vrrw_physics

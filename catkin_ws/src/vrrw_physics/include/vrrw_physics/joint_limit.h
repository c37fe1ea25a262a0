#pragma once
#include <BulletDynamics/Featherstone/btMultiBodyConstraint.h>

namespace vrrw_physics
{
/// \brief Island of a multibody link's constraints: the tag of its collider, or of any collider of
/// the body when the link has none (constraints of untagged links are never solved).
int constraintIsland(const btMultiBody* body, int link);

/// \brief Lower and upper limit of a 1-dof joint as speculative unilateral rows, created only when
/// the joint could reach a limit within the next step (so a robot far from its limits costs nothing):
/// qd >= (lower - q)/h and -qd >= (q - upper)/h, impulse >= 0.
class JointLimit : public btMultiBodyConstraint
{
public:
  JointLimit(btMultiBody* body, int link, double lower, double upper);

  void finalizeMultiDof() override;
  int getIslandIdA() const override;
  int getIslandIdB() const override;
  void createConstraintRows(btMultiBodyConstraintArray& rows, btMultiBodyJacobianData& data,
                            const btContactSolverInfo& info) override;
  void debugDraw(btIDebugDraw*) override {}

  double lower() const { return lower_; }
  double upper() const { return upper_; }

private:
  double lower_;
  double upper_;
};
}  // namespace vrrw_physics

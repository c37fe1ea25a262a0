#pragma once
#include <BulletDynamics/Featherstone/btMultiBodyConstraint.h>
#include <vrrw_physics/joint_space_inertia.h>

#include <vector>

namespace vrrw_physics
{
/// \brief Island of a multibody link's constraints: the tag of its collider, or of any collider of
/// the body when the link has none (constraints of untagged links are never solved).
int constraintIsland(const btMultiBody* body, int link);

/// \brief Position limit of one 1-dof joint.
struct JointRange
{
  int link = -1;  ///< Bullet link index
  double lower = 0.0;
  double upper = 0.0;
};

/// \brief Every joint limit of one robot as speculative unilateral rows, created only for joints
/// that could reach a limit within the next step (a robot far from its limits costs nothing):
/// qd >= (lower - q)/h and -qd >= (q - upper)/h, impulse >= 0; a violated limit is pushed back
/// with the solver's erp. One constraint per robot keeps Bullet's per-constraint island sorting cheap.
class JointLimits : public btMultiBodyConstraint
{
public:
  JointLimits(btMultiBody* body, const std::vector<JointRange>& ranges, const JointSpaceResponse* response = nullptr);

  void finalizeMultiDof() override;
  int getIslandIdA() const override;
  int getIslandIdB() const override;
  void createConstraintRows(btMultiBodyConstraintArray& rows, btMultiBodyJacobianData& data,
                            const btContactSolverInfo& info) override;
  void debugDraw(btIDebugDraw*) override {}

  const std::vector<JointRange>& ranges() const { return ranges_; }

private:
  std::vector<JointRange> ranges_;
  const JointSpaceResponse* response_;
};
}  // namespace vrrw_physics

#pragma once
#include <BulletDynamics/Featherstone/btMultiBodyConstraint.h>

#include <vector>

namespace vrrw_physics
{
/// \brief The joint constraints of one robot (drives, couplings, limits) handed to Bullet as a single
/// constraint: Bullet sorts and visits constraints per island with virtual calls, so one object per
/// robot instead of one per joint keeps that bookkeeping off the step's critical path. Each member
/// still writes its own rows and receives its own applied impulses.
class JointRowGroup : public btMultiBodyConstraint
{
public:
  explicit JointRowGroup(btMultiBody* body);

  /// \brief Adds a member (not owned); its rows are created in the order added.
  void add(btMultiBodyConstraint* member);

  void finalizeMultiDof() override {}
  int getIslandIdA() const override;
  int getIslandIdB() const override;
  void createConstraintRows(btMultiBodyConstraintArray& rows, btMultiBodyJacobianData& data,
                            const btContactSolverInfo& info) override;
  void debugDraw(btIDebugDraw*) override {}

private:
  std::vector<btMultiBodyConstraint*> members_;
  const btCollisionObject* island_object_ = nullptr;
};
}  // namespace vrrw_physics

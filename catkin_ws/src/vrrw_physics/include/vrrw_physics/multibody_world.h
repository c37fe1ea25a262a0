#pragma once
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>

#include <vector>

namespace vrrw_physics
{
class JointSpaceResponse;

/// \brief btMultiBodyDynamicsWorld without the per-step prediction of link transforms, and optionally
/// with forward dynamics from the joint-space inertia in place of Bullet's articulated-body pass.
///
/// Bullet 3.24 predicts every multibody's positions at the end of the step
/// (predictPositionsMultiDof) and stores them as the link colliders' interpolation transforms;
/// only continuous collision of rigid bodies and deformable bodies read those, and this workspace has
/// neither on robot links, so the step's results are bit-identical without it (about 5 % of a
/// paper_multibot step). Rigid bodies are still predicted as before.
///
/// A body given to setJointSpaceDynamics has its velocities stepped by qdd = M^-1 (tau - c)
/// (jointSpaceAccelerations) instead of Bullet's articulated-body pass, whenever nothing needs what that
/// pass caches: Bullet's contact rows and constraints of its own (a weld) read the articulated inertias
/// through calcAccelerationDeltasMultiDof, so a body with a contact point in a manifold, a multibody
/// constraint other than this library's joint rows, or no valid M takes Bullet's pass for that step.
/// Equal to Bullet's step up to rounding.
ATTRIBUTE_ALIGNED16(class) MultiBodyWorld : public btMultiBodyDynamicsWorld
{
public:
  BT_DECLARE_ALIGNED_ALLOCATOR();
  using btMultiBodyDynamicsWorld::btMultiBodyDynamicsWorld;

  /// \brief Steps `body` with the M^-1 of `response` (kept by the caller, current at every step) when it can.
  void setJointSpaceDynamics(btMultiBody* body, const JointSpaceResponse* response);
  /// \brief Bodies stepped without Bullet's articulated-body pass in the last step.
  int jointSpaceSteppedBodies() const { return int(ours_.size()); }

protected:
  void predictUnconstraintMotion(btScalar timeStep) override;
  void solveExternalForces(btContactSolverInfo& solverInfo) override;

private:
  struct Entry
  {
    btMultiBody* body;
    const JointSpaceResponse* response;
  };
  std::vector<Entry> joint_space_;
  std::vector<Entry> ours_;
  std::vector<const btMultiBody*> bullet_needed_;
  btAlignedObjectArray<btMultiBody*> all_bodies_;
  btAlignedObjectArray<btMultiBody*> bullet_bodies_;
  double qdd_[6 + 64];
};
}  // namespace vrrw_physics

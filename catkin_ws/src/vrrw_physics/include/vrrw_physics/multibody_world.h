#pragma once
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>

namespace vrrw_physics
{
/// \brief btMultiBodyDynamicsWorld without the per-step prediction of link transforms.
///
/// Bullet 3.24 predicts every multibody's positions at the end of the step
/// (predictPositionsMultiDof) and stores them as the link colliders' interpolation transforms;
/// only continuous collision of rigid bodies and deformable bodies read those, and this workspace has
/// neither on robot links, so the step's results are bit-identical without it (about 5 % of a
/// paper_multibot step). Rigid bodies are still predicted as before.
ATTRIBUTE_ALIGNED16(class) MultiBodyWorld : public btMultiBodyDynamicsWorld
{
public:
  BT_DECLARE_ALIGNED_ALLOCATOR();
  using btMultiBodyDynamicsWorld::btMultiBodyDynamicsWorld;

protected:
  void predictUnconstraintMotion(btScalar timeStep) override;
};
}  // namespace vrrw_physics

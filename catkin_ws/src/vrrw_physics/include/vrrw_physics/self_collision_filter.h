#pragma once
#include <BulletCollision/BroadphaseCollision/btOverlappingPairCache.h>

namespace vrrw_physics
{
/// \brief Broadphase filter: Bullet's group/mask test, and no pair between two links of one multibody
/// whose self-collision is off.
///
/// Such pairs never make a contact (btMultiBodyLinkCollider::checkCollideWithOverride rejects them in
/// the narrowphase), but without this filter the broadphase keeps every overlapping one: in
/// paper_multibot 198 of 210 pairs, visited by the dispatcher and the island builder every step.
class SelfCollisionFilter : public btOverlapFilterCallback
{
public:
  bool needBroadphaseCollision(btBroadphaseProxy* proxy0, btBroadphaseProxy* proxy1) const override;
};
}  // namespace vrrw_physics

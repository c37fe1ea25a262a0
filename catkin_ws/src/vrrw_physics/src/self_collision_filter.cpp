#include <vrrw_physics/self_collision_filter.h>

#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>

namespace vrrw_physics
{
bool SelfCollisionFilter::needBroadphaseCollision(btBroadphaseProxy* proxy0, btBroadphaseProxy* proxy1) const
{
  // Bullet's own test (btHashedOverlappingPairCache::needsBroadphaseCollision without a callback).
  if ((proxy0->m_collisionFilterGroup & proxy1->m_collisionFilterMask) == 0 ||
      (proxy1->m_collisionFilterGroup & proxy0->m_collisionFilterMask) == 0)
    return false;
  const btMultiBodyLinkCollider* a =
      btMultiBodyLinkCollider::upcast(static_cast<const btCollisionObject*>(proxy0->m_clientObject));
  const btMultiBodyLinkCollider* b =
      btMultiBodyLinkCollider::upcast(static_cast<const btCollisionObject*>(proxy1->m_clientObject));
  return !(a && b && a->m_multiBody == b->m_multiBody && !a->m_multiBody->hasSelfCollision());
}
}  // namespace vrrw_physics

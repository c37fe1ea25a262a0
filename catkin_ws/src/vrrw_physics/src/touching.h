#pragma once
// When a Bullet contact point counts as touching: the contact report and the held-object judgement agree on it.
#include <BulletCollision/NarrowPhaseCollision/btManifoldPoint.h>

namespace vrrw_physics
{
/// A contact point counts while its gap is within the collision margin or the solver pushed through it.
constexpr double kTouchingGap = 0.001;  // m

inline bool isTouching(const btManifoldPoint& point)
{
  return point.getDistance() <= kTouchingGap || point.m_appliedImpulse > 0;
}
}  // namespace vrrw_physics

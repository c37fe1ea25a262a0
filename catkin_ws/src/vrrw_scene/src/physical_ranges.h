#pragma once
// The sizes a workspace cell can have. A number beyond them is a typo (1e30 for 1.30, -10 for 10) that would
// not fail at load but break planning and physics later: Bullet computes in single precision (its step at
// 100 m is 8 um, at 1e30 m nothing moves), KDL and OMPL sample joint ranges (+-1e300 never converges).
namespace vrrw_scene
{
namespace ranges
{
/// m: |x|, |y|, |z| of a robot's base, an object's pose or a random offset (a large hall).
constexpr double kMaxCoordinate = 100.0;
/// m: an object's size, radius or length.
constexpr double kMaxExtent = 100.0;
/// kg: a link or an object (the heaviest industrial arm's base is about 1 t).
constexpr double kMaxMass = 10000.0;
/// kg m^2: a principal moment of inertia (10 t at 1 m).
constexpr double kMaxInertia = 10000.0;
/// rad or m: a joint limit's |lower| and |upper| (16 turns; UR wrists turn +-2 pi).
constexpr double kMaxJointTravel = 100.0;
/// N m or N: a joint's URDF effort limit (the largest industrial arms stay below 1e5 N m).
constexpr double kMaxEffort = 1e6;
/// rad/s or m/s: a joint's URDF velocity limit.
constexpr double kMaxVelocity = 1000.0;
/// an object's friction coefficient (rubber on rubber is about 1-2).
constexpr double kMaxFriction = 10.0;
}  // namespace ranges
}  // namespace vrrw_scene

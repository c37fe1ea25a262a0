#include <vrrw_physics/articulated_robot.h>
#include <vrrw_physics/self_collision_filter.h>

#include <BulletCollision/CollisionShapes/btSphereShape.h>
#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>
#include <gtest/gtest.h>

#include <memory>

using namespace vrrw_physics;

namespace
{
btBroadphaseProxy proxy(btCollisionObject& object, int group, int mask)
{
  btBroadphaseProxy p;
  p.m_clientObject = &object;
  p.m_collisionFilterGroup = group;
  p.m_collisionFilterMask = mask;
  return p;
}

std::unique_ptr<btMultiBody> twoLinks(bool self_collision)
{
  auto body = std::make_unique<btMultiBody>(2, btScalar(1), btVector3(1, 1, 1), true, false);
  for (int i = 0; i < 2; ++i)
    body->setupRevolute(i, btScalar(1), btVector3(1, 1, 1), i - 1, btQuaternion::getIdentity(), btVector3(0, 0, 1),
                        btVector3(0, 0, 0), btVector3(0.1f, 0, 0), true);
  body->finalizeMultiDof();
  body->setHasSelfCollision(self_collision);
  return body;
}
}  // namespace

TEST(SelfCollisionFilter, DropsPairsWithinOneRobotWithoutSelfCollision)
{
  const SelfCollisionFilter filter;
  const int all = btBroadphaseProxy::AllFilter, def = btBroadphaseProxy::DefaultFilter;
  auto robot = twoLinks(false);
  auto other = twoLinks(false);
  auto self = twoLinks(true);
  btMultiBodyLinkCollider a0(robot.get(), 0), a1(robot.get(), 1), b0(other.get(), 0), s0(self.get(), 0),
      s1(self.get(), 1);
  btCollisionObject box;
  auto pa0 = proxy(a0, def, all), pa1 = proxy(a1, def, all), pb0 = proxy(b0, def, all), ps0 = proxy(s0, def, all),
       ps1 = proxy(s1, def, all), pbox = proxy(box, def, all);
  EXPECT_FALSE(filter.needBroadphaseCollision(&pa0, &pa1));  // same robot, self-collision off
  EXPECT_TRUE(filter.needBroadphaseCollision(&pa0, &pb0));   // two robots
  EXPECT_TRUE(filter.needBroadphaseCollision(&pa1, &pbox));  // robot and object
  EXPECT_TRUE(filter.needBroadphaseCollision(&ps0, &ps1));   // self-collision on: kept
  // Bullet's group/mask test still applies.
  auto mute = proxy(b0, def, 0);
  EXPECT_FALSE(filter.needBroadphaseCollision(&pa0, &mute));
  EXPECT_FALSE(filter.needBroadphaseCollision(&mute, &pa0));
}

#include <vrrw_physics/articulated_robot.h>
#include <vrrw_physics/multibody_world.h>

#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>
#include <BulletCollision/CollisionDispatch/btCollisionDispatcher.h>
#include <BulletCollision/CollisionDispatch/btDefaultCollisionConfiguration.h>
#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletDynamics/Dynamics/btRigidBody.h>
#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyConstraintSolver.h>
#include <gtest/gtest.h>
#include <urdf_parser/urdf_parser.h>

#include <cstring>
#include <fstream>
#include <memory>
#include <sstream>
#include <vector>

#include "pendulum_fixture.h"

using namespace vrrw_physics;

namespace
{
/// The test URDF's slider carriage falls onto a fixed box (a contact on a robot link) and a dynamic box
/// falls onto it: joint position and velocity of every step, then the number of steps in contact.
std::vector<float> drop(bool stock_world)
{
  const auto model = vrrw_physics_test::pendulumModel();
  btDefaultCollisionConfiguration config;
  btCollisionDispatcher dispatcher(&config);
  btDbvtBroadphase broadphase;
  btMultiBodyConstraintSolver solver;
  std::unique_ptr<btMultiBodyDynamicsWorld> world;
  if (stock_world)
    world = std::make_unique<btMultiBodyDynamicsWorld>(&dispatcher, &broadphase, &solver, &config);
  else
    world = std::make_unique<MultiBodyWorld>(&dispatcher, &broadphase, &solver, &config);
  world->setGravity(btVector3(0, 0, btScalar(-9.81)));
  btBoxShape floor_shape(btVector3(btScalar(0.5), btScalar(0.5), btScalar(0.1)));
  btRigidBody floor(btRigidBody::btRigidBodyConstructionInfo(0, nullptr, &floor_shape));
  floor.setWorldTransform(btTransform(btQuaternion::getIdentity(), btVector3(3, 0, btScalar(-0.6))));
  world->addRigidBody(&floor);
  btBoxShape cube_shape(btVector3(btScalar(0.03), btScalar(0.03), btScalar(0.03)));
  btVector3 cube_inertia;
  cube_shape.calculateLocalInertia(btScalar(0.2), cube_inertia);
  btRigidBody cube(btRigidBody::btRigidBodyConstructionInfo(btScalar(0.2), nullptr, &cube_shape, cube_inertia));
  cube.setWorldTransform(btTransform(btQuaternion::getIdentity(), btVector3(btScalar(3.01), 0, btScalar(0.2))));
  world->addRigidBody(&cube);
  std::vector<float> trace;
  int touching = 0;
  {
    ArticulatedRobot slider(*model, "s", "s_base_link");
    slider.setState({ 0.0 }, { 0.0 });
    slider.addToWorld(world.get());
    for (int step = 0; step < 1000; ++step)
    {
      world->stepSimulation(btScalar(0.001), 0, btScalar(0.001));
      trace.push_back(slider.body()->getJointPos(0));
      trace.push_back(slider.body()->getJointVel(0));
      trace.push_back(cube.getWorldTransform().getOrigin().z());
      for (int m = 0; m < world->getDispatcher()->getNumManifolds(); ++m)
        touching += world->getDispatcher()->getManifoldByIndexInternal(m)->getNumContacts() > 0;
    }
  }
  world->removeRigidBody(&cube);
  world->removeRigidBody(&floor);
  trace.push_back(float(touching));
  return trace;
}
}  // namespace

TEST(MultiBodyWorld, SameStepsAsBulletsWorldWithoutPredictingLinkTransforms)
{
  const std::vector<float> stock = drop(true);
  const std::vector<float> ours = drop(false);
  ASSERT_EQ(stock.size(), ours.size());
  EXPECT_GT(stock.back(), 500.0f);               // contact counts (carriage on the floor, cube on the carriage)
  EXPECT_LT(stock[stock.size() - 4], -0.3f);     // the carriage fell onto the floor
  EXPECT_EQ(std::memcmp(stock.data(), ours.data(), stock.size() * sizeof(float)), 0);
}

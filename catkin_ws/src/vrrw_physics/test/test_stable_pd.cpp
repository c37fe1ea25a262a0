#include <vrrw_physics/articulated_robot.h>
#include <vrrw_physics/joint_space_inertia.h>
#include <vrrw_physics/stable_pd.h>

#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>
#include <BulletCollision/CollisionDispatch/btDefaultCollisionConfiguration.h>
#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyConstraintSolver.h>
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>
#include <gtest/gtest.h>
#include <urdf_parser/urdf_parser.h>

#include <fstream>
#include <sstream>

#include "pendulum_fixture.h"

using namespace vrrw_physics;


TEST(JointSpaceInertia, InertiaOfThePendulumIsItsMomentAboutTheAxis)
{
  const auto urdf = vrrw_physics_test::pendulumModel();
  ArticulatedRobot robot(*urdf, "p", "p_base_link");
  EXPECT_NEAR(jointSpaceInertia(*robot.body(), robot.framePoses())(0, 0), 0.51, 1e-9);
}

TEST(JointSpaceInertia, InertiaMatchesBulletsResponseToJointImpulses)
{
  const auto urdf = vrrw_physics_test::pendulumModel();
  btDefaultCollisionConfiguration config;
  btCollisionDispatcher dispatcher(&config);
  btDbvtBroadphase broadphase;
  btMultiBodyConstraintSolver solver;
  btMultiBodyDynamicsWorld world(&dispatcher, &broadphase, &solver, &config);
  world.setGravity(btVector3(0, 0, 0));
  {
    ArticulatedRobot robot(*urdf, "a", "a_base_link");
    robot.addToWorld(&world, false);
    const std::vector<double> q0{ 0.4, -0.7, 0.1 };
    const double h = 1e-4;
    robot.setState(q0, { 0, 0, 0 });
    const Eigen::MatrixXd m = jointSpaceInertia(*robot.body(), robot.framePoses());
    for (std::size_t j = 0; j < 3; ++j)
    {
      robot.setState(q0, { 0, 0, 0 });
      Eigen::Vector3d tau = Eigen::Vector3d::Zero();
      tau(Eigen::Index(j)) = 10.0;
      robot.body()->addJointTorque(robot.joints()[j].link, btScalar(tau(Eigen::Index(j))));
      world.stepSimulation(btScalar(h), 0, btScalar(h));
      const auto v = robot.velocities();
      const Eigen::Vector3d acceleration = Eigen::Vector3d(v[0], v[1], v[2]) / h;
      EXPECT_LT((m * acceleration - tau).norm(), 1e-3 * tau.norm()) << "joint " << j;
    }
  }
}

TEST(StablePd, ImplicitTorqueBringsTheJointToItsPredictedVelocity)
{
  const auto urdf = vrrw_physics_test::pendulumModel();
  ArticulatedRobot robot(*urdf, "p", "p_base_link");
  robot.setState({ 0.0 }, { 0.2 });
  robot.drives()[0]->setGains(1e5, 8e4);
  robot.drives()[0]->setTarget(0.1, 0.0);
  StablePd pd(robot);
  const double h = 0.001;
  const double tau = pd.torques(h, jointSpaceInertia(*robot.body(), robot.framePoses()), { 0.0 })[0];
  // x = (I v + h (K e)) / (I + h (h K + D)); tau = K (e - h x) - D x.
  const double x = (0.51 * 0.2 + h * 1e5 * 0.1) / (0.51 + h * (h * 1e5 + 8e4));
  EXPECT_NEAR(tau, 1e5 * (0.1 - h * x) - 8e4 * x, 1e-4);  // Bullet stores the inertia in float
}

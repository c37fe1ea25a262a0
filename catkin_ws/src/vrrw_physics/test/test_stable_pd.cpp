#include <vrrw_physics/articulated_robot.h>
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

using namespace vrrw_physics;

namespace
{
urdf::ModelInterfaceSharedPtr model()
{
  std::ifstream in(std::string(TEST_DATA) + "/pendulum.urdf");
  std::stringstream text;
  text << in.rdbuf();
  return urdf::parseURDF(text.str());
}
}  // namespace

TEST(StablePd, InertiaOfThePendulumIsItsMomentAboutTheAxis)
{
  const auto urdf = model();
  ArticulatedRobot robot(*urdf, "p", "p_base_link");
  StablePd pd(robot);
  EXPECT_NEAR(pd.inertia()(0, 0), 0.51, 1e-9);
}

TEST(StablePd, InertiaMatchesBulletsResponseToJointImpulses)
{
  const auto urdf = model();
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
    const Eigen::MatrixXd m = StablePd(robot).inertia();
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

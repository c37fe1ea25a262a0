#include <vrrw_physics/articulated_robot.h>
#include <vrrw_physics/joint_space_inertia.h>
#include <vrrw_physics/physics_world.h>
#include <vrrw_scene/scene_loader.h>

#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <gtest/gtest.h>
#include <urdf_parser/urdf_parser.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iostream>

using namespace vrrw_physics;

namespace
{
vrrw_scene::Scene paperMultibot()
{
  vrrw_scene::LoadOptions load;
  load.root = VRRW_TEST_ROOT;
  return vrrw_scene::loadScene("paper_multibot", load);
}
}  // namespace

TEST(JointSpaceAccelerations, EqualBulletsArticulatedBodyPassWithVelocitiesForcesAndTorques)
{
  const vrrw_scene::Scene scene = paperMultibot();
  const urdf::ModelInterfaceSharedPtr model = urdf::parseURDF(scene.urdf);
  ASSERT_TRUE(model);
  int robots = 0;
  for (const vrrw_scene::Robot& spec : scene.robots)
  {
    const std::string base = spec.base_link.empty() ? spec.name + "_base_link" : spec.base_link;
    ArticulatedRobot robot(*model, spec.name, base);
    const std::size_t n = robot.joints().size();
    std::vector<double> q(n), qd(n);
    for (std::size_t j = 0; j < n; ++j)
    {
      q[j] = 0.3 * std::sin(1.7 * double(j) + 0.4);
      qd[j] = 1.5 * std::cos(2.3 * double(j) + 0.1);
    }
    robot.setState(q, qd);
    btMultiBody* body = robot.body();
    body->clearForcesAndTorques();
    for (int i = 0; i < body->getNumLinks(); ++i)
    {
      body->addLinkForce(i, btVector3(0, 0, btScalar(-9.81)) * body->getLinkMass(i) +
                                btVector3(btScalar(0.5 * i), 1, -2));
      body->addLinkTorque(i, btVector3(btScalar(0.1), btScalar(-0.2 * i), btScalar(0.3)));
      body->addJointTorque(i, btScalar(3.0 - 0.7 * i));
    }
    JointSpaceResponse response;
    response.joint_of_dof = robot.response().joint_of_dof;
    const JointMatrix m = jointSpaceInertia(*robot.body(), robot.framePoses());
    response.setInertia(m);
    ASSERT_TRUE(supportsJointSpaceAccelerations(*body, response)) << spec.name;
    std::vector<double> ours(std::size_t(6 + body->getNumDofs()));
    jointSpaceAccelerations(*body, response, ours.data());

    btAlignedObjectArray<btScalar> r;
    btAlignedObjectArray<btVector3> v;
    btAlignedObjectArray<btMatrix3x3> mats;
    body->computeAccelerationsArticulatedBodyAlgorithmMultiDof(0, r, v, mats, false, false, false);
    const btScalar* bullet = &r[body->getNumDofs()];
    double scale = 1.0, worst = 0.0;
    for (int d = 0; d < 6 + body->getNumDofs(); ++d)
      scale = std::max(scale, std::abs(double(bullet[d])));
    for (int d = 0; d < 6 + body->getNumDofs(); ++d)
      worst = std::max(worst, std::abs(ours[std::size_t(d)] - double(bullet[d])));
    // Bullet 3.24 as packaged is single precision (btScalar float): its pass rounds at about 1e-7 of each
    // quantity, and the light gripper links (M down to 2e-5 kg m^2) turn that into differences of about 3e-7 of
    // the largest acceleration. The backward error, M (ours - Bullet's), is the torque that would explain the
    // difference: it must stay at float rounding of the torques involved.
    double residual = 0.0, torque = 1.0;
    for (int d = 0; d < body->getNumDofs(); ++d)
    {
      const int i = response.joint_of_dof[std::size_t(d)];
      double sum = 0.0, tau = 0.0;
      for (int e = 0; e < body->getNumDofs(); ++e)
      {
        const double mij = m(i, response.joint_of_dof[std::size_t(e)]);
        sum += mij * (ours[std::size_t(6 + e)] - double(bullet[6 + e]));
        tau += mij * double(bullet[6 + e]);
      }
      residual = std::max(residual, std::abs(sum));
      torque = std::max(torque, std::max(std::abs(tau), std::abs(double(body->getJointTorque(d)))));
    }
    std::cout << spec.name << ": " << body->getNumDofs() << " dofs, largest |qdd| " << scale
              << ", largest difference " << worst << ", M (difference) " << residual << " N m of " << torque << "\n";
    EXPECT_LT(residual, 1e-5 * torque) << spec.name;
    EXPECT_LT(worst, 1e-5 * scale) << spec.name;
    ++robots;
  }
  EXPECT_EQ(robots, 4);
}

namespace
{
/// paper_multibot for 1 s, rigid hold with moving targets on two arms: every joint position and velocity.
std::vector<double> hold(bool joint_space)
{
  WorldOptions options;
  options.joint_space_dynamics = joint_space;
  PhysicsWorld world(paperMultibot(), options);
  std::vector<double> values;
  const JointStates start = world.jointStates("ur3e");
  for (int i = 0; i < 1000; ++i)
  {
    std::vector<std::string> names;
    std::vector<double> targets;
    for (std::size_t j = 0; j < start.name.size(); ++j)
      if (world.robot("ur3e").joints()[j].drive >= 0)
      {
        names.push_back(start.name[j]);
        targets.push_back(start.position[j] + 0.2 * std::sin(3.0 * world.time()));
      }
    world.setDriveTargets("ur3e", names, targets, {});
    EXPECT_TRUE(world.step());
    for (const std::string& robot : world.robotNames())
    {
      const JointStates s = world.jointStates(robot);
      values.insert(values.end(), s.position.begin(), s.position.end());
      values.insert(values.end(), s.velocity.begin(), s.velocity.end());
    }
  }
  return values;
}
}  // namespace

TEST(JointSpaceAccelerations, WorldStepsAsWithBulletsPassUpToRoundingAndRepeatsBitForBit)
{
  const std::vector<double> bullet = hold(false);
  const std::vector<double> ours = hold(true);
  const std::vector<double> again = hold(true);
  ASSERT_EQ(bullet.size(), ours.size());
  double worst = 0.0;
  for (std::size_t i = 0; i < bullet.size(); ++i)
    worst = std::max(worst, std::abs(bullet[i] - ours[i]));
  std::cout << bullet.size() << " values, largest difference " << worst << "\n";
  // Bullet's single-precision state: a float near 1 rad is resolved to 6e-8.
  EXPECT_LT(worst, 1e-5);
  ASSERT_EQ(ours.size(), again.size());
  EXPECT_EQ(std::memcmp(ours.data(), again.data(), ours.size() * sizeof(double)), 0);
}

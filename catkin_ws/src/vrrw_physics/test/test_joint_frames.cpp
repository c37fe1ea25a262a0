// JointFrames: the frames of the robots' moving joints, chained from the world, land where Bullet has the links.
#include <vrrw_physics/joint_frames.h>

#include <gtest/gtest.h>
#include <urdf_parser/urdf_parser.h>

#include "world_fixture.h"

using namespace vrrw_physics;
using vrrw_physics_test::run;
using vrrw_physics_test::shippedScene;

TEST(JointFrames, ChainedFromTheBaseEveryMovingFrameIsWhereBulletHasItsLinkInEveryRobotOfPaperMultibot)
{
  const vrrw_scene::Scene scene = shippedScene("paper_multibot");
  PhysicsWorld world(scene);
  const urdf::ModelInterfaceSharedPtr model = urdf::parseURDF(scene.urdf);
  for (const vrrw_scene::Robot& robot : scene.robots)  // arms away from their start, grippers half closed
  {
    const JointStates now = world.jointStates(robot.name);
    std::vector<std::string> joints = robot.arm_joints;
    std::vector<double> targets;
    for (const std::string& joint : robot.arm_joints)
      for (std::size_t j = 0; j < now.name.size(); ++j)
        if (now.name[j] == joint)
          targets.push_back(now.position[j] + (now.position[j] > 0.0 ? -0.3 : 0.3));  // inside the limits
    for (const std::string& joint : robot.gripper_joints)
    {
      const urdf::JointLimits& limits = *model->getJoint(joint)->limits;
      joints.push_back(joint);
      targets.push_back(0.5 * (limits.lower + limits.upper));
    }
    world.setDriveTargets(robot.name, joints, targets, std::vector<double>(targets.size(), 0.0), {});
  }
  run(world, 1.0);

  std::size_t compared = 0, mimics = 0, movable = 0;
  for (const auto& [name, joint] : model->joints_)
    movable += joint->type != urdf::Joint::FIXED && joint->type != urdf::Joint::FLOATING ? 1 : 0;
  double worst = 0.0;
  for (const vrrw_scene::Robot& robot : scene.robots)
  {
    const JointStates states = world.jointStates(robot.name);
    JointFrames frames(*model, states.name);
    for (const JointFrames::Frame& f : frames.at(states.position))
    {
      const Eigen::Isometry3d chained = world.framePose(f.parent) * f.pose;
      const Eigen::Isometry3d bullet = world.framePose(f.child);
      const double error = std::max((chained.translation() - bullet.translation()).norm(),
                                    Eigen::AngleAxisd(chained.rotation().transpose() * bullet.rotation()).angle());
      EXPECT_LT(error, 1e-6) << robot.name << ": " << f.parent << " -> " << f.child;
      worst = std::max(worst, error);
      ++compared;
      mimics += model->getLink(f.child)->parent_joint->mimic ? 1 : 0;
    }
  }
  EXPECT_EQ(compared, movable);  // every moving joint of the cell, each once
  EXPECT_GT(mimics, 0u);
  std::cout << compared << " moving frames (" << mimics << " of mimic joints), worst " << worst
            << " (m or rad) from Bullet's link poses\n";
}

TEST(JointFrames, ANameThatIsNoMovingJointOrTheWrongNumberOfPositionsIsRefusedNamingIt)
{
  const vrrw_scene::Scene scene = shippedScene("pick_place_drill");
  const urdf::ModelInterfaceSharedPtr model = urdf::parseURDF(scene.urdf);
  try
  {
    JointFrames frames(*model, { "ur5e_shoulder_pan_joint", "no_such_joint" });
    ADD_FAILURE() << "no error";
  }
  catch (const std::invalid_argument& e)
  {
    EXPECT_NE(std::string(e.what()).find("no_such_joint"), std::string::npos) << e.what();
  }
  JointFrames frames(*model, { "ur5e_shoulder_pan_joint" });
  EXPECT_EQ(frames.at({ 0.5 }).size(), 1u);
  EXPECT_THROW(frames.at({ 0.5, 0.1 }), std::invalid_argument);
}

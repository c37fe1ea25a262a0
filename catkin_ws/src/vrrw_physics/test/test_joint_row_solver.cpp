#include <vrrw_physics/joint_row_solver.h>
#include <vrrw_physics/multibody_world.h>
#include <vrrw_physics/self_collision_filter.h>
#include <vrrw_physics/physics_world.h>
#include <vrrw_scene/scene_loader.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <iostream>

using namespace vrrw_physics;

namespace
{
struct Trajectory
{
  std::vector<double> values;  ///< every joint state, effort and object pose of every step
  double pushed = 0.0;         ///< how far the hand moved the UR5e's wrist (m)
  int rejected = 0;
};

/// paper_multibot for 1.5 s: three arms track moving targets, the UR5e is compliant and a kinematic
/// sphere sweeps through its wrist (contacts on a robot link, so the inner joint sweeps run too).
Trajectory simulate(bool reference)
{
  vrrw_scene::LoadOptions load;
  load.root = VRRW_TEST_ROOT;
  WorldOptions options;
  options.bullet_reference = reference;
  // This compares the bit-identical speed-ups (JointRowSolver, SelfCollisionFilter, MultiBodyWorld's skipped
  // prediction) with stock Bullet; the joint-space forward dynamics changes rounding and is compared with
  // Bullet's articulated-body pass in test_joint_space_inertia.
  options.joint_space_dynamics = false;
  options.joint_rows_last = false;  // Bullet's order of joint rows and contacts in a sweep
  PhysicsWorld world(vrrw_scene::loadScene("paper_multibot", load), options);
  world.setMode("ur5e", DriveMode::Compliant);
  const Eigen::Vector3d wrist = world.framePose("ur5e_wrist_1_link").translation();
  std::map<std::string, JointStates> start;
  for (const std::string& robot : world.robotNames())
    start[robot] = world.jointStates(robot);
  Trajectory run;
  for (int i = 0; i < 1500; ++i)
  {
    const double t = world.time();
    for (const std::string robot : { "ur3e", "ur10e", "fetch" })
    {
      const JointStates& s = start[robot];
      std::vector<std::string> names;
      std::vector<double> targets;
      for (std::size_t j = 0; j < s.name.size(); ++j)
      {
        const SimJoint& joint = world.robot(robot).joints()[j];
        if (joint.drive < 0)
          continue;
        names.push_back(s.name[j]);
        targets.push_back(s.position[j] + (j % 2 ? 0.2 : -0.2) * std::sin(1.5 * t));
        // Past a limit by up to the 5 % of the range a target may: the joint presses into its limit row.
        const double margin = kJointLimitMargin * (joint.upper - joint.lower);
        if (joint.limited)
          targets.back() = std::clamp(targets.back(), joint.lower - margin, joint.upper + margin);
      }
      world.setDriveTargets(robot, names, targets, {});
    }
    const Eigen::Vector3d hand = wrist + Eigen::Vector3d(0.0, -0.12 + 0.1 * t, 0.0);
    world.operatorInput().setHand("hand", Eigen::Isometry3d(Eigen::Translation3d(hand)), 0.04);
    run.rejected += !world.step();
    for (const std::string& robot : world.robotNames())
    {
      const JointStates s = world.jointStates(robot);
      for (const auto* v : { &s.position, &s.velocity, &s.effort })
        run.values.insert(run.values.end(), v->begin(), v->end());
    }
    for (const std::string& object : world.objectNames())
    {
      const Eigen::Matrix4d m = world.objectPose(object).matrix();
      run.values.insert(run.values.end(), m.data(), m.data() + 16);
    }
  }
  run.pushed = (world.framePose("ur5e_wrist_1_link").translation() - wrist).norm();
  return run;
}
}  // namespace

TEST(JointRowSolver, DefaultWorldIsBitIdenticalToStockBulletWithDrivesCouplingsLimitsAndContacts)
{
  const Trajectory bullet = simulate(true);
  const Trajectory sparse = simulate(false);
  std::cout << "hand moved the compliant UR5e wrist " << bullet.pushed << " m; " << bullet.values.size()
            << " values compared\n";
  EXPECT_GT(bullet.pushed, 0.01);  // the sweep did touch the robot
  EXPECT_EQ(bullet.rejected, 0);
  EXPECT_EQ(sparse.rejected, 0);
  ASSERT_EQ(bullet.values.size(), sparse.values.size());
  std::size_t differing = 0;
  for (std::size_t i = 0; i < bullet.values.size(); ++i)
    differing += std::memcmp(&bullet.values[i], &sparse.values[i], sizeof(double)) != 0;
  EXPECT_EQ(differing, 0u);
}

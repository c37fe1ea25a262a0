// RobotDrives through PhysicsWorld: a mode change holds the pose, targets that stop arriving hold at rest,
// an effort in the targets bounds the force of a drive.
#include <vrrw_physics/physics_world.h>

#include <gtest/gtest.h>

#include <cmath>
#include <tuple>

#include "world_fixture.h"

using namespace vrrw_physics;
using vrrw_physics_test::run;
using vrrw_physics_test::shippedScene;

namespace
{
/// `scene` with a fixed 2 x 4 x 2 cm block (4 cm along y) at `frame` of a world built from it.
vrrw_scene::Scene withBlockAt(vrrw_scene::Scene scene, const std::string& frame)
{
  vrrw_scene::Object block;
  block.name = "block";
  block.kind = "box";
  block.fixed = true;
  vrrw_scene::Shape box;
  box.type = vrrw_scene::Shape::Type::Box;
  box.box_size = Eigen::Vector3d(0.02, 0.04, 0.02);
  block.collision = { box };
  block.pose = PhysicsWorld(scene).framePose(frame);
  scene.objects.push_back(block);
  return scene;
}

struct Squeeze
{
  double force = 0.0;     ///< N: normal force between the block and the robot's links
  double position = 0.0;  ///< of the closing joint
};

/// Closes gripper joint `joint` of `robot` onto the block (target `closed`) for 1.5 s with force limit `effort`
/// (0: the configured limit).
Squeeze squeeze(const vrrw_scene::Scene& scene, const std::string& robot, const std::string& joint, double closed,
                double effort)
{
  PhysicsWorld world(scene);
  world.setDriveTargets(robot, { joint }, { closed }, {}, { effort });
  run(world, 1.5);
  Squeeze s;
  for (const ContactPair& c : world.contacts())
    if (c.body_a == "block" && c.body_b.rfind(robot + "_", 0) == 0)
      s.force += c.normal_force;
  s.position = world.jointStates(robot).position[std::size_t(world.robot(robot).jointIndex(joint))];
  return s;
}

/// d(distance between the 2F-85's pads) / d(finger_joint) at finger_joint = q, the linkage's lever.
double padGapRate(PhysicsWorld& world, double q)
{
  const ArticulatedRobot& robot = world.robot("ur5e");
  const auto gap = [&](double angle) {
    WorldState s = world.snapshot();
    s.positions[0][std::size_t(robot.jointIndex("ur5e_finger_joint"))] = angle;
    s.positions[0] = robot.withMimics(s.positions[0]);
    world.restore(s);
    return (world.framePose("ur5e_left_inner_finger_pad").translation() -
            world.framePose("ur5e_right_inner_finger_pad").translation())
        .norm();
  };
  return (gap(q - 1e-4) - gap(q + 1e-4)) / 2e-4;
}
}  // namespace

TEST(RobotDrives, ParsesModesAndSchemes)
{
  EXPECT_EQ(parseDriveMode("rigid"), DriveMode::Rigid);
  EXPECT_EQ(parseDriveMode("compliant"), DriveMode::Compliant);
  EXPECT_EQ(parseDriveMode("custom"), DriveMode::Custom);
  EXPECT_THROW(parseDriveMode("floppy"), std::invalid_argument);
  EXPECT_EQ(parseDriveScheme("stable_pd"), DriveScheme::StablePd);
  EXPECT_THROW(parseDriveScheme("pid"), std::invalid_argument);
}

TEST(RobotDrives, LeavingCompliantModeHoldsThePoseTheArmIsIn)
{
  PhysicsWorld world(shippedScene("pick_place_drill"));
  const Eigen::Vector3d start = world.framePose("ur5e_tcp").translation();
  world.setMode("ur5e", DriveMode::Compliant);
  OperatorSpring push;  // the operator pushes the compliant arm away: 20 N along +y for 0.5 s
  push.body = "ur5e_tool0";
  push.max_force = 20.0;
  push.target.translation() = world.framePose("ur5e_tool0").translation() + Eigen::Vector3d(0, 10.0, 0);
  world.operatorInput().attachSpring("push", push);
  run(world, 0.5);
  world.operatorInput().releaseSpring("push");
  run(world, 0.2);
  const Eigen::Vector3d pushed = world.framePose("ur5e_tcp").translation();
  world.setMode("ur5e", DriveMode::Rigid);
  double drift = 0.0;
  run(world, 5.0, [&] { drift = std::max(drift, (world.framePose("ur5e_tcp").translation() - pushed).norm()); });
  std::cout << "pushed " << (pushed - start).norm() << " m away, set rigid: TCP drift " << drift << " m over 5 s\n";
  EXPECT_GT((pushed - start).norm(), 0.03);  // the targets of the start would pull it back this far
  EXPECT_LT(drift, 1.5e-6);  // deterministic: 5.2e-7 m measured (the README's target: < 1 mm)
}

TEST(RobotDrives, TargetsThatStopArrivingHoldTheLastTargetAtRest)
{
  // A controller streams a ramp on the pan joint at 0.25 rad/s, then dies.
  const auto ramp = [](double timeout) {
    WorldOptions options;
    options.target_timeout = timeout;
    PhysicsWorld world(shippedScene("pick_place_drill"), options);
    double target = 0.0, farthest = 0.0;
    run(world, 0.4, [&] {
      target = 0.25 * world.time();
      world.setDriveTargets("ur5e", { "ur5e_shoulder_pan_joint" }, { target }, { 0.25 });
    });
    run(world, 3.0, [&] { farthest = std::max(farthest, world.jointStates("ur5e").position[0]); });
    EXPECT_EQ(world.takeReports().size(), timeout > 0.0 ? 1u : 0u);
    return std::tuple{ target, farthest, world.jointStates("ur5e").position[0] };
  };
  const auto [target, farthest, held] = ramp(0.1);
  const auto [same_target, unused, coasted] = ramp(0.0);
  std::cout << "targets stopped at " << target << " rad: the arm went on to " << farthest << " rad and rests at "
            << held << " rad; with no timeout it coasts to " << coasted << " rad\n";
  EXPECT_LT(farthest - target, 0.1 * 0.25 + 2e-3);  // 0.1 s more on the stale velocity at most
  EXPECT_LT(std::abs(held - target), 1.5e-3);  // 6.6e-4 rad measured
  EXPECT_GT(coasted - same_target, 0.1);  // what the timeout prevents
}

TEST(RobotDrives, ALateTargetIsBridgedAlongTheLastTargetVelocity)
{
  // A controller streams a 0.25 rad/s ramp on the pan joint every 2 ms, then is descheduled for 80 ms.
  // Held between messages (zero-order), the targets lag the ramp by up to v * age: 1.2 mrad worst over the
  // run; carried along their velocity, 0.35 mrad (simulated time: the same figures on every machine).
  PhysicsWorld world(shippedScene("pick_place_drill"));
  const double q0 = world.jointStates("ur5e").position[0];
  double worst = 0.0;
  run(world, 0.6, [&] {
    const double t = world.time(), ramp = q0 + 0.25 * t;
    const bool stalled = t > 0.4 && t < 0.48;
    if (!stalled && std::lround(t * 1000.0) % 2 == 0)
      world.setDriveTargets("ur5e", { "ur5e_shoulder_pan_joint" }, { ramp }, { 0.25 });
    if (t > 0.2)
      worst = std::max(worst, std::abs(world.jointStates("ur5e").position[0] - ramp));
  });
  std::cout << "ramp tracking with an 80 ms gap in the targets: worst " << worst << " rad\n";
  EXPECT_LT(worst, 6e-4);
  EXPECT_TRUE(world.takeReports().empty());  // 80 ms is no stale stream (0.1 s)
}

TEST(RobotDrives, EffortInTargetsBoundsTheSqueezeOfAFingerDrive)
{
  // Fetch: two prismatic fingers, one mimicking the other; closed on a fixed block, the two pads press it
  // with the drives' force limits, 2 x effort in all.
  const vrrw_scene::Scene fetch = withBlockAt(shippedScene("paper_multibot"), "fetch_gripper_link");
  for (const double effort : { 10.0, 30.0 })
  {
    const double force = squeeze(fetch, "fetch", "fetch_l_gripper_finger_joint", 0.0, effort).force;
    std::cout << "fetch fingers, effort " << effort << " N: squeeze " << force << " N\n";
    EXPECT_NEAR(force, 2.0 * effort, 1e-3 * 2.0 * effort);  // 20.0 N and 60.0 N measured
  }
  EXPECT_GT(squeeze(fetch, "fetch", "fetch_l_gripper_finger_joint", 0.0, 0.0).force, 100.0);  // the URDF's 60 N each
  // Robotiq 2F-85: finger_joint is the knuckle's angle, and its five mimic joints each have a follower drive that
  // takes the same limit; by virtual work the pads squeeze with at most 2 x 6 x effort / (d gap / d finger_joint).
  const vrrw_scene::Scene ur5e = withBlockAt(shippedScene("pick_place_drill"), "ur5e_tcp");
  PhysicsWorld lever(ur5e);
  for (const double effort : { 0.25, 0.5 })
  {
    const Squeeze s = squeeze(ur5e, "ur5e", "ur5e_finger_joint", 0.8, effort);
    const double bound = 12.0 * effort / padGapRate(lever, s.position);
    std::cout << "2F-85 finger_joint effort " << effort << " N m: squeeze " << s.force << " N (virtual work: " << bound
              << " N)\n";
    // 0.940 and 0.952 of virtual work measured (0.25 and 0.5 N m) with the joint rows after the contacts (issue
    // 22); 1.004 and 1.020 before
    EXPECT_NEAR(s.force / bound, 0.946, 0.02);
  }
}

#include <vrrw_physics/physics_world.h>
#include <vrrw_scene/scene_loader.h>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <map>

using namespace vrrw_physics;

namespace
{
vrrw_scene::Scene scene(const std::string& name)
{
  vrrw_scene::LoadOptions options;
  options.root = VRRW_TEST_ROOT;
  return vrrw_scene::loadScene(name, options);
}

double maxHoldError(PhysicsWorld& world, double seconds)
{
  std::map<std::string, std::vector<double>> start;
  for (const auto& r : world.robotNames())
    start[r] = world.jointStates(r).position;
  double worst = 0.0;
  const int steps = int(std::lround(seconds / world.options().dt));
  for (int i = 0; i < steps; ++i)
  {
    EXPECT_TRUE(world.step()) << world.lastError();
    if (i % 50 != 49)
      continue;
    for (const auto& r : world.robotNames())
    {
      const auto q = world.jointStates(r).position;
      for (std::size_t j = 0; j < q.size(); ++j)
        if (world.robot(r).joints()[j].drive >= 0)
          worst = std::max(worst, std::abs(q[j] - start[r][j]));
    }
  }
  return worst;
}

std::string errorOf(const std::function<void()>& call)
{
  try
  {
    call();
  }
  catch (const InputError& e)
  {
    const std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    return message;
  }
  ADD_FAILURE() << "no InputError";
  return "";
}
}  // namespace

TEST(PhysicsWorld, RigidModeHoldsEveryArmOfPaperMultibotAgainstGravity)
{
  PhysicsWorld world(scene("paper_multibot"));
  ASSERT_EQ(world.robotNames().size(), 4u);
  const double error = maxHoldError(world, 2.0);
  EXPECT_LT(error, 1e-3);
  std::cout << "rigid hold, gravity compensated: max joint error " << error << " rad over 2 s\n";
}

TEST(PhysicsWorld, RigidGainsAloneHoldTheUr5eWithinAMilliradian)
{
  PhysicsWorld world(scene("pick_place_drill"));
  world.setGravityCompensation("ur5e", false);
  // Arm stretched out horizontally: the largest gravity load of the shoulder.
  const std::vector<std::string> joints{ "ur5e_shoulder_pan_joint", "ur5e_shoulder_lift_joint", "ur5e_elbow_joint",
                                         "ur5e_wrist_1_joint",      "ur5e_wrist_2_joint",       "ur5e_wrist_3_joint" };
  const std::vector<double> horizontal{ 0.0, 0.0, 0.0, 0.0, 0.0, 0.0 };
  WorldState s = world.snapshot();
  world.setDriveTargets("ur5e", joints, horizontal, {});
  for (std::size_t j = 0; j < joints.size(); ++j)
    s.positions[0][std::size_t(world.robot("ur5e").jointIndex(joints[j]))] = horizontal[j];
  s.target_positions = world.snapshot().target_positions;
  world.restore(s);
  for (int i = 0; i < 3000; ++i)
    world.step();  // settle: the overdamped drive's time constant is D/K = 0.8 s
  const double error = maxHoldError(world, 1.0);
  const auto q = world.jointStates("ur5e").position;
  const double sag = std::abs(q[std::size_t(world.robot("ur5e").jointIndex("ur5e_shoulder_lift_joint"))]);
  std::cout << "rigid hold without compensation, arm horizontal: shoulder sag " << sag << " rad, drift " << error
            << " rad\n";
  EXPECT_LT(sag, 1e-3);
}

TEST(PhysicsWorld, CompliantArmYieldsToA20NPullAndStopsWhenReleased)
{
  PhysicsWorld world(scene("pick_place_drill"));
  world.setMode("ur5e", DriveMode::Compliant);
  EXPECT_DOUBLE_EQ(world.gains("ur5e", "ur5e_elbow_joint").stiffness, 0.0);
  const Eigen::Vector3d start = world.framePose("ur5e_tool0").translation();
  OperatorSpring pull;
  pull.body = "ur5e_tool0";
  pull.stiffness = 1e5;  // saturates at max_force: a constant 20 N pull along +y
  pull.damping = 0.0;
  pull.max_force = 20.0;
  pull.target.translation() = start + Eigen::Vector3d(0, 10.0, 0);
  world.attachSpring("hand", pull);
  for (int i = 0; i < 500; ++i)
    ASSERT_TRUE(world.step()) << world.lastError();
  const double moved = (world.framePose("ur5e_tool0").translation() - start).norm();
  world.releaseSpring("hand");
  for (int i = 0; i < 1500; ++i)
    ASSERT_TRUE(world.step()) << world.lastError();
  const Eigen::Vector3d after_release = world.framePose("ur5e_tool0").translation();
  for (int i = 0; i < 500; ++i)
    world.step();
  const double drift = (world.framePose("ur5e_tool0").translation() - after_release).norm();
  double speed = 0.0;
  for (double v : world.jointStates("ur5e").velocity)
    speed = std::max(speed, std::abs(v));
  std::cout << "compliant: 20 N for 0.5 s moved tool0 " << moved << " m; 1.5 s after release it drifts " << drift
            << " m in 0.5 s, joint speed " << speed << " rad/s\n";
  EXPECT_GT(moved, 0.02);
  EXPECT_LT(drift, 1e-3);
  EXPECT_LT(speed, 1e-2);
}

TEST(PhysicsWorld, SameInputsGiveBitIdenticalJointStatesOver10s)
{
  const vrrw_scene::Scene cell = scene("pick_place_drill");
  std::vector<std::vector<double>> runs[2];
  for (auto& run : runs)
  {
    PhysicsWorld world(cell);
    const auto names = world.jointStates("ur5e").name;
    for (int i = 0; i < 10000; ++i)
    {
      const double t = world.time();
      world.setDriveTargets("ur5e", { "ur5e_shoulder_pan_joint", "ur5e_elbow_joint" },
                            { 0.5 * std::sin(t), 1.5708 + 0.3 * std::sin(2 * t) },
                            { 0.5 * std::cos(t), 0.6 * std::cos(2 * t) });
      world.step();
      if (i % 10 == 0)
      {
        const JointStates s = world.jointStates("ur5e");
        std::vector<double> row = s.position;
        row.insert(row.end(), s.velocity.begin(), s.velocity.end());
        run.push_back(row);
      }
    }
  }
  ASSERT_EQ(runs[0].size(), runs[1].size());
  std::size_t differing = 0;
  for (std::size_t i = 0; i < runs[0].size(); ++i)
    differing += runs[0][i] != runs[1][i];
  EXPECT_EQ(differing, 0u);
  EXPECT_GT(std::abs(runs[0].back()[0]), 0.0);
}

TEST(PhysicsWorld, BadInputGetsAClearErrorAndTheSimulationContinues)
{
  PhysicsWorld world(scene("pick_place_drill"));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const WorldState before = world.snapshot();
  EXPECT_NE(errorOf([&] { world.setDriveTargets("ur5e", { "ur5e_wrist_9_joint" }, { 0.1 }, {}); }).find("ur5e_wrist_9_joint"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { world.setDriveTargets("ur5e", { "ur5e_elbow_joint" }, { nan }, {}); }).find("not finite"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { world.setDriveTargets("ur5e", { "ur5e_elbow_joint" }, { 0.1, 0.2 }, {}); }).find("positions"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { world.setDriveTargets("ur9", { "ur5e_elbow_joint" }, { 0.1 }, {}); }).find("ur9"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { world.setGains("ur5e", { "ur5e_elbow_joint" }, { -1.0 }, { 10.0 }, {}); }).find(">= 0"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { world.setGains("ur5e", {}, { 1.0, 2.0 }, { 1.0, 2.0 }, {}); }).find("6 joints but 2"),
            std::string::npos);
  OperatorSpring spring;
  spring.body = "ur5e_no_such_link";
  EXPECT_NE(errorOf([&] { world.attachSpring("s", spring); }).find("ur5e_no_such_link"), std::string::npos);
  EXPECT_NE(errorOf([&] { world.moveSpring("never_attached", Eigen::Isometry3d::Identity()); }).find("never_attached"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { world.setObjectPose("unicorn", Eigen::Isometry3d::Identity()); }).find("unicorn"),
            std::string::npos);
  // Nothing was applied: targets are those of the start, and the world still steps.
  EXPECT_EQ(world.snapshot().target_positions, before.target_positions);
  EXPECT_EQ(world.mode("ur5e"), DriveMode::Rigid);
  for (int i = 0; i < 100; ++i)
    ASSERT_TRUE(world.step());
  EXPECT_NEAR(world.time(), 0.1, 1e-9);
}

TEST(PhysicsWorld, GuardRejectsAnExplodingStepAndRestoresTheLastGoodState)
{
  PhysicsWorld world(scene("pick_place_drill"));
  for (int i = 0; i < 200; ++i)
    ASSERT_TRUE(world.step());
  const Eigen::Isometry3d drill = world.objectPose("drill");
  OperatorSpring fling;  // explicit spring far beyond its stable range on a 1.5 kg body
  fling.body = "drill";
  fling.stiffness = 1e9;
  fling.max_force = 1e9;
  fling.target.translation() = drill.translation() + Eigen::Vector3d(0, 0, 1);
  world.attachSpring("fling", fling);
  bool rejected = false;
  for (int i = 0; i < 50 && !rejected; ++i)
    rejected = !world.step();
  ASSERT_TRUE(rejected);
  EXPECT_NE(world.lastError().find("drill"), std::string::npos) << world.lastError();
  EXPECT_NEAR(world.time(), 0.2, 1e-9);
  EXPECT_LT((world.objectPose("drill").translation() - drill.translation()).norm(), 1e-3);
  world.releaseSpring("fling");
  for (int i = 0; i < 100; ++i)
    ASSERT_TRUE(world.step()) << world.lastError();
}

TEST(PhysicsWorld, ResetReturnsToTheInitialState)
{
  PhysicsWorld world(scene("pick_place_drill"));
  const WorldState start = world.snapshot();
  world.setDriveTargets("ur5e", { "ur5e_shoulder_pan_joint" }, { 0.5 }, {});
  world.setObjectPose("drill", Eigen::Isometry3d(Eigen::Translation3d(0.0, 0.3, 0.9)));
  for (int i = 0; i < 300; ++i)
    world.step();
  world.reset();
  EXPECT_EQ(world.time(), 0.0);
  EXPECT_EQ(world.snapshot().positions, start.positions);
  EXPECT_LT((world.objectPose("drill").translation() - start.object_poses[1].translation()).norm(), 1e-6);
}

TEST(PhysicsWorld, KinematicHandPushesAnObjectByContact)
{
  PhysicsWorld world(scene("pick_place_drill"));
  EXPECT_TRUE(world.graspAssists().empty());  // grasp assist is off unless asked for
  const Eigen::Vector3d drill = world.objectPose("drill").translation();
  // Sweep a 4 cm sphere along +y through the drill's battery, 3 cm above the table, at 0.3 m/s.
  const Eigen::Vector3d from = drill + Eigen::Vector3d(0, -0.15, 0.03);
  for (int i = 0; i <= 1000; ++i)
  {
    world.setHandPose(Eigen::Isometry3d(Eigen::Translation3d(from + Eigen::Vector3d(0, 0.3 * i * 1e-3, 0))));
    ASSERT_TRUE(world.step()) << world.lastError();
  }
  const double pushed = world.objectPose("drill").translation().y() - drill.y();
  std::cout << "hand: swept 0.3 m, the drill moved " << pushed << " m along the sweep\n";
  EXPECT_GT(pushed, 0.05);
  world.removeHand();
  ASSERT_TRUE(world.step());
}

TEST(PhysicsWorld, GraspAssistWeldsTheObjectToTheTcpWhenAsked)
{
  vrrw_scene::Scene cell = scene("pick_place_drill");
  PhysicsWorld world(cell);
  const Eigen::Isometry3d tcp = world.framePose("ur5e_tcp");
  Eigen::Isometry3d place = Eigen::Isometry3d::Identity();
  place.translation() = tcp.translation() - Eigen::Vector3d(0, 0, 0.25);  // below the open fingers, in free space
  world.setObjectPose("drill", place);
  world.setGraspAssist("ur5e", "drill", true);
  EXPECT_EQ(world.graspAssists(), std::vector<std::string>{ "ur5e/drill" });
  const Eigen::Isometry3d held = world.framePose("ur5e_tcp").inverse() * world.objectPose("drill");
  world.setDriveTargets("ur5e", { "ur5e_shoulder_pan_joint" }, { 0.3 }, {});
  for (int i = 0; i < 2000; ++i)
    ASSERT_TRUE(world.step()) << world.lastError();
  const Eigen::Isometry3d now = world.framePose("ur5e_tcp").inverse() * world.objectPose("drill");
  EXPECT_LT((now.translation() - held.translation()).norm(), 2e-3);
  EXPECT_GT(std::abs(world.jointStates("ur5e").position[0]), 0.1);
  world.setGraspAssist("ur5e", "drill", false);
  EXPECT_TRUE(world.graspAssists().empty());
  EXPECT_THROW(world.setGraspAssist("ur5e", "table", true), InputError);
}

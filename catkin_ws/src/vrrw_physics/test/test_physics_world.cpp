// PhysicsWorld: holding, compliance, repeatability, the guard, reset, a world that is not finite, contacts.
#include <vrrw_physics/physics_world.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>

#include "world_fixture.h"

using namespace vrrw_physics;
using vrrw_physics_test::inputErrorOf;
using vrrw_physics_test::run;
using vrrw_physics_test::shippedScene;

namespace
{
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

const ContactPair* findContact(const std::vector<ContactPair>& contacts, const std::string& a, const std::string& b)
{
  for (const ContactPair& c : contacts)
    if ((c.body_a == a && c.body_b == b) || (c.body_a == b && c.body_b == a))
      return &c;
  return nullptr;
}
}  // namespace

TEST(PhysicsWorld, RigidModeHoldsEveryArmOfPaperMultibotAgainstGravity)
{
  PhysicsWorld world(shippedScene("paper_multibot"));
  ASSERT_EQ(world.robotNames().size(), 4u);
  const double error = maxHoldError(world, 2.0);
  EXPECT_LT(error, 1e-3);
  std::cout << "rigid hold, gravity compensated: max joint error " << error << " rad over 2 s\n";
}

TEST(PhysicsWorld, RigidGainsAloneHoldTheStretchedUr5eWithinTwoMilliradians)
{
  PhysicsWorld world(shippedScene("pick_place_drill"));
  world.setGravityCompensation("ur5e", false);
  // Arm stretched out horizontally: the largest gravity load of the shoulder. The wrist turns the gripper up, so
  // nothing rests on the table (with the gripper hanging down its knuckle touched it: a contact, not the drives,
  // then decided the sag).
  const std::vector<std::string> joints{ "ur5e_shoulder_pan_joint", "ur5e_shoulder_lift_joint", "ur5e_elbow_joint",
                                         "ur5e_wrist_1_joint",      "ur5e_wrist_2_joint",       "ur5e_wrist_3_joint" };
  const std::vector<double> horizontal{ 0.0, 0.0, 0.0, -M_PI / 2, 0.0, 0.0 };
  WorldState s = world.snapshot();
  world.setDriveTargets("ur5e", joints, horizontal, {});
  for (std::size_t j = 0; j < joints.size(); ++j)
    s.positions[0][std::size_t(world.robot("ur5e").jointIndex(joints[j]))] = horizontal[j];
  s.target_positions = world.snapshot().target_positions;
  world.restore(s);
  run(world, 3.0);  // settle: the overdamped drive's time constant is D/K = 0.8 s
  const double error = maxHoldError(world, 1.0);
  const auto q = world.jointStates("ur5e").position;
  const double sag = std::abs(q[std::size_t(world.robot("ur5e").jointIndex("ur5e_shoulder_lift_joint"))]);
  std::cout << "rigid hold without compensation, arm horizontal: shoulder sag " << sag << " rad, drift " << error
            << " rad\n";
  for (const ContactPair& contact : world.contacts())  // the drives alone carry the arm
    EXPECT_TRUE(contact.body_a.rfind("ur5e", 0) != 0 && contact.body_b.rfind("ur5e", 0) != 0)
        << contact.body_a << " touches " << contact.body_b;
  EXPECT_LT(sag, 2e-3);  // measured 1.26e-3: K alone against the stretched arm's weight, nothing compensated
}

TEST(PhysicsWorld, CompliantArmYieldsToA20NPullAndStopsWhenReleased)
{
  PhysicsWorld world(shippedScene("pick_place_drill"));
  world.setMode("ur5e", DriveMode::Compliant);
  EXPECT_DOUBLE_EQ(world.gains("ur5e", "ur5e_elbow_joint").stiffness, 0.0);
  const Eigen::Vector3d start = world.framePose("ur5e_tool0").translation();
  OperatorSpring pull;
  pull.body = "ur5e_tool0";
  pull.stiffness = 1e4;  // saturates at max_force: a constant 20 N pull along +y
  pull.damping = 0.0;
  pull.max_force = 20.0;
  pull.target.translation() = start + Eigen::Vector3d(0, 10.0, 0);
  world.operatorInput().attachSpring("hand", pull);
  run(world, 0.5);
  const double moved = (world.framePose("ur5e_tool0").translation() - start).norm();
  world.operatorInput().releaseSpring("hand");
  run(world, 1.5);
  const Eigen::Vector3d after_release = world.framePose("ur5e_tool0").translation();
  run(world, 0.5);
  const double drift = (world.framePose("ur5e_tool0").translation() - after_release).norm();
  const double speed = vrrw_physics_test::largestJointSpeed(world, "ur5e");
  std::cout << "compliant: 20 N for 0.5 s moved tool0 " << moved << " m; 1.5 s after release it drifts " << drift
            << " m in 0.5 s, joint speed " << speed << " rad/s\n";
  EXPECT_GT(moved, 0.02);
  EXPECT_LT(drift, 1e-3);
  EXPECT_LT(speed, 1e-2);
}

TEST(PhysicsWorld, SameInputsGiveBitIdenticalJointStatesOver10s)
{
  const vrrw_scene::Scene cell = shippedScene("pick_place_drill");
  std::vector<std::vector<double>> runs[2];
  for (auto& samples : runs)
  {
    PhysicsWorld world(cell);
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
        samples.push_back(row);
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

TEST(PhysicsWorld, BadInputGetsAClearErrorNamingTheRangeAndNothingIsApplied)
{
  PhysicsWorld world(shippedScene("pick_place_drill"));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const WorldState before = world.snapshot();
  const auto mentions = [](const std::string& error, const std::string& text) {
    EXPECT_NE(error.find(text), std::string::npos) << error;
  };
  mentions(inputErrorOf([&] { world.setDriveTargets("ur5e", { "ur5e_wrist_9_joint" }, { 0.1 }, {}); }),
           "ur5e_wrist_9_joint");
  mentions(inputErrorOf([&] { world.setDriveTargets("ur5e", { "ur5e_elbow_joint" }, { nan }, {}); }), "not finite");
  mentions(inputErrorOf([&] { world.setDriveTargets("ur5e", { "ur5e_elbow_joint" }, { 0.1, 0.2 }, {}); }), "positions");
  mentions(inputErrorOf([&] { world.setDriveTargets("ur9", { "ur5e_elbow_joint" }, { 0.1 }, {}); }), "ur9");
  mentions(inputErrorOf([&] { world.setDriveTargets("ur5e", { "ur5e_elbow_joint" }, { 90.0 }, {}); }),
           "position: 90 outside [-3.4");
  mentions(inputErrorOf([&] { world.setDriveTargets("ur5e", { "ur5e_elbow_joint" }, { 0.1 }, { 1e3 }); }),
           "velocity: 1000 outside [-50, 50] rad/s");
  mentions(inputErrorOf([&] { world.setDriveTargets("ur5e", { "ur5e_elbow_joint" }, { 0.1 }, {}, { -1.0 }); }),
           "effort: -1 outside [0, 100000] N m");
  mentions(inputErrorOf([&] {
             world.setDriveTargets("ur5e", { "ur5e_elbow_joint", "ur5e_elbow_joint" }, { 0.1, 0.2 }, {});
           }),
           "named twice");
  mentions(inputErrorOf([&] { world.setGains("ur5e", { "ur5e_elbow_joint" }, { -1.0 }, { 10.0 }, {}); }),
           "stiffness: -1 outside [0, 1e+07] N m/rad");
  mentions(inputErrorOf([&] { world.setGains("ur5e", {}, { 1.0, 2.0 }, { 1.0, 2.0 }, {}); }), "6 joint names but 2");
  mentions(inputErrorOf([&] { world.setObjectPose("unicorn", Eigen::Isometry3d::Identity()); }), "unicorn");
  mentions(inputErrorOf([&] { world.setObjectPose("drill", Eigen::Isometry3d(Eigen::Translation3d(1e300, 0, 0))); }),
           "position.x: 1e+300 outside [-100, 100] m (the world extent)");
  mentions(inputErrorOf([&] { world.setObjectPose("table", Eigen::Isometry3d::Identity()); }), "fixed");
  // Nothing was applied: targets are those of the start, and the world still steps.
  EXPECT_EQ(world.snapshot().target_positions, before.target_positions);
  EXPECT_EQ(world.snapshot().object_poses[1].matrix(), before.object_poses[1].matrix());
  EXPECT_EQ(world.mode("ur5e"), DriveMode::Rigid);
  run(world, 0.1);
  EXPECT_NEAR(world.time(), 0.1, 1e-9);
}

TEST(PhysicsWorld, GuardReleasesTheSpringThatTrippedItAndTheWorldGoesOn)
{
  WorldOptions options;
  options.max_object_speed = 0.5;  // a 1 kN pull on the drill exceeds it within a step
  PhysicsWorld world(shippedScene("pick_place_drill"), options);
  run(world, 0.2);
  const Eigen::Isometry3d drill = world.objectPose("drill");
  OperatorSpring fling;
  fling.body = "drill";
  fling.stiffness = 1e4;
  fling.max_force = 1e3;
  fling.target.translation() = drill.translation() + Eigen::Vector3d(0, 0, 1);
  world.operatorInput().attachSpring("fling", fling);
  EXPECT_FALSE(world.step());
  EXPECT_NE(world.lastError().find("object drill"), std::string::npos) << world.lastError();
  EXPECT_NE(world.lastError().find("released spring 'fling'"), std::string::npos) << world.lastError();
  EXPECT_EQ(world.takeReports(), std::vector<std::string>{ world.lastError() });
  EXPECT_NEAR(world.time(), 0.201, 1e-9);  // simulated time never runs backwards
  EXPECT_LT((world.objectPose("drill").translation() - drill.translation()).norm(), 1e-3);
  EXPECT_TRUE(world.operatorInput().springs().empty());
  run(world, 0.5);
  EXPECT_FALSE(world.stopped());
}

TEST(PhysicsWorld, GuardStopsWithOneErrorAfterRepeatedTripsUntilReset)
{
  WorldOptions options;
  options.max_joint_speed = 1e-5;  // the sag of an uncompensated arm in its first step exceeds it
  PhysicsWorld world(shippedScene("pick_place_drill"), options);
  world.setGravityCompensation("ur5e", false);
  int rejected = 0;
  for (int i = 0; i < 100; ++i)
    rejected += !world.step();
  EXPECT_TRUE(world.stopped());
  EXPECT_EQ(rejected, 100);  // 3 trips, then every step refused without stepping
  const std::vector<std::string> reports = world.takeReports();
  ASSERT_EQ(reports.size(), 3u);
  EXPECT_NE(reports.back().find("stopped after 3 trips"), std::string::npos) << reports.back();
  EXPECT_NEAR(world.time(), 0.003, 1e-9);
  world.reset();
  EXPECT_FALSE(world.stopped());
  run(world, 0.2);  // gravity compensation is back on: nothing moves
}

TEST(PhysicsWorld, ResetRestoresObjectsSpringsHandsModesGainsAssistsAndTargets)
{
  PhysicsWorld world(shippedScene("pick_place_drill"));
  const WorldState start = world.snapshot();
  const ArticulatedRobot& ur5e = world.robot("ur5e");
  const double finger_limit = ur5e.joints()[std::size_t(ur5e.jointIndex("ur5e_finger_joint"))].max_effort;
  const DriveGains rigid = world.gains("ur5e", "ur5e_elbow_joint");
  world.setDriveTargets("ur5e", { "ur5e_shoulder_pan_joint", "ur5e_finger_joint" }, { 0.5, 0.2 }, {}, { 0.0, 1.0 });
  EXPECT_DOUBLE_EQ(world.gains("ur5e", "ur5e_finger_joint").max_force, 1.0);
  world.setGains("ur5e", { "ur5e_elbow_joint" }, { 10.0 }, { 1.0 }, { 5.0 });
  world.setGravityCompensation("ur5e", false);
  OperatorSpring spring;
  spring.body = "ur5e_wrist_3_link";
  spring.target = world.framePose("ur5e_wrist_3_link");
  world.operatorInput().attachSpring("s", spring);
  world.operatorInput().setHand("right", Eigen::Isometry3d(Eigen::Translation3d(0.5, 0.5, 1.5)), 0.05);
  world.operatorInput().setGraspAssist("ur5e", "drill", true);
  run(world, 0.3);
  world.reset();
  EXPECT_EQ(world.time(), 0.0);
  EXPECT_EQ(world.snapshot().positions, start.positions);
  EXPECT_EQ(world.snapshot().target_positions, start.target_positions);
  EXPECT_EQ(world.mode("ur5e"), DriveMode::Rigid);
  EXPECT_EQ(world.gains("ur5e", "ur5e_elbow_joint").stiffness, rigid.stiffness);
  EXPECT_EQ(world.gains("ur5e", "ur5e_elbow_joint").max_force, rigid.max_force);
  EXPECT_EQ(world.gains("ur5e", "ur5e_finger_joint").max_force, finger_limit);
  EXPECT_TRUE(world.operatorInput().springs().empty());
  EXPECT_TRUE(world.operatorInput().hands().empty());
  EXPECT_TRUE(world.operatorInput().graspAssists().empty());
  EXPECT_LT((world.objectPose("drill").translation() - start.object_poses[1].translation()).norm(), 1e-6);
  // Far away and back: lifted 5 cm after a reset, the drill falls back onto the table.
  world.setObjectPose("drill", Eigen::Isometry3d(Eigen::Translation3d(90.0, -90.0, 80.0)));
  run(world, 0.3);
  world.reset();
  Eigen::Isometry3d lifted = start.object_poses[1];
  lifted.translation().z() += 0.05;
  world.setObjectPose("drill", lifted);
  run(world, 1.0);
  const double landed = world.objectPose("drill").translation().z() - start.object_poses[1].translation().z();
  std::cout << "after reset, the drill lifted 5 cm lands " << landed << " m from its start height\n";
  EXPECT_LT(std::abs(landed), 3e-3);
  EXPECT_LT(maxHoldError(world, 0.5), 1e-4);  // gravity compensation is back on
}

namespace
{
/// 3 s of a script with contacts: the drill dropped 2 cm onto the table, the arm swinging, the fingers closing;
/// every 10th step's arm and drill state.
std::vector<std::vector<double>> contactScript(PhysicsWorld& world)
{
  const WorldState start = world.snapshot();
  Eigen::Isometry3d lifted = start.object_poses[1];
  lifted.translation().z() += 0.02;
  world.setObjectPose("drill", lifted);
  std::vector<std::vector<double>> samples;
  for (int i = 0; i < 3000; ++i)
  {
    const double t = world.time();
    world.setDriveTargets("ur5e", { "ur5e_shoulder_pan_joint", "ur5e_elbow_joint", "ur5e_finger_joint" },
                          { 0.5 * std::sin(t), 1.5708 + 0.3 * std::sin(2 * t), 0.25 * t },
                          { 0.5 * std::cos(t), 0.6 * std::cos(2 * t), 0.25 });
    EXPECT_TRUE(world.step()) << world.lastError();
    if (i % 10 != 0)
      continue;
    const JointStates s = world.jointStates("ur5e");
    std::vector<double> row = s.position;
    row.insert(row.end(), s.velocity.begin(), s.velocity.end());
    const Eigen::Isometry3d drill = world.objectPose("drill");
    row.insert(row.end(), drill.data(), drill.data() + 16);
    samples.push_back(row);
  }
  return samples;
}

std::size_t differingRows(const std::vector<std::vector<double>>& a, const std::vector<std::vector<double>>& b)
{
  std::size_t differing = a.size() > b.size() ? a.size() - b.size() : b.size() - a.size();
  for (std::size_t i = 0; i < a.size() && i < b.size(); ++i)
    differing += a[i] != b[i];
  return differing;
}
}  // namespace

TEST(PhysicsWorld, AfterResetTheSameInputsGiveTheFreshWorldsStatesBitForBit)
{
  const vrrw_scene::Scene cell = shippedScene("pick_place_drill");
  PhysicsWorld fresh_world(cell);
  const auto fresh = contactScript(fresh_world);
  // another history before the reset: the drill knocked over by the arm, left lying elsewhere, at rest
  PhysicsWorld world(cell);
  world.setDriveTargets("ur5e", { "ur5e_shoulder_lift_joint", "ur5e_elbow_joint", "ur5e_finger_joint" },
                        { -0.6, 1.2, 0.8 }, { 0.0, 0.0, 0.0 });
  Eigen::Isometry3d thrown = world.objectPose("drill");
  thrown.translation() += Eigen::Vector3d(0.1, -0.15, 0.3);
  world.setObjectPose("drill", thrown);
  run(world, 4.0);
  world.reset();
  const auto after_reset = contactScript(world);
  world.reset();
  const auto after_second_reset = contactScript(world);
  EXPECT_EQ(differingRows(fresh, after_reset), 0u);
  EXPECT_EQ(differingRows(fresh, after_second_reset), 0u);
  EXPECT_EQ(fresh.size(), 300u);
}

TEST(PhysicsWorld, AWorldThatIsNotFiniteIsRefusedNamingWhatIsWrong)
{
  vrrw_scene::Scene far = shippedScene("pick_place_drill");
  const std::size_t joint = far.urdf.find("name=\"ur5e_base_joint\"");
  ASSERT_NE(joint, std::string::npos);
  const std::size_t x = far.urdf.find("xyz=\"", joint) + 5;
  far.urdf.replace(x, far.urdf.find(' ', x) - x, "1e308");
  try
  {
    PhysicsWorld world(far);
    FAIL() << "a robot base at x = 1e308 was accepted";
  }
  catch (const std::runtime_error& e)
  {
    EXPECT_NE(std::string(e.what()).find("robot ur5e: base: position.x: 1e+308 outside [-100, 100]"),
              std::string::npos)
        << e.what();
  }
  vrrw_scene::Scene lost = shippedScene("pick_place_drill");
  lost.objects[1].pose.translation().x() = std::numeric_limits<double>::infinity();
  EXPECT_THROW(PhysicsWorld world(lost), std::runtime_error);
}

TEST(PhysicsWorld, ContactsNameTheTouchingPairsWithTheirNormalForce)
{
  PhysicsWorld world(shippedScene("pick_place_drill"));
  run(world, 0.5);
  const double weight = 9.81 * shippedScene("pick_place_drill").object("drill")->mass;
  const std::vector<ContactPair> resting = world.contacts();
  const ContactPair* drill = findContact(resting, "drill", "table");
  ASSERT_NE(drill, nullptr);
  EXPECT_NEAR(drill->normal_force, weight, 0.05 * weight);
  EXPECT_LT(drill->position.z(), world.objectPose("drill").translation().z() + 0.01);
  for (const ContactPair& c : resting)
    EXPECT_TRUE(c.body_a.rfind("ur5e_", 0) != 0 && c.body_b.rfind("ur5e_", 0) != 0) << c.body_a << " " << c.body_b;
  // Dropped beside the table, the drill lands on the floor.
  world.setObjectPose("drill", Eigen::Isometry3d(Eigen::Translation3d(1.5, 1.5, 0.3)));
  run(world, 1.0);
  EXPECT_NEAR(world.objectPose("drill").translation().z(), 0.0, 0.1);
  EXPECT_NE(findContact(world.contacts(), "drill", "floor"), nullptr);
  // A hand lowered onto the wrist at 0.1 m/s: the pair names the link and the hand.
  const Eigen::Vector3d wrist = world.framePose("ur5e_wrist_3_link").translation();
  double height = 0.25;
  run(world, 1.5, [&] {
    height -= 1e-4;
    const Eigen::Vector3d hand = wrist + Eigen::Vector3d(0, 0, height);
    world.operatorInput().setHand("right", Eigen::Isometry3d(Eigen::Translation3d(hand)), 0.05);
  });
  bool hand_on_arm = false;
  for (const ContactPair& c : world.contacts())  // names in order: "hand/..." < "ur5e_..."
    hand_on_arm = hand_on_arm || (c.body_a == "hand/right" && c.body_b.rfind("ur5e_", 0) == 0);
  EXPECT_TRUE(hand_on_arm);
}

TEST(PhysicsWorld, GraspAssistWeldsTheObjectToTheTcpWhenAsked)
{
  PhysicsWorld world(shippedScene("pick_place_drill"));
  OperatorInput& input = world.operatorInput();
  EXPECT_TRUE(input.graspAssists().empty());  // off unless asked for
  const Eigen::Isometry3d tcp = world.framePose("ur5e_tcp");
  Eigen::Isometry3d place = Eigen::Isometry3d::Identity();
  place.translation() = tcp.translation() - Eigen::Vector3d(0, 0, 0.25);  // below the open fingers, in free space
  world.setObjectPose("drill", place);
  input.setGraspAssist("ur5e", "drill", true);
  EXPECT_EQ(input.graspAssists(), std::vector<std::string>{ "ur5e/drill" });
  const Eigen::Isometry3d held = world.framePose("ur5e_tcp").inverse() * world.objectPose("drill");
  world.setDriveTargets("ur5e", { "ur5e_shoulder_pan_joint" }, { 0.3 }, {});
  run(world, 2.0);
  const Eigen::Isometry3d now = world.framePose("ur5e_tcp").inverse() * world.objectPose("drill");
  EXPECT_LT((now.translation() - held.translation()).norm(), 2e-3);
  EXPECT_GT(std::abs(world.jointStates("ur5e").position[0]), 0.1);
  input.setGraspAssist("ur5e", "drill", false);
  EXPECT_TRUE(input.graspAssists().empty());
  EXPECT_THROW(input.setGraspAssist("ur5e", "table", true), InputError);
}

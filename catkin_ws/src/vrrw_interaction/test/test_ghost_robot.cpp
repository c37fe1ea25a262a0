// GhostRobot, Presets, nearestBody and Hand on the shipped pick_place_drill cell (no ROS).
#include <fstream>
#include <gtest/gtest.h>

#include <vrrw_interaction/ghost_robot.h>
#include <vrrw_interaction/hand.h>
#include <vrrw_kinematics/scene_state.h>
#include <vrrw_kinematics/top_grasp.h>
#include <vrrw_scene/scene_loader.h>

using namespace vrrw_interaction;

namespace
{
class GhostTest : public ::testing::Test
{
protected:
  static void SetUpTestSuite()
  {
    scene_ = new vrrw_scene::Scene(vrrw_scene::loadScene("pick_place_drill"));
    world_ = new vrrw_kinematics::CollisionWorld(vrrw_kinematics::CollisionWorld::fromScene(*scene_));
    world_->loadOrComputeAllowedCollisions(scene_->cache_dir);
  }
  static void TearDownTestSuite()
  {
    delete world_;
    delete scene_;
  }
  GhostTest()
    : state_(vrrw_kinematics::initialState(world_->model(), *scene_))
    , arm_(*world_, *scene_->robot("ur5e"))
    , ghost_(arm_, Presets::load(presetsFile(), "ur5e", scene_->source_file, "ur5e", 6), arm_.jointValues(state_))
  {
  }
  static std::string presetsFile() { return vrrw_scene::vrrwRoot() + "/urdf/config/presets.yaml"; }

  static vrrw_scene::Scene* scene_;
  static vrrw_kinematics::CollisionWorld* world_;
  Eigen::VectorXd state_;
  vrrw_kinematics::Arm arm_;
  GhostRobot ghost_;
};
vrrw_scene::Scene* GhostTest::scene_ = nullptr;
vrrw_kinematics::CollisionWorld* GhostTest::world_ = nullptr;

double rotationError(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b)
{
  return Eigen::AngleAxisd(a.rotation().transpose() * b.rotation()).angle();
}
}  // namespace

TEST_F(GhostTest, EveryPresetIsExact)
{
  const Presets& presets = ghost_.presets();
  for (const std::string name : { "zero", "home", "square_left", "square_center", "square_right" })
  {
    ASSERT_TRUE(presets.has(name)) << name;
    const Outcome o = ghost_.preset(name, state_);
    ASSERT_TRUE(o.success) << name << ": " << o.message;
    if (std::string(name) == "zero")  // stretched out at the table's height
    {
      EXPECT_NE(o.message.find("(in collision: "), std::string::npos) << o.message;
    }
    EXPECT_EQ(ghost_.joints(), presets.at(name)) << name;
  }
  const Eigen::VectorXd home = (Eigen::VectorXd(6) << 0, -M_PI / 2, 0, -M_PI / 2, 0, 0).finished();
  EXPECT_EQ(presets.at("home"), home);
  const Outcome unknown = ghost_.preset("dance", state_);
  EXPECT_FALSE(unknown.success);
  EXPECT_NE(unknown.message.find("unknown preset 'dance'"), std::string::npos) << unknown.message;
}

TEST_F(GhostTest, SetPoseReachesThePoseAndRefusalsLeaveTheGhost)
{
  ASSERT_TRUE(ghost_.preset("square_center", state_).success);
  Eigen::Isometry3d target = ghost_.tcpPose(state_);
  target.translation() += Eigen::Vector3d(0.05, 0.1, -0.05);
  target.rotate(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX()));
  const Outcome set = ghost_.setPose(target, state_, 10.0);
  ASSERT_TRUE(set.success) << set.message;
  const Eigen::Isometry3d reached = ghost_.tcpPose(state_);
  EXPECT_LT((reached.translation() - target.translation()).norm(), 1e-6);
  EXPECT_LT(rotationError(reached, target), 1e-6);

  const Eigen::VectorXd before = ghost_.joints();
  Eigen::Isometry3d far = target;
  far.translation() += Eigen::Vector3d(3.0, 0.0, 0.0);
  Eigen::Vector2d residual;
  const Outcome unreachable = ghost_.setPose(far, state_, 0.5, &residual);
  EXPECT_FALSE(unreachable.success);
  EXPECT_EQ(unreachable.message.rfind("unreachable (residual", 0), 0u) << unreachable.message;
  EXPECT_GT(residual[0], 1.0);
  EXPECT_EQ(ghost_.joints(), before);

  Eigen::Isometry3d into_table = target;
  into_table.translation().z() = 0.70;  // the table top is at 0.75
  const Outcome colliding = ghost_.setPose(into_table, state_, 10.0);
  EXPECT_FALSE(colliding.success);
  EXPECT_EQ(colliding.message.rfind("collision: ", 0), 0u) << colliding.message;
  EXPECT_EQ(ghost_.joints(), before);

  const Outcome nan = ghost_.setJoints({}, { 0, NAN, 0, 0, 0, 0 }, state_);
  EXPECT_FALSE(nan.success);
  EXPECT_NE(nan.message.find("not finite"), std::string::npos) << nan.message;
  EXPECT_FALSE(ghost_.setJoints({ "ur5e_elbow" }, { 0.1 }, state_).success);
  EXPECT_EQ(ghost_.joints(), before);
}

TEST_F(GhostTest, PlanPassesThroughTheWaypoints)
{
  ASSERT_TRUE(ghost_.preset("square_left", state_).success);
  ghost_.addWaypoint();
  ASSERT_TRUE(ghost_.preset("square_right", state_).success);
  ghost_.addWaypoint();
  ASSERT_TRUE(ghost_.preset("square_center", state_).success);
  const auto plan = ghost_.plan(state_, 2.0);
  ASSERT_TRUE(plan.success) << plan.message;
  ASSERT_EQ(plan.waypoint_times.size(), 3u);
  for (std::size_t w = 0; w < 2; ++w)
  {
    const auto& point = *std::find_if(plan.trajectory.points.begin(), plan.trajectory.points.end(),
                                      [&](const auto& p) { return std::abs(p.time - plan.waypoint_times[w]) < 1e-9; });
    for (std::size_t j = 0; j < 6; ++j)
      EXPECT_NEAR(point.positions[j], ghost_.waypoints()[w][j], 1e-6);
  }
  ASSERT_TRUE(ghost_.lastPlan());
  EXPECT_NEAR(ghost_.lastPlan()->points.back().positions[0], 0.0, 1e-9);
}

TEST_F(GhostTest, PlanThroughAWaypointTheWorldNowBlocksFailsNamingIt)
{
  ASSERT_TRUE(ghost_.preset("square_right", state_).success);  // the robot starts at square_center
  ghost_.addWaypoint();
  ASSERT_TRUE(ghost_.preset("square_left", state_).success);
  ghost_.clearPlan();
  vrrw_kinematics::CollisionWorld world = *world_;  // the drill moved to where waypoint 0 holds the gripper
  vrrw_kinematics::Arm arm(world, *scene_->robot("ur5e"));
  GhostRobot ghost(arm, ghost_.presets(), ghost_.joints());
  ghost.setJoints({}, std::vector<double>(ghost_.waypoints()[0].data(), ghost_.waypoints()[0].data() + 6), state_);
  ghost.addWaypoint();
  const Eigen::Isometry3d tcp = ghost.tcpPose(state_);
  ghost.preset("square_left", state_);
  Eigen::Isometry3d drill = Eigen::Isometry3d::Identity();
  drill.translation() = tcp.translation() - Eigen::Vector3d(0, 0, 0.1);
  world.setObjectPose("drill", drill);
  const auto plan = ghost.plan(state_, 1.0);
  EXPECT_FALSE(plan.success);
  EXPECT_EQ(plan.failed_waypoint, 0) << plan.message;
  EXPECT_FALSE(ghost.lastPlan());
}

TEST_F(GhostTest, PlaceContactLetsTheHeldDrillTouchTheTableOnlyAtTheGhostAndOnTheLastLeg)
{
  vrrw_kinematics::CollisionWorld world = *world_;
  vrrw_kinematics::Arm arm(world, *scene_->robot("ur5e"));
  std::vector<Eigen::Isometry3d> bodies;
  world.bodyTransforms(state_, bodies);
  Eigen::Isometry3d drill = bodies[world.bodyIndex("drill")];  // standing on the table
  drill.translation().z() += 0.05;
  world.setObjectPose("drill", drill);
  const Eigen::Isometry3d grasp = vrrw_kinematics::topGrasp(drill, Eigen::Vector3d(0.03, 0.0, 0.203));
  GhostRobot taker(arm, ghost_.presets(), arm.jointValues(state_));
  ASSERT_TRUE(taker.setPose(grasp, state_, 10.0).success);
  const Eigen::VectorXd state = arm.withJointValues(state_, taker.joints());
  std::vector<std::string> gripper_links;
  for (std::vector<int> below{ world.model().linkIndex("ur5e_tool0") }; !below.empty();)
  {
    const auto& link = world.model().links()[below.back()];
    below.pop_back();
    gripper_links.push_back(link.name);
    below.insert(below.end(), link.child_links.begin(), link.child_links.end());
  }
  world.attachObject("drill", "ur5e_tcp", state, gripper_links);  // held 5 cm above the table
  world.setAllowed("drill", "table", false);                       // as the interaction node does when it takes it

  GhostRobot ghost(arm, ghost_.presets(), taker.joints());
  const auto lowered = [&](double dz) { return grasp * Eigen::Isometry3d(Eigen::Translation3d(0, 0, dz)); };
  const Eigen::Isometry3d pressed = lowered(0.052), above = lowered(0.02);  // tool z points down
  const Outcome refused = ghost.setPose(pressed, state, 10.0);
  EXPECT_FALSE(refused.success);
  EXPECT_NE(refused.message.find("table"), std::string::npos) << refused.message;
  EXPECT_NE(refused.message.find("drill"), std::string::npos) << refused.message;

  int toggles = 0;
  ghost.place_contact = [&](bool allow) {
    world.setAllowed("drill", "table", allow);
    ++toggles;
  };
  const Outcome fingers = ghost.setPose(lowered(0.25), state, 10.0);  // the fingers 5 cm into the table
  EXPECT_FALSE(fingers.success);
  EXPECT_NE(fingers.message.find("table"), std::string::npos) << fingers.message;
  EXPECT_EQ(fingers.message.find("drill"), std::string::npos) << fingers.message;
  ASSERT_TRUE(ghost.setPose(pressed, state, 10.0).success);
  EXPECT_FALSE(world.acm().allowed("drill", "table"));
  EXPECT_EQ(toggles % 2, 0);

  // the pressing pose as a waypoint is refused: only the last leg may touch
  ghost.addWaypoint();
  ASSERT_TRUE(ghost.setPose(above, state, 10.0).success);
  const auto through = ghost.plan(state, 1.0);
  EXPECT_FALSE(through.success);
  EXPECT_EQ(through.failed_waypoint, 0) << through.message;

  // above it as the waypoint, pressed as the goal: planned, stopping at the waypoint, ending pressed
  ghost.clearWaypoints();
  ghost.addWaypoint();
  ASSERT_TRUE(ghost.setPose(pressed, state, 10.0).success);
  const auto place = ghost.plan(state, 1.0);
  ASSERT_TRUE(place.success) << place.message;
  ASSERT_EQ(place.waypoint_times.size(), 2u);
  EXPECT_NEAR(place.waypoint_times.back(), place.trajectory.points.back().time, 1e-9);
  const auto& end = place.trajectory.points.back().positions;
  for (std::size_t j = 0; j < 6; ++j)
    EXPECT_NEAR(end[j], ghost.joints()[Eigen::Index(j)], 1e-6);
  for (std::size_t k = 1; k < place.trajectory.points.size(); ++k)
    ASSERT_GT(place.trajectory.points[k].time, place.trajectory.points[k - 1].time);
  EXPECT_FALSE(world.acm().allowed("drill", "table"));
  EXPECT_EQ(toggles % 2, 0);
}

TEST_F(GhostTest, BadRequestsAreRefusedNamingTheFieldAndTheGhostStays)
{
  ASSERT_TRUE(ghost_.preset("home", state_).success);
  const Eigen::VectorXd home = ghost_.joints();
  // a joint named twice is refused (vrrw_common's joint mapping), as /<robot>/plan and the controller refuse it
  const Outcome twice = ghost_.setJoints({ "ur5e_elbow_joint", "ur5e_elbow_joint" }, { 0.5, 0.7 }, state_);
  EXPECT_FALSE(twice.success);
  EXPECT_EQ(twice.message, "name: 'ur5e_elbow_joint' named twice");
  EXPECT_EQ(ghost_.joints(), home);
  // a target 1e300 m away says how far (it said "residual 0.000 m": issue 21), in a few characters
  Eigen::Isometry3d far = ghost_.tcpPose(state_);
  for (const double x : { 5.0, 1e100, 1e300 })
  {
    far.translation().x() = x;
    const Outcome o = ghost_.setPose(far, state_, 10.0);
    EXPECT_FALSE(o.success);
    EXPECT_LT(o.message.size(), 60u) << o.message;
    const double residual = std::stod(o.message.substr(o.message.find("residual ") + 9));
    EXPECT_GT(residual, 0.5 * x) << o.message;
    EXPECT_LT(residual, 2.0 * x) << o.message;
  }
  EXPECT_EQ(ghost_.joints(), home);
}

TEST_F(GhostTest, HandGrabsTheNearestBodyAtItsSurface)
{
  std::vector<Eigen::Isometry3d> links;
  world_->model().linkTransforms(state_, links);
  const Eigen::Isometry3d wrist = links[world_->model().linkIndex("ur5e_wrist_3_link")];
  const Eigen::Vector3d near = wrist.translation() + wrist.rotation() * Eigen::Vector3d(0, 0, 0.0);
  const auto target = nearestBody(*world_, state_, near, 0.05, [](const auto& b) { return !b.object; });
  ASSERT_TRUE(target);
  EXPECT_EQ(target->robot, "ur5e");
  EXPECT_LT(target->distance, 0.05);
  const Eigen::Isometry3d frame = links[world_->model().linkIndex(target->body)];
  EXPECT_LT((frame * target->point_in_body - target->point_in_world).norm(), 1e-9);
  EXPECT_FALSE(nearestBody(*world_, state_, Eigen::Vector3d(5, 5, 5), 0.05, [](const auto&) { return true; }));

  Hand hand("left");
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = near;
  hand.setPose(pose, 10.0);
  EXPECT_EQ(hand.setGrip(0.2), Hand::GripChange::None);
  EXPECT_EQ(hand.setGrip(0.9), Hand::GripChange::Close);
  hand.hold(*target);
  pose.translation() += Eigen::Vector3d(0.2, 0, 0);
  hand.setPose(pose, 10.3);
  EXPECT_LT((hand.heldPointTarget() - target->point_in_world - Eigen::Vector3d(0.2, 0, 0)).norm(), 1e-12);
  EXPECT_FALSE(hand.stale(10.7));
  EXPECT_TRUE(hand.stale(10.81));
  EXPECT_EQ(hand.setGrip(0.1), Hand::GripChange::Open);
  EXPECT_EQ(gripError(0.5), "");
  EXPECT_NE(gripError(1.5).find("outside [0, 1]"), std::string::npos);
  EXPECT_EQ(gripError(NAN), "not finite");
}

TEST(Presets, BadFilesNameTheField)
{
  const std::string file = ::testing::TempDir() + "/bad_presets.yaml";
  std::ofstream(file) << "ur5e:\n  home: [0, 1, 2]\n";
  try
  {
    Presets::load(file, "ur5e", "", "ur5e", 6);
    FAIL() << "accepted";
  }
  catch (const PresetError& e)
  {
    EXPECT_NE(std::string(e.what()).find("ur5e.home: must list 6 joint values"), std::string::npos) << e.what();
  }
  std::ofstream(file) << "ur5e:\n  home: [0, 1, 2, x, 4, 5]\n";
  EXPECT_THROW(Presets::load(file, "ur5e", "", "ur5e", 6), PresetError);
}

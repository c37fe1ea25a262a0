// Node test (rostest, real master, real nodes, fake controller): the ghost's services, the marker's
// latest-wins drag, plan and execute through two waypoints, free-drive by a scripted hand, and bad input.
#include <geometry_msgs/PoseStamped.h>
#include <std_msgs/Bool.h>
#include <std_msgs/Float64.h>
#include <std_srvs/SetBool.h>
#include <std_srvs/Trigger.h>
#include <tf2_eigen/tf2_eigen.h>
#include <visualization_msgs/InteractiveMarkerFeedback.h>
#include <visualization_msgs/InteractiveMarkerUpdate.h>
#include <vrrw_msgs/GhostExecute.h>
#include <vrrw_msgs/GhostPlan.h>
#include <vrrw_msgs/GhostPreset.h>
#include <vrrw_msgs/GhostSetJoints.h>
#include <vrrw_msgs/GhostSetPose.h>
#include <vrrw_trajectory/msg_conversions.h>

#include "interaction_fixture.h"

using namespace vrrw_interaction_test;

namespace
{
struct Cell
{
  explicit Cell(ros::NodeHandle& nh, const std::string& scene)
    : arm(scene)
    , ghost(nh, "/ur5e/ghost/joint_states")
    , robot(nh, "/ur5e/joint_states")
    , events(nh, "/operator/events")
    , updates(nh, "/interaction/update")
    , active(nh, "/ur5e/free_drive_active")
    , feedback(nh.advertise<visualization_msgs::InteractiveMarkerFeedback>("/interaction/feedback", 10))
    , hand_pose(nh.advertise<geometry_msgs::PoseStamped>("/operator/test_hand/pose", 10))
    , hand_grip(nh.advertise<std_msgs::Float64>("/operator/test_hand/grip", 10))
  {
  }
  vrrw_msgs::GhostPreset preset(const std::string& name)
  {
    vrrw_msgs::GhostPreset srv;
    srv.request.name = name;
    return call("/ur5e/ghost/preset", srv);
  }
  vrrw_msgs::GhostSetPose setPose(const Eigen::Isometry3d& pose, const std::string& frame = "world")
  {
    vrrw_msgs::GhostSetPose srv;
    srv.request.pose.header.frame_id = frame;
    srv.request.pose.pose = tf2::toMsg(pose);
    return call("/ur5e/ghost/set_pose", srv);
  }
  std_srvs::Trigger trigger(const std::string& name) { return call<std_srvs::Trigger>("/ur5e/ghost/" + name); }
  /// The ghost as published after now (the ghost publishes at 10 Hz and on every change).
  Eigen::VectorXd ghostQ()
  {
    const ros::Time now = ros::Time::now();
    EXPECT_TRUE(eventually([&] { return ghost.last().header.stamp >= now; })) << "no ghost state since " << now;
    return arm6(ghost.last());
  }
  bool hasEvent(const std::string& kind)
  {
    for (const auto& e : events.all())
      if (e.kind == kind)
        return true;
    return false;
  }
  SceneArm arm;
  Latest<sensor_msgs::JointState> ghost, robot;
  Latest<vrrw_msgs::Event> events;
  Latest<visualization_msgs::InteractiveMarkerUpdate> updates;
  Latest<std_msgs::Bool> active;
  ros::Publisher feedback, hand_pose, hand_grip;
};
Cell* cell = nullptr;
}  // namespace

TEST(InteractionFake, PresetsAreExactAndTheSceneAddsOne)
{
  ASSERT_TRUE(cell->ghost.wait(20.0));
  const double h = M_PI / 2;
  const std::map<std::string, std::vector<double>> expected = {
    { "zero", { 0, 0, 0, 0, 0, 0 } }, { "home", { 0, -h, 0, -h, 0, 0 } },
    { "square_center", { 0, -h, h, -h, -h, 0 } }, { "over_bin", { -0.5, -1.2, 1.4, -1.77, -1.57, 0.0 } }
  };
  for (const std::string name : { "square_left", "square_right" })
    EXPECT_TRUE(cell->preset(name).response.success) << name;
  for (const auto& [name, q] : expected)
  {
    const auto srv = cell->preset(name);
    ASSERT_TRUE(srv.response.success) << name << ": " << srv.response.message;
    for (int j = 0; j < 6; ++j)
      EXPECT_EQ(cell->ghostQ()[j], q[j]) << name << " joint " << j;
  }
}

TEST(InteractionFake, SetPoseInAnyFrameIsReachedAndRefusalsLeaveTheGhost)
{
  ASSERT_TRUE(cell->preset("square_center").response.success);
  Eigen::Isometry3d target = cell->arm.tcp(cell->ghostQ());
  target.translation() += Eigen::Vector3d(0.04, -0.08, 0.05);
  target.rotate(Eigen::AngleAxisd(0.25, Eigen::Vector3d::UnitY()));
  const Eigen::Isometry3d base = cell->arm.world.model().relativeTransform(cell->arm.state, "world", "ur5e_base_link");
  const auto srv = cell->setPose(base.inverse() * target, "ur5e_base_link");
  ASSERT_TRUE(srv.response.success) << srv.response.message;
  const Eigen::Isometry3d reached = cell->arm.tcp(cell->ghostQ());
  EXPECT_LT((reached.translation() - target.translation()).norm(), 1e-6);
  EXPECT_LT(Eigen::AngleAxisd(reached.rotation().transpose() * target.rotation()).angle(), 1e-6);

  const Eigen::VectorXd before = cell->ghostQ();
  Eigen::Isometry3d far = target;
  far.translation().x() += 3.0;
  const auto unreachable = cell->setPose(far);
  EXPECT_FALSE(unreachable.response.success);
  EXPECT_EQ(unreachable.response.message.rfind("unreachable (residual", 0), 0u) << unreachable.response.message;
  Eigen::Isometry3d low = target;
  low.translation().z() = 0.70;
  const auto colliding = cell->setPose(low);
  EXPECT_FALSE(colliding.response.success);
  EXPECT_EQ(colliding.response.message.rfind("collision: ", 0), 0u) << colliding.response.message;
  EXPECT_EQ(cell->ghostQ(), before);  // a ghost state published after both refusals
}

TEST(InteractionFake, BadInputIsOneLineNamingTheFieldAndMovesNothing)
{
  ASSERT_TRUE(cell->preset("square_center").response.success);
  const Eigen::VectorXd before = cell->ghostQ();
  const auto expectRefused = [](const std::string& message, const std::string& part) {
    EXPECT_NE(message.find(part), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  };
  auto unknown = cell->preset("dance");
  EXPECT_FALSE(unknown.response.success);
  expectRefused(unknown.response.message, "name: unknown preset 'dance' (known: home, over_bin,");
  vrrw_msgs::GhostSetPose pose;
  pose.request.pose.header.frame_id = "world";
  pose.request.pose.pose.position.z = 1.0;
  pose.request.pose.pose.orientation.w = NAN;
  auto nan = call("/ur5e/ghost/set_pose", pose);
  EXPECT_FALSE(nan.response.success);
  expectRefused(nan.response.message, "pose.pose: ");
  pose.request.pose.pose.orientation.w = 0.5;
  auto non_unit = call("/ur5e/ghost/set_pose", pose);
  EXPECT_FALSE(non_unit.response.success);
  expectRefused(non_unit.response.message, "quaternion");
  pose.request.pose.pose.orientation.w = 1.0;
  pose.request.pose.header.frame_id = "no_such_frame";
  auto frame = call("/ur5e/ghost/set_pose", pose);
  EXPECT_FALSE(frame.response.success);
  expectRefused(frame.response.message, "pose.header.frame_id: unknown frame 'no_such_frame'");
  vrrw_msgs::GhostSetJoints joints;
  joints.request.position = { 0, 0, 0 };
  auto short_joints = call("/ur5e/ghost/set_joints", joints);
  EXPECT_FALSE(short_joints.response.success);
  expectRefused(short_joints.response.message, "position: 3 values, the arm has 6 joints");
  auto execute = call<vrrw_msgs::GhostExecute>("/ur5e/ghost/execute");
  EXPECT_FALSE(execute.response.success);
  expectRefused(execute.response.message, "no plan");
  EXPECT_EQ(cell->ghostQ(), before);
  EXPECT_FALSE(ros::service::exists("/ur7e/ghost/preset", false));  // an unknown robot has no services
}

TEST(InteractionFake, MarkerDragMovesTheGhostAndAnUnreachablePoseTurnsItRed)
{
  ASSERT_TRUE(cell->preset("square_center").response.success);
  Eigen::Isometry3d target = cell->arm.tcp(cell->ghostQ());
  visualization_msgs::InteractiveMarkerFeedback f;
  f.header.frame_id = "world";
  f.client_id = "test";
  f.marker_name = "ur5e";
  f.event_type = visualization_msgs::InteractiveMarkerFeedback::POSE_UPDATE;
  for (int i = 1; i <= 20; ++i)  // 100 Hz, 1 mm a step
  {
    target.translation().y() += 0.001;
    f.header.stamp = ros::Time::now();
    f.pose = tf2::toMsg(target);
    cell->feedback.publish(f);
    ros::WallDuration(0.01).sleep();
  }
  // latest wins: the ghost ends at the last pose, however many of the drag's poses the node took on the way
  EXPECT_TRUE(eventually([&] { return (cell->arm.tcp(cell->ghostQ()).translation() - target.translation()).norm() < 1e-6; }));
  EXPECT_LT((cell->arm.tcp(cell->ghostQ()).translation() - target.translation()).norm(), 1e-6);
  const Eigen::VectorXd before = cell->ghostQ();
  target.translation().x() += 3.0;
  f.pose = tf2::toMsg(target);
  cell->feedback.publish(f);
  EXPECT_TRUE(eventually([&] {
    for (const auto& update : cell->updates.all())
      for (const auto& marker : update.markers)
        if (marker.description.find("unreachable (residual") != std::string::npos)
          return true;
    return false;
  })) << "the marker never said unreachable";
  EXPECT_EQ(cell->ghostQ(), before);
}

TEST(InteractionFake, PlanThroughTwoWaypointsAndExecuteEndsAtTheGhost)
{
  ASSERT_TRUE(cell->trigger("clear_waypoints").response.success);
  std::vector<Eigen::VectorXd> waypoints;
  for (const std::string name : { "square_left", "square_right" })
  {
    ASSERT_TRUE(cell->preset(name).response.success);
    waypoints.push_back(cell->ghostQ());
    ASSERT_TRUE(cell->trigger("add_waypoint").response.success);
  }
  ASSERT_TRUE(cell->preset("over_bin").response.success);
  const Eigen::VectorXd goal = cell->ghostQ();
  vrrw_msgs::GhostPlan plan;
  plan.request.time_limit = 2.0;
  plan = call("/ur5e/ghost/plan", plan);
  ASSERT_TRUE(plan.response.success) << plan.response.message;
  for (const Eigen::VectorXd& w : waypoints)
  {
    double nearest = 1e9;
    for (const auto& p : plan.response.trajectory.points)
      nearest = std::min(nearest, (Eigen::Map<const Eigen::VectorXd>(p.positions.data(), 6) - w).cwiseAbs().maxCoeff());
    EXPECT_LT(nearest, 1e-6);
  }
  // The same plan at half the velocity and a quarter of the acceleration limits: played at half speed.
  const double full_speed = vrrw_trajectory::fromMsg(plan.response.trajectory).duration();
  vrrw_msgs::GhostPlan slow = plan;
  slow.request.max_velocity_scaling_factor = 1.5;
  slow = call("/ur5e/ghost/plan", slow);
  EXPECT_FALSE(slow.response.success);
  EXPECT_NE(slow.response.message.find("max_velocity_scaling_factor: 1.5"), std::string::npos) << slow.response.message;
  slow.request.max_velocity_scaling_factor = 0.5;
  slow.request.time_profile = "trapezoid";
  slow = call("/ur5e/ghost/plan", slow);
  EXPECT_FALSE(slow.response.success);
  EXPECT_NE(slow.response.message.find("time_profile: 'trapezoid'"), std::string::npos) << slow.response.message;
  slow.request.time_profile = "minimum_jerk";  // smooth, so longer than the time-optimal plan
  slow = call("/ur5e/ghost/plan", slow);
  ASSERT_TRUE(slow.response.success) << slow.response.message;
  EXPECT_GT(vrrw_trajectory::fromMsg(slow.response.trajectory).duration(), 1.05 * full_speed);
  slow.request.time_profile = "";
  slow.request.max_acceleration_scaling_factor = 0.25;
  slow = call("/ur5e/ghost/plan", slow);
  ASSERT_TRUE(slow.response.success) << slow.response.message;
  EXPECT_NEAR(vrrw_trajectory::fromMsg(slow.response.trajectory).duration(), 2.0 * full_speed, 0.02 * full_speed);
  const auto execute = call<vrrw_msgs::GhostExecute>("/ur5e/ghost/execute");
  ASSERT_TRUE(execute.response.success) << execute.response.message;
  EXPECT_EQ(execute.response.error_code, 0);
  EXPECT_TRUE(eventually([&] { return (arm6(cell->robot.last()) - goal).cwiseAbs().maxCoeff() < 1e-6; }));
  EXPECT_LT((arm6(cell->robot.last()) - goal).cwiseAbs().maxCoeff(), 1e-6);
  EXPECT_TRUE(cell->hasEvent("plan"));
  EXPECT_TRUE(cell->hasEvent("execute"));
}

TEST(InteractionFake, FreeDriveFollowsAHandAndStopsWhereItIs)
{
  ASSERT_TRUE(call<std_srvs::SetBool>("/ur5e/free_drive", [] {
                std_srvs::SetBool s;
                s.request.data = true;
                return s;
              }()).response.success);
  ASSERT_TRUE(cell->active.wait(5.0, 2));  // the latched false of the start, then true
  EXPECT_TRUE(cell->active.last().data);
  const Eigen::VectorXd q0 = arm6(cell->robot.last());
  Eigen::VectorXd state = cell->arm.arm.withJointValues(cell->arm.state, q0);
  Eigen::Isometry3d hand = cell->arm.world.model().relativeTransform(state, "world", "ur5e_wrist_3_link");
  geometry_msgs::PoseStamped pose;
  pose.header.frame_id = "world";
  const auto send = [&] {
    pose.header.stamp = ros::Time::now();
    pose.pose = tf2::toMsg(hand);
    cell->hand_pose.publish(pose);
  };
  for (int i = 0; i < 500 && cell->hand_grip.getNumSubscribers() == 0; ++i, ros::WallDuration(0.02).sleep())
    send();  // the node finds /operator/<hand>/pose topics once a second
  ASSERT_GT(cell->hand_grip.getNumSubscribers(), 0u);
  for (int i = 0; i < 20; ++i, ros::WallDuration(0.02).sleep())
    send();  // the pose subscription may connect just after the grip's
  std_msgs::Float64 grip;
  grip.data = 1.5;  // bad: ignored
  cell->hand_grip.publish(grip);
  ros::WallDuration(0.1).sleep();
  EXPECT_FALSE(cell->hasEvent("grab"));
  grip.data = 1.0;
  cell->hand_grip.publish(grip);
  ASSERT_TRUE(eventually([&] { return cell->hasEvent("grab"); }));
  const Eigen::Vector3d tcp0 = cell->arm.tcp(q0).translation();
  for (int i = 0; i < 50; ++i, ros::WallDuration(0.02).sleep())  // 5 cm up in 1 s
  {
    hand.translation().z() += 0.001;
    send();
  }
  const auto moved_by = [&] { return Eigen::Vector3d(cell->arm.tcp(arm6(cell->robot.last())).translation() - tcp0); };
  EXPECT_TRUE(eventually([&] { return std::abs(moved_by().z() - 0.05) < 0.005; }));  // the hand's last pose reached
  const Eigen::Vector3d moved = moved_by();
  EXPECT_NEAR(moved.z(), 0.05, 0.005);
  EXPECT_LT(moved.head<2>().norm(), 0.005);
  grip.data = 0.0;
  cell->hand_grip.publish(grip);
  EXPECT_TRUE(eventually([&] { return cell->hasEvent("release"); }));
  ASSERT_TRUE(call<std_srvs::SetBool>("/ur5e/free_drive").response.success);
  EXPECT_TRUE(eventually([&] { return !cell->active.last().data; }));
  // the arm ends its last steps toward the hand's last pose (within 5 mm of it above, not yet at rest); from
  // then on, free-drive off, it must stay
  EXPECT_TRUE(eventually([&] {
    const Eigen::VectorXd before = arm6(cell->robot.last());
    ros::WallDuration(0.05).sleep();
    return (arm6(cell->robot.last()) - before).cwiseAbs().maxCoeff() < 1e-9;
  }));
  const Eigen::VectorXd held = arm6(cell->robot.last());
  ros::WallDuration(1.0).sleep();
  EXPECT_LT((arm6(cell->robot.last()) - held).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_TRUE(cell->hasEvent("free_drive_on"));
  EXPECT_TRUE(cell->hasEvent("free_drive_off"));
}

TEST(InteractionFake, AStaleHandLetsGo)
{
  const Eigen::VectorXd q = arm6(cell->robot.last());
  const Eigen::Isometry3d wrist = cell->arm.world.model().relativeTransform(
      cell->arm.arm.withJointValues(cell->arm.state, q), "world", "ur5e_wrist_3_link");
  geometry_msgs::PoseStamped pose;
  pose.header.frame_id = "world";
  pose.pose = tf2::toMsg(wrist);
  std_msgs::Float64 grip;
  grip.data = 0.0;
  cell->hand_grip.publish(grip);
  for (int i = 0; i < 10; ++i, ros::WallDuration(0.02).sleep())
    cell->hand_pose.publish(pose);
  const std::size_t before = cell->events.size();
  grip.data = 0.8;
  cell->hand_grip.publish(grip);
  // no pose any more: a lost tracker; the node lets go once the last pose is stale
  bool grabbed = false, stale = false;
  EXPECT_TRUE(eventually([&] {
    const auto events = cell->events.all();
    for (std::size_t i = before; i < events.size(); ++i)
    {
      grabbed = grabbed || events[i].kind == "grab";
      stale = stale || (events[i].kind == "release" && events[i].detail.find("stale") != std::string::npos);
    }
    return stale;
  }));
  EXPECT_TRUE(grabbed);
  EXPECT_TRUE(stale);
  grip.data = 0.0;
  cell->hand_grip.publish(grip);
}

int main(int argc, char** argv)
{
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_interaction_fake");
  ros::NodeHandle nh;
  ros::AsyncSpinner spinner(2);
  spinner.start();
  Cell c(nh, ros::param::param<std::string>("~scene", "pick_place_drill"));
  cell = &c;
  return RUN_ALL_TESTS();
}

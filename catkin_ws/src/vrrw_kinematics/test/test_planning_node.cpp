#include <gtest/gtest.h>
#include <cmath>
#include <limits>
#include <ros/ros.h>
#include <vrrw_common/ros/persistent_service.h>
#include <vrrw_msgs/AttachObject.h>
#include <vrrw_msgs/CheckPath.h>
#include <vrrw_msgs/CheckState.h>
#include <vrrw_msgs/ComputeFK.h>
#include <vrrw_msgs/ComputeIK.h>
#include <vrrw_msgs/Plan.h>

namespace
{
const std::vector<std::string> kArm = { "ur5e_shoulder_pan_joint", "ur5e_shoulder_lift_joint", "ur5e_elbow_joint",
                                        "ur5e_wrist_1_joint", "ur5e_wrist_2_joint", "ur5e_wrist_3_joint" };

sensor_msgs::JointState arm(const std::vector<double>& q)
{
  sensor_msgs::JointState state;
  state.name = kArm;
  state.position = q;
  return state;
}

template <typename Service>
Service call(const std::string& name, Service service)
{
  EXPECT_TRUE(ros::service::waitForService(name, ros::Duration(30.0))) << name;
  std::string error;
  EXPECT_TRUE(vrrw_common::services().tryCall(name, service, &error)) << error;
  return service;
}
}  // namespace

TEST(PlanningNode, FkIkRoundTrip)
{
  vrrw_msgs::ComputeFK fk;
  fk.request.joint_state = arm({ 0.3, -1.2, 1.4, -1.8, -1.57, 0.2 });
  fk = call("/ur5e/compute_fk", fk);
  ASSERT_EQ(fk.response.error_code, 0) << fk.response.message;
  EXPECT_EQ(fk.response.pose.header.frame_id, "world");
  EXPECT_GT(fk.response.pose.pose.position.z, 0.75);

  vrrw_msgs::ComputeIK ik;
  ik.request.pose = fk.response.pose;
  ik.request.seed = arm({ 0.25, -1.1, 1.3, -1.7, -1.5, 0.1 });
  ik = call("/ur5e/compute_ik", ik);
  ASSERT_EQ(ik.response.error_code, 0) << ik.response.message;
  ASSERT_EQ(ik.response.solution.position.size(), 6u);
  for (std::size_t i = 0; i < 6; ++i)
    EXPECT_NEAR(ik.response.solution.position[i], fk.request.joint_state.position[i], 1e-6);

  vrrw_msgs::ComputeIK free_only;  // a collision-free solution, position-only mode
  free_only.request.pose = fk.response.pose;
  free_only.request.mode = vrrw_msgs::ComputeIK::Request::POSITION_ONLY;
  free_only.request.avoid_collisions = true;
  free_only = call("/ur5e/compute_ik", free_only);
  ASSERT_EQ(free_only.response.error_code, 0) << free_only.response.message;
  vrrw_msgs::CheckState check;
  check.request.joint_state = free_only.response.solution;
  EXPECT_TRUE(call("/ur5e/check_state", check).response.valid);
  vrrw_msgs::ComputeFK reached;
  reached.request.joint_state = free_only.response.solution;
  reached = call("/ur5e/compute_fk", reached);
  EXPECT_NEAR(reached.response.pose.pose.position.x, fk.response.pose.pose.position.x, 1e-5);
  EXPECT_NEAR(reached.response.pose.pose.position.z, fk.response.pose.pose.position.z, 1e-5);

  vrrw_msgs::ComputeFK in_base;
  in_base.request.joint_state = fk.request.joint_state;
  in_base.request.frame_id = "ur5e_base_link";
  in_base = call("/ur5e/compute_fk", in_base);
  EXPECT_NEAR(in_base.response.pose.pose.position.z, fk.response.pose.pose.position.z - 0.75, 1e-9);
}

TEST(PlanningNode, CheckStateNamesTheCollidingPair)
{
  vrrw_msgs::CheckState free;
  free.request.joint_state = arm({ 0.0, -1.57, 1.57, -1.57, -1.57, 0.0 });
  free = call("/ur5e/check_state", free);
  EXPECT_TRUE(free.response.valid) << free.response.message;
  EXPECT_GT(free.response.min_distance, 0.0);
  EXPECT_LT(free.response.min_distance, 0.5);

  vrrw_msgs::CheckState down;  // upper arm pointing down through the table
  down.request.joint_state = arm({ 0.0, 1.2, 0.0, 0.0, 0.0, 0.0 });
  down = call("/ur5e/check_state", down);
  EXPECT_FALSE(down.response.valid);
  EXPECT_TRUE(down.response.in_collision);
  EXPECT_EQ(down.response.error_code, 7);
  EXPECT_LE(down.response.min_distance, 0.0);
  EXPECT_TRUE(down.response.link_a == "table" || down.response.link_b == "table")
      << down.response.link_a << " - " << down.response.link_b;

  vrrw_msgs::CheckState limits;
  limits.request.joint_state = arm({ 0.0, -1.57, 4.0, -1.57, -1.57, 0.0 });
  limits = call("/ur5e/check_state", limits);
  EXPECT_FALSE(limits.response.within_limits);
  EXPECT_EQ(limits.response.error_code, 6);
  EXPECT_NE(limits.response.message.find("ur5e_elbow_joint"), std::string::npos);
}

/// A path of the arm's joints with one point per given state.
vrrw_msgs::CheckPath pathOf(const std::vector<std::vector<double>>& states)
{
  vrrw_msgs::CheckPath path;
  path.request.path.joint_names = kArm;
  for (const auto& q : states)
  {
    path.request.path.points.emplace_back();
    path.request.path.points.back().positions = q;
  }
  return path;
}

TEST(PlanningNode, CheckPathAnswersEveryPointAsCheckStateWould)
{
  // free, through the table, outside the elbow's limits, free again: every point answered in order
  const std::vector<std::vector<double>> states = { { 0.0, -1.57, 1.57, -1.57, -1.57, 0.0 },
                                                    { 0.0, 1.2, 0.0, 0.0, 0.0, 0.0 },
                                                    { 0.0, -1.57, 4.0, -1.57, -1.57, 0.0 },
                                                    { 0.3, -1.57, 1.57, -1.57, -1.57, 0.0 } };
  const vrrw_msgs::CheckPath path = call("/ur5e/check_path", pathOf(states));
  ASSERT_EQ(path.response.error_code, 0) << path.response.message;
  ASSERT_EQ(path.response.link_a.size(), 4u);
  ASSERT_EQ(path.response.link_b.size(), 4u);
  ASSERT_EQ(path.response.limit_violation.size(), 4u);
  for (std::size_t k = 0; k < states.size(); ++k)
  {
    vrrw_msgs::CheckState one;
    one.request.joint_state = arm(states[k]);
    one = call("/ur5e/check_state", one);
    EXPECT_EQ(path.response.link_a[k], one.response.link_a) << "point " << k;
    EXPECT_EQ(path.response.link_b[k], one.response.link_b) << "point " << k;
    EXPECT_EQ(path.response.limit_violation[k].empty(), one.response.within_limits) << "point " << k;
  }
  EXPECT_EQ(path.response.link_a[0], "");
  EXPECT_NE(path.response.link_a[1] + path.response.link_b[1], "");
  EXPECT_NE(path.response.limit_violation[2].find("ur5e_elbow_joint"), std::string::npos)
      << path.response.limit_violation[2];
  EXPECT_EQ(path.response.link_a[3], "");
}

TEST(PlanningNode, CheckPathRefusesABadPointOrAPathBeyondItsBoundWhole)
{
  vrrw_msgs::CheckPath nan = pathOf({ { 0.0, -1.57, 1.57, -1.57, -1.57, 0.0 },
                                      { 0.0, -1.57, std::nan(""), -1.57, -1.57, 0.0 } });
  nan = call("/ur5e/check_path", nan);
  EXPECT_EQ(nan.response.error_code, 9);
  EXPECT_EQ(nan.response.message, "check_path: path.points[1]: joint ur5e_elbow_joint: not finite");
  EXPECT_TRUE(nan.response.link_a.empty());

  vrrw_msgs::CheckPath short_point = pathOf({ { 0.0, -1.57, 1.57 } });
  short_point = call("/ur5e/check_path", short_point);
  EXPECT_EQ(short_point.response.error_code, 9);
  EXPECT_EQ(short_point.response.message, "check_path: path.points[0]: 6 names but 3 positions");

  const std::size_t too_many = vrrw_msgs::CheckPath::Request::MAX_POINTS + 1;
  vrrw_msgs::CheckPath long_path =
      pathOf(std::vector<std::vector<double>>(too_many, { 0.0, -1.57, 1.57, -1.57, -1.57, 0.0 }));
  long_path = call("/ur5e/check_path", long_path);
  EXPECT_EQ(long_path.response.error_code, 9);
  EXPECT_EQ(long_path.response.message, "check_path: path.points: 20001 points; at most 20000 per call");
  EXPECT_TRUE(long_path.response.link_a.empty());

  vrrw_msgs::CheckPath empty = call("/ur5e/check_path", vrrw_msgs::CheckPath());
  EXPECT_EQ(empty.response.error_code, 0);
  EXPECT_TRUE(empty.response.link_a.empty());
}

TEST(PlanningNode, PlansATimedTrajectory)
{
  vrrw_msgs::Plan plan;
  plan.request.start = arm({ -0.8, -1.57, 1.57, -1.57, -1.57, 0.0 });
  plan.request.goal_joints = arm({ 0.8, -1.2, 1.2, -1.57, -1.57, 0.5 });
  plan.request.seed = 3;
  plan = call("/ur5e/plan", plan);
  ASSERT_EQ(plan.response.error_code, 0) << plan.response.message;
  const auto& points = plan.response.trajectory.points;
  ASSERT_GE(points.size(), 2u);
  EXPECT_EQ(plan.response.trajectory.joint_names, kArm);
  EXPECT_NEAR(points.front().positions[0], -0.8, 1e-9);
  EXPECT_NEAR(points.back().positions[0], 0.8, 1e-9);
  EXPECT_NEAR(points.back().positions[5], 0.5, 1e-9);
  for (std::size_t k = 1; k < points.size(); ++k)
    EXPECT_GT(points[k].time_from_start.toSec(), points[k - 1].time_from_start.toSec());
  for (const double v : points.back().velocities)
    EXPECT_EQ(v, 0.0);
  EXPECT_GT(plan.response.planning_time, 0.0);
  EXPECT_GT(plan.response.path_length, 1.6);

  vrrw_msgs::Plan pose_goal;
  pose_goal.request.start = plan.request.start;
  vrrw_msgs::ComputeFK fk;
  fk.request.joint_state = plan.request.goal_joints;
  pose_goal.request.goal_pose = call("/ur5e/compute_fk", fk).response.pose;
  pose_goal.request.planner = "RRT";
  pose_goal = call("/ur5e/plan", pose_goal);
  EXPECT_EQ(pose_goal.response.error_code, 0) << pose_goal.response.message;
}

TEST(PlanningNode, BadRequestsGetCodesAndTheNodeStaysUp)
{
  vrrw_msgs::ComputeFK unknown_link;
  unknown_link.request.link = "no_such_link";
  EXPECT_EQ(call("/ur5e/compute_fk", unknown_link).response.error_code, 2);

  vrrw_msgs::ComputeFK unknown_frame;
  unknown_frame.request.frame_id = "no_such_frame";
  EXPECT_EQ(call("/ur5e/compute_fk", unknown_frame).response.error_code, 2);

  vrrw_msgs::ComputeIK nan_pose;
  nan_pose.request.pose.pose.position.x = std::nan("");
  nan_pose.request.pose.pose.orientation.w = 1.0;
  EXPECT_EQ(call("/ur5e/compute_ik", nan_pose).response.error_code, 4);

  vrrw_msgs::ComputeIK not_unit;
  not_unit.request.pose.pose.orientation.w = 2.0;
  const auto not_unit_response = call("/ur5e/compute_ik", not_unit).response;
  EXPECT_EQ(not_unit_response.error_code, 4);
  EXPECT_NE(not_unit_response.message.find("quaternion"), std::string::npos);

  vrrw_msgs::ComputeIK unreachable;
  unreachable.request.pose.header.frame_id = "world";
  unreachable.request.pose.pose.position.x = 5.0;
  unreachable.request.pose.pose.orientation.w = 1.0;
  EXPECT_EQ(call("/ur5e/compute_ik", unreachable).response.error_code, 5);

  vrrw_msgs::Plan outside;
  outside.request.goal_joints = arm({ 0.0, -1.57, 4.0, -1.57, -1.57, 0.0 });
  EXPECT_EQ(call("/ur5e/plan", outside).response.error_code, 6);

  vrrw_msgs::Plan goal_in_collision;
  goal_in_collision.request.goal_joints = arm({ 0.0, 1.2, 0.0, 0.0, 0.0, 0.0 });
  EXPECT_EQ(call("/ur5e/plan", goal_in_collision).response.error_code, 7);

  vrrw_msgs::Plan start_in_collision;
  start_in_collision.request.start = arm({ 0.0, 1.2, 0.0, 0.0, 0.0, 0.0 });
  start_in_collision.request.goal_joints = arm({ 0.0, -1.57, 1.57, -1.57, -1.57, 0.0 });
  EXPECT_EQ(call("/ur5e/plan", start_in_collision).response.error_code, 7);

  vrrw_msgs::Plan bad_planner;
  bad_planner.request.goal_joints = arm({ 0.3, -1.57, 1.57, -1.57, -1.57, 0.0 });
  bad_planner.request.planner = "NoSuchPlanner";
  EXPECT_EQ(call("/ur5e/plan", bad_planner).response.error_code, 9);

  vrrw_msgs::Plan not_serial;
  not_serial.request.goal_pose.pose.orientation.w = 1.0;
  not_serial.request.link = "ur5e_base_link_inertia";
  EXPECT_EQ(call("/ur5e/plan", not_serial).response.error_code, 3);

  vrrw_msgs::CheckState unknown_joint;
  unknown_joint.request.joint_state.name = { "no_such_joint" };
  unknown_joint.request.joint_state.position = { 0.0 };
  EXPECT_EQ(call("/ur5e/check_state", unknown_joint).response.error_code, 9);

  vrrw_msgs::CheckState mimic_ignored;  // a full /joint_states message may carry mimic joints
  mimic_ignored.request.joint_state.name = { "ur5e_left_inner_knuckle_joint" };
  mimic_ignored.request.joint_state.position = { 0.1 };
  EXPECT_EQ(call("/ur5e/check_state", mimic_ignored).response.error_code, 0);

  vrrw_msgs::CheckState still_up;
  EXPECT_TRUE(vrrw_common::services().tryCall("/ur5e/check_state", still_up));
}

TEST(PlanningNode, PlanRequestsWithoutAUsableGoalOrTimeLimitAreRefused)
{
  vrrw_msgs::Plan empty;
  empty = call("/ur5e/plan", empty);
  EXPECT_EQ(empty.response.error_code, 9);
  EXPECT_EQ(empty.response.message.rfind("no goal", 0), 0u) << empty.response.message;

  vrrw_msgs::Plan twice;  // the controller refuses the same joint named twice: so does the planner
  twice.request.goal_joints = arm({ 0.3, -1.57, 1.57, -1.57, -1.57, 0.0 });
  twice.request.goal_joints.name[3] = kArm[0];
  twice = call("/ur5e/plan", twice);
  EXPECT_EQ(twice.response.error_code, 9);
  EXPECT_NE(twice.response.message.find("joint " + kArm[0] + ": named twice"), std::string::npos)
      << twice.response.message;

  for (const double limit : { -1.0, std::nan(""), std::numeric_limits<double>::infinity() })
  {
    vrrw_msgs::Plan bad_limit;
    bad_limit.request.goal_joints = arm({ 0.3, -1.57, 1.57, -1.57, -1.57, 0.0 });
    bad_limit.request.time_limit = limit;
    bad_limit = call("/ur5e/plan", bad_limit);
    EXPECT_EQ(bad_limit.response.error_code, 9) << limit;
    EXPECT_EQ(bad_limit.response.message.rfind("time_limit", 0), 0u) << bad_limit.response.message;
  }

  vrrw_msgs::Plan bad_profile;
  bad_profile.request.goal_joints = arm({ 0.3, -1.57, 1.57, -1.57, -1.57, 0.0 });
  bad_profile.request.time_profile = "s_curve";
  bad_profile = call("/ur5e/plan", bad_profile);
  EXPECT_EQ(bad_profile.response.error_code, 9);
  EXPECT_NE(bad_profile.response.message.find("time_profile: 's_curve'"), std::string::npos)
      << bad_profile.response.message;
}

TEST(PlanningNode, AnswersFromAStoppedJointStateStreamCarryAWarning)
{
  ros::NodeHandle nh;
  ros::Publisher states = nh.advertise<sensor_msgs::JointState>("/joint_states", 10);
  const sensor_msgs::JointState home = arm({ 0.0, -1.57, 1.57, -1.57, -1.57, 0.0 });
  for (int i = 0; i < 600 && states.getNumSubscribers() == 0; ++i)
    ros::Duration(0.05).sleep();
  for (int i = 0; i < 10; ++i)
  {
    states.publish(home);  // a controller streaming, then stopping (~stale_after is 1 s)
    ros::Duration(0.05).sleep();
  }
  ros::Duration(1.5).sleep();
  vrrw_msgs::CheckState stale = call("/ur5e/check_state", vrrw_msgs::CheckState());
  EXPECT_EQ(stale.response.error_code, 0);
  EXPECT_TRUE(stale.response.valid);
  EXPECT_NE(stale.response.message.find("last joint state of ur5e is"), std::string::npos) << stale.response.message;
  vrrw_msgs::Plan plan;
  plan.request.goal_joints = arm({ 0.3, -1.57, 1.57, -1.57, -1.57, 0.0 });
  plan = call("/ur5e/plan", plan);
  EXPECT_EQ(plan.response.error_code, 0) << plan.response.message;
  EXPECT_NE(plan.response.message.find("s old"), std::string::npos) << plan.response.message;

  vrrw_msgs::CheckState given;  // a request that gives every arm joint does not use the live state
  given.request.joint_state = home;
  given = call("/ur5e/check_state", given);
  EXPECT_EQ(given.response.message, "");
}

TEST(PlanningNode, AttachAndDetachAnObject)
{
  vrrw_msgs::AttachObject attach;
  attach.request.object = "drill";
  attach.request.attach = true;
  attach = call("/ur5e/attach_object", attach);
  EXPECT_EQ(attach.response.error_code, 0) << attach.response.message;

  vrrw_msgs::CheckState holding;  // the drill hangs from the tcp wherever it went when attached
  holding = call("/ur5e/check_state", holding);
  EXPECT_EQ(holding.response.error_code == 0 || holding.response.error_code == 7, true);

  vrrw_msgs::AttachObject detach;
  detach.request.object = "drill";
  detach = call("/ur5e/attach_object", detach);
  EXPECT_EQ(detach.response.error_code, 0) << detach.response.message;
  EXPECT_EQ(call("/ur5e/attach_object", detach).response.error_code, 9);

  vrrw_msgs::AttachObject unknown;
  unknown.request.object = "no_such_object";
  unknown.request.attach = true;
  EXPECT_EQ(call("/ur5e/attach_object", unknown).response.error_code, 9);
}

int main(int argc, char** argv)
{
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_planning_node");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}

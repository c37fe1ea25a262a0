// rostest: dmp_node learns from a rosbag written here, a CSV and a message, plans to new goals, and
// answers bad requests with success = false and a message naming the problem (and stays up).
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

#include <ros/ros.h>
#include <vrrw_common/ros/persistent_service.h>
#include <rosbag/bag.h>
#include <sensor_msgs/JointState.h>

#include <vrrw_dmp/Learn.h>
#include <vrrw_dmp/Plan.h>
#include <vrrw_dmp/dmp_yaml.h>
#include <vrrw_trajectory/csv.h>

#include "demo_fixture.h"

using vrrw_dmp_test::SmoothDemo;

namespace
{
const SmoothDemo kDemo;

std::string temporary(const std::string& name)
{
  return ::testing::TempDir() + "vrrw_dmp_node_" + std::to_string(::getpid()) + "_" + name;
}

/// A recording as the recorder writes it (without metadata): /ur5e/joint_states with the arm's 6 joints and
/// the gripper's, one state published twice.
std::string writeBag()
{
  const std::string path = temporary("demo.bag");
  rosbag::Bag bag(path, rosbag::bagmode::Write);
  const auto demo = vrrw_dmp_test::sample(kDemo, 300, 0.3);
  const ros::Time origin(1000.0);
  for (std::size_t k = 0; k < demo.points.size(); ++k)
  {
    sensor_msgs::JointState state;
    state.header.stamp = origin + ros::Duration(demo.points[k].time);
    for (std::size_t j = 0; j < 6; ++j)
    {
      state.name.push_back("ur5e_" + demo.joint_names[j]);
      state.position.push_back(demo.points[k].positions[j]);
    }
    state.name.push_back("ur5e_finger_joint");
    state.position.push_back(0.0);
    bag.write("/ur5e/joint_states", state.header.stamp, state);
    if (k == 10)
      bag.write("/ur5e/joint_states", state.header.stamp, state);
  }
  bag.close();
  return path;
}

std::vector<std::string> armJoints()
{
  std::vector<std::string> names;
  for (int j = 1; j <= 6; ++j)
    names.push_back("ur5e_joint_" + std::to_string(j));
  return names;
}

class DmpNodeTest : public ::testing::Test
{
protected:
  void SetUp() override
  {
    ASSERT_TRUE(ros::service::waitForService("/dmp_node/learn", ros::Duration(20.0)));
    ASSERT_TRUE(ros::service::waitForService("/dmp_node/plan", ros::Duration(20.0)));
  }

  vrrw_dmp::Learn::Response learn(vrrw_dmp::Learn::Request request)
  {
    vrrw_dmp::Learn service;
    service.request = request;
    EXPECT_TRUE(vrrw_common::services().tryCall("/dmp_node/learn", service));
    return service.response;
  }

  vrrw_dmp::Plan::Response plan(vrrw_dmp::Plan::Request request)
  {
    vrrw_dmp::Plan service;
    service.request = request;
    EXPECT_TRUE(vrrw_common::services().tryCall("/dmp_node/plan", service));
    return service.response;
  }
};
}  // namespace

TEST_F(DmpNodeTest, LearnsFromBagAndPlansToNewGoal)
{
  const std::string bag = writeBag();
  vrrw_dmp::Learn::Request request;
  request.bag_path = bag;
  request.robot = "ur5e";
  request.model_path = temporary("model.yaml");
  const auto learned = learn(request);
  ASSERT_TRUE(learned.success) << learned.message;
  EXPECT_EQ(learned.joint_names, armJoints());
  EXPECT_EQ(learned.samples, 300);  // the state published twice is one sample
  EXPECT_NEAR(learned.duration, kDemo.T, 1e-9);
  EXPECT_EQ(vrrw_dmp::loadDmp(request.model_path).provenance().source, bag + " robot ur5e");

  const auto reproduced = plan({});
  ASSERT_TRUE(reproduced.success) << reproduced.message;
  EXPECT_EQ(reproduced.message.find("warning"), std::string::npos) << reproduced.message;
  double sum = 0.0;
  std::size_t count = 0;
  for (const auto& point : reproduced.trajectory.points)
    if (point.time_from_start.toSec() <= kDemo.T)
    {
      const double e = point.positions[1] - kDemo.position(1, point.time_from_start.toSec());
      sum += e * e;
      ++count;
    }
  EXPECT_LT(std::sqrt(sum / static_cast<double>(count)), 1e-2);

  vrrw_dmp::Plan::Request to_goal;
  to_goal.start = { 0.0, -1.57, 1.2, -1.57, -1.57, 0.0 };
  to_goal.goal = { -0.5, -1.0, 0.4, -1.2, -1.0, 0.5 };
  to_goal.tau = 4.0;
  to_goal.dt = 0.008;
  const auto planned = plan(to_goal);
  ASSERT_TRUE(planned.success) << planned.message;
  const auto& points = planned.trajectory.points;
  EXPECT_EQ(planned.trajectory.joint_names, armJoints());
  EXPECT_EQ(points.front().positions, to_goal.start);
  EXPECT_NEAR(points[1].time_from_start.toSec(), 0.008, 1e-9);
  EXPECT_GE(points.back().time_from_start.toSec(), 4.0);
  for (std::size_t j = 0; j < 6; ++j)
  {
    EXPECT_NEAR(points.back().positions[j], to_goal.goal[j], vrrw_dmp::RolloutRequest().goal_tolerance);
    EXPECT_NEAR(points.back().velocities[j], 0.0, vrrw_dmp::RolloutRequest().rest_speed);
  }
  std::remove(bag.c_str());
  std::remove(request.model_path.c_str());
}

TEST_F(DmpNodeTest, LearnsFromCsvAndFromMessage)
{
  const std::string csv = temporary("demo.csv");
  vrrw_trajectory::writeCsv(csv, vrrw_dmp_test::sample(kDemo, 200, 0.3));
  vrrw_dmp::Learn::Request from_csv;
  from_csv.csv_path = csv;
  from_csv.basis_count = 30;
  const auto learned = learn(from_csv);
  EXPECT_TRUE(learned.success) << learned.message;
  EXPECT_EQ(learned.samples, 200);
  std::remove(csv.c_str());

  vrrw_dmp::Learn::Request from_message;
  const auto demo = vrrw_dmp_test::sample(kDemo, 100, 0.0, 0.0, 1.0, 2);
  from_message.trajectory.joint_names = { "a", "b" };
  for (const auto& point : demo.points)
  {
    trajectory_msgs::JointTrajectoryPoint p;
    p.positions = point.positions;
    p.time_from_start = ros::Duration(point.time);
    from_message.trajectory.points.push_back(p);
  }
  const auto from_msg = learn(from_message);
  EXPECT_TRUE(from_msg.success) << from_msg.message;
  EXPECT_EQ(from_msg.joint_names, (std::vector<std::string>{ "a", "b" }));
  vrrw_dmp::Plan::Request to_goal;
  to_goal.goal = { 1.0, -1.0 };
  const auto planned = plan(to_goal);
  ASSERT_TRUE(planned.success) << planned.message;
  EXPECT_NEAR(planned.trajectory.points.back().positions[0], 1.0, 1e-3);
  EXPECT_NEAR(planned.trajectory.points.back().positions[1], -1.0, 1e-3);
  // b: g - x0 = -0.9 against the demonstrated 0.3, the shape is mirrored (a: 1.3 / 0.55, fine)
  EXPECT_NE(planned.message.find("; warning: joint 'b': goal scaling factor (g - x0)/(g_demo - x0_demo) = -3 mirrors"),
            std::string::npos)
      << planned.message;
  EXPECT_EQ(planned.message.find("joint 'a'"), std::string::npos) << planned.message;

  to_goal.goal = { 1.0, demo.points.front().positions[1] };  // b: goal == start
  const auto flat = plan(to_goal);
  ASSERT_TRUE(flat.success) << flat.message;
  EXPECT_NE(flat.message.find("; warning: joint 'b': new g - x0 = 0 is within 5%"), std::string::npos) << flat.message;
  EXPECT_NE(flat.message.find("--scaling amplitude"), std::string::npos) << flat.message;
  EXPECT_EQ(flat.message.find("joint 'a'"), std::string::npos) << flat.message;
}

TEST_F(DmpNodeTest, BadRequestsAreAnsweredAndTheNodeStaysUp)
{
  vrrw_dmp::Learn::Request good;
  good.csv_path = temporary("good.csv");
  vrrw_trajectory::writeCsv(good.csv_path, vrrw_dmp_test::sample(kDemo, 50, 0.0, 0.0, 1.0, 2));
  ASSERT_TRUE(learn(good).success);

  vrrw_dmp::Learn::Request missing_bag;
  missing_bag.bag_path = "/nonexistent/demo.bag";
  auto response = learn(missing_bag);
  EXPECT_FALSE(response.success);
  EXPECT_EQ(response.message, "/nonexistent/demo.bag: no such file");

  EXPECT_EQ(learn({}).message, "give exactly one of bag_path, csv_path or trajectory (got 0)");

  const std::string csv = temporary("bad.csv");
  std::ofstream(csv) << "t,a,a_vel\n0,1,0\n0.1,nan,0\n";
  vrrw_dmp::Learn::Request bad_csv;
  bad_csv.csv_path = csv;
  response = learn(bad_csv);
  EXPECT_FALSE(response.success);
  EXPECT_EQ(response.message, csv + ":3: column 'a': 'nan' is not finite");
  bad_csv.basis_count = -1;
  std::ofstream(csv) << "t,a,a_vel\n0,1,0\n0.1,2,0\n0.2,2,0\n";
  EXPECT_NE(learn(bad_csv).message.find("must be >= 0"), std::string::npos);
  std::remove(csv.c_str());

  vrrw_dmp::Plan::Request wrong_goal;
  wrong_goal.goal = { 1.0 };
  const auto planned = plan(wrong_goal);
  EXPECT_FALSE(planned.success);
  EXPECT_EQ(planned.message, "goal: 1 values for 2 joints") << planned.message;
  vrrw_dmp::Plan::Request negative_tau;
  negative_tau.tau = -2.0;
  EXPECT_EQ(plan(negative_tau).message, "tau = -2: must be a finite number > 0");

  // output that would not fit is refused before any work, and no model file is written
  vrrw_dmp::Plan::Request endless;
  endless.tau = 1e6;
  const auto refused = plan(endless);
  EXPECT_FALSE(refused.success);
  EXPECT_NE(refused.message.find("more than the limit of 1000000: raise dt or shorten tau"), std::string::npos)
      << refused.message;
  vrrw_dmp::Learn::Request huge_basis = good;
  huge_basis.basis_count = 1000000000;
  huge_basis.model_path = temporary("huge.yaml");
  EXPECT_EQ(learn(huge_basis).message, "basis count N = 1000000000: more than the limit of 10000");
  EXPECT_FALSE(std::ifstream(huge_basis.model_path).good());

  EXPECT_TRUE(learn(good).success);
  EXPECT_TRUE(plan({}).success);
  std::remove(good.csv_path.c_str());
}

int main(int argc, char** argv)
{
  ::testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_dmp_node");
  ros::NodeHandle node;
  return RUN_ALL_TESTS();
}

// The one real-mode goal path (RobotControllers, as `vrrw demos replay --mode real` and `./vrrw demo --real`
// use it) through the controller's real relay to a stand-in for ur_robot_driver that executes each goal at
// the driver's rate (vrrw_control/test/driver_stand_in.py): the replay end to end, a cancel while the real arm
// moves, a driver's abort, error and rejection forwarded with their codes, a new goal while the real arm
// moves, stamps and the start tolerance, and a driver that dies mid-goal (last: it leaves no driver).
#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <mutex>
#include <regex>
#include <sstream>
#include <sys/wait.h>
#include <thread>

#include <actionlib/client/simple_action_client.h>
#include <ros/master.h>
#include <ros/network.h>
#include <ros/ros.h>
#include <vrrw_demos/demo_csv.h>
#include <vrrw_demos/ros/robot_controllers.h>
#include <vrrw_trajectory/msg_conversions.h>
#include <xmlrpcpp/XmlRpcClient.h>

#include "scripted_demo.h"
#include "tool_process.h"

using namespace vrrw_demos;
using vrrw_demos_test::folder;
using vrrw_demos_test::run;

namespace
{
const std::vector<std::string> kJoints{ "ur5e_shoulder_pan_joint", "ur5e_shoulder_lift_joint", "ur5e_elbow_joint",
                                        "ur5e_wrist_1_joint",      "ur5e_wrist_2_joint",       "ur5e_wrist_3_joint" };

/// The stand-in's record: one JSON line per goal it received, written when the goal ended.
std::vector<std::string> received()
{
  std::ifstream in(ros::param::param<std::string>("/stand_in_record", ""));
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);)
    lines.push_back(line);
  return lines;
}

std::string field(const std::string& line, const std::string& key)
{
  const std::regex pattern("\"" + key + "\": (\"[^\"]*\"|\\[[^\\]]*\\]|[-0-9.e+]+)");
  std::smatch match;
  return std::regex_search(line, match, pattern) ? match[1].str() : "";
}

/// Waits until `done` holds: the condition is the verdict, 10 s of wall time only a guard against a hang.
bool eventually(const std::function<bool()>& done)
{
  for (int k = 0; k < 1000; ++k, ros::WallDuration(0.01).sleep())
    if (done())
      return true;
  return done();
}

double firstNumber(const std::string& list)
{
  return std::stod(list.substr(list.find('[') + 1));
}

/// The stand-in driver's arm (its own joint_states, unprefixed).
class DriverArm
{
public:
  explicit DriverArm(ros::NodeHandle& nh)
  {
    sub_ = nh.subscribe<sensor_msgs::JointState>("/stand_in/joint_states", 10, [this](const sensor_msgs::JointStateConstPtr& m) {
      std::lock_guard<std::mutex> lock(mutex_);
      pan_ = m->position[0];
    });
  }
  double pan()
  {
    std::lock_guard<std::mutex> lock(mutex_);
    return pan_;
  }
  /// Waits (wall, at most 10 s) until the real arm's pan is past \a value.
  bool waitPast(double value, double direction)
  {
    for (int k = 0; k < 2000; ++k, ros::WallDuration(0.005).sleep())
      if ((pan() - value) * direction > 0.0)
        return true;
    return false;
  }

private:
  std::mutex mutex_;
  double pan_ = 0.0;  ///< PROTECTED BY mutex_
  ros::Subscriber sub_;  ///< last: destroyed first (its shutdown waits for a running callback)
};

DriverArm* g_driver = nullptr;

/// Rest to rest from where the arm is, the pan turned by \a pan rad, over \a seconds.
ArmMotion turn(RobotControllers& controllers, const std::string& name, double pan, double seconds)
{
  ArmMotion motion;
  motion.name = name;
  motion.trajectory.joint_names = kJoints;
  const std::vector<double> from = controllers.measuredArm(kJoints, 5.0);
  std::vector<double> to = from;
  to[0] += pan;
  motion.trajectory.points = { { 0.0, from, std::vector<double>(6, 0.0), {} },
                               { seconds, to, std::vector<double>(6, 0.0), {} } };
  return motion;
}

void demand(const std::string& outcome, int code = 0)
{
  ros::param::set("/stand_in_driver/next_outcome", outcome);
  if (code != 0)
    ros::param::set("/stand_in_driver/next_error_code", code);
}
}  // namespace

TEST(RealRelay, ReplaySendsEachGoalToTheDriverOnceSimulated)
{
  const std::string csv = folder() + "/scripted.csv", bag = folder() + "/scripted.bag";
  exportCsv(vrrw_demos_test::scriptedPickPlace(250.0, 2e-4).demo.robots[0], csv);
  std::string output;
  ASSERT_EQ(run(VRRW_TOOL " import " + csv + " --bag " + bag + " --robot ur5e", &output), 0) << output;
  const std::size_t before = received().size();
  ASSERT_EQ(run(VRRW_TOOL " replay " + bag + " --mode real --yes", &output), 0) << output;
  // the controller ran each goal in simulation and held it for the confirmation, then relayed it
  EXPECT_NE(output.find("replay: to the recorded start: SUCCEEDED"), std::string::npos) << output;
  EXPECT_NE(output.find("(real arm)"), std::string::npos) << output;  // progress while the real arm moves
  EXPECT_NE(output.find("\"result\": \"SUCCEEDED\""), std::string::npos) << output;
  const auto goals = received();
  ASSERT_EQ(goals.size(), before + 2) << output;  // the approach and the demonstration; gripper goals stay simulated
  for (std::size_t k = before; k < goals.size(); ++k)
  {
    EXPECT_EQ(field(goals[k], "joint_names").rfind("[\"shoulder_pan_joint\"", 0), 0u) << goals[k];  // prefix stripped
    EXPECT_EQ(field(goals[k], "outcome"), "\"succeeded\"") << goals[k];
    EXPECT_EQ(field(goals[k], "skipped_points"), "0") << goals[k];  // executed from its first point
  }
}

TEST(RealRelay, CancelWhileTheRealArmMovesStopsItThereAndTheControllerShowsIt)
{
  RobotControllers controllers("ur5e", true);
  controllers.connect(10.0);
  const ArmMotion motion = turn(controllers, "turn", 0.4, 3.0);
  const double start = motion.trajectory.points[0].positions[0];
  GoalOutcome outcome;
  std::thread runner([&] { outcome = controllers.runArm(motion, 10.0); });
  ASSERT_TRUE(g_driver->waitPast(start + 0.05, 1.0)) << "the real arm never moved";
  controllers.cancel();
  runner.join();
  EXPECT_EQ(outcome.state, "CANCELLED");
  EXPECT_NE(outcome.message.find("PREEMPTED (canceled; cancel forwarded to the real driver)"), std::string::npos)
      << outcome.message;
  // the stand-in writes its record line when the goal has ended on its side
  EXPECT_TRUE(eventually([] { return !received().empty() && field(received().back(), "outcome") == "\"canceled\""; }));
  const auto goals = received();
  ASSERT_FALSE(goals.empty());
  EXPECT_EQ(field(goals.back(), "outcome"), "\"canceled\"") << goals.back();
  const double stopped = firstNumber(field(goals.back(), "at"));
  EXPECT_GT(stopped, start + 0.05);
  EXPECT_LT(stopped, start + 0.39);  // stopped well before the end
  // the virtual arm shows where the real one stopped
  RobotControllers again("ur5e", true);
  EXPECT_NEAR(again.measuredArm(kJoints, 5.0)[0], stopped, 1e-9);
}

TEST(RealRelay, ADriverAbortIsForwardedWithItsCodeAndTheArmStaysWhereItStopped)
{
  RobotControllers controllers("ur5e", true);
  controllers.connect(10.0);
  const ArmMotion motion = turn(controllers, "turn", -0.3, 2.0);
  const double start = motion.trajectory.points[0].positions[0];
  demand("abort");  // a protective stop halfway, PATH_TOLERANCE_VIOLATED
  const GoalOutcome outcome = controllers.runArm(motion, 10.0);
  EXPECT_EQ(outcome.state, "ABORTED");
  EXPECT_EQ(outcome.error_code, -4);
  EXPECT_NE(outcome.message.find("real driver: ABORTED stand-in: protective stop"), std::string::npos) << outcome.message;
  const auto goals = received();
  EXPECT_EQ(field(goals.back(), "outcome"), "\"aborted\"");
  const double stopped = firstNumber(field(goals.back(), "at"));
  EXPECT_NEAR(stopped, start - 0.15, 0.01);  // halfway of a symmetric rest-to-rest move (a tick is 0.5 mrad)
  eventually([&] { return std::abs(controllers.measuredArm(kJoints, 5.0)[0] - stopped) < 1e-9; });
  EXPECT_NEAR(controllers.measuredArm(kJoints, 5.0)[0], stopped, 1e-9);
}

TEST(RealRelay, ADriverErrorAndARejectionAreForwardedWithTheirCodes)
{
  RobotControllers controllers("ur5e", true);
  controllers.connect(10.0);
  demand("error", -5);  // runs to its end, then GOAL_TOLERANCE_VIOLATED
  GoalOutcome outcome = controllers.runArm(turn(controllers, "turn", 0.1, 0.5), 10.0);
  EXPECT_EQ(outcome.state, "ABORTED");
  EXPECT_EQ(outcome.error_code, -5);
  EXPECT_NE(outcome.message.find("stand-in: goal tolerance"), std::string::npos) << outcome.message;

  ros::WallDuration(0.3).sleep();
  const double before = g_driver->pan();
  demand("reject", -2);
  outcome = controllers.runArm(turn(controllers, "turn", 0.1, 0.5), 10.0);
  EXPECT_EQ(outcome.state, "ABORTED");
  EXPECT_EQ(outcome.error_code, -2);
  EXPECT_NE(outcome.message.find("real driver: REJECTED stand-in: rejected on demand"), std::string::npos)
      << outcome.message;
  EXPECT_EQ(field(received().back(), "outcome"), "\"rejected\"");
  EXPECT_EQ(g_driver->pan(), before);  // nothing moved
}

TEST(RealRelay, ANewGoalWhileTheRealArmMovesIsRefusedAndTheRunningOneFinishes)
{
  RobotControllers controllers("ur5e", true);
  controllers.connect(10.0);
  const std::size_t before = received().size();
  const ArmMotion motion = turn(controllers, "turn", 0.3, 2.0);
  GoalOutcome outcome;
  std::thread runner([&] { outcome = controllers.runArm(motion, 10.0); });
  ASSERT_TRUE(g_driver->waitPast(motion.trajectory.points[0].positions[0] + 0.02, 1.0));
  actionlib::SimpleActionClient<control_msgs::FollowJointTrajectoryAction> other(
      "/ur5e/arm_controller/follow_joint_trajectory", true);
  ASSERT_TRUE(other.waitForServer(ros::Duration(5.0)));
  control_msgs::FollowJointTrajectoryGoal second;
  second.trajectory = vrrw_trajectory::toMsg(motion.trajectory);
  other.sendGoal(second);
  ASSERT_TRUE(other.waitForResult(ros::Duration(5.0)));
  EXPECT_EQ(other.getState(), actionlib::SimpleClientGoalState::REJECTED);
  EXPECT_EQ(other.getResult()->error_string, "a goal is executing on the real robot; cancel it first");
  runner.join();
  EXPECT_TRUE(outcome.succeeded()) << outcome.text();
  EXPECT_EQ(received().size(), before + 1);  // the driver saw the first goal only
}

TEST(RealRelay, AStampedGoalReachesTheDriverStampedNowAndStartsWithinTheStartTolerance)
{
  RobotControllers controllers("ur5e", true);
  controllers.connect(10.0);
  // stamped 0.5 s ahead: the simulation waits for it; confirmed after the simulation, so by the time the
  // driver gets it that stamp lies in the past: relayed with stamp 0, it runs whole from its first point
  ArmMotion motion = turn(controllers, "stamped", 0.1, 1.0);
  motion.start = ros::Time::now() + ros::Duration(0.5);
  GoalOutcome outcome = controllers.runArm(motion, 10.0);
  EXPECT_TRUE(outcome.succeeded()) << outcome.text();
  auto goal = received().back();
  EXPECT_EQ(std::stod(field(goal, "stamp")), 0.0) << goal;
  EXPECT_EQ(field(goal, "skipped_points"), "0") << goal;

  // 8 mrad from the real arm: inside the controller's start tolerance (0.01) and the driver's (0.01)
  ros::WallDuration(0.3).sleep();
  motion = turn(controllers, "near", 0.1, 0.5);
  motion.trajectory.points[0].positions[1] += 0.008;
  outcome = controllers.runArm(motion, 10.0);
  EXPECT_TRUE(outcome.succeeded()) << outcome.text();
  // 20 mrad: the controller's gate refuses it; the driver never sees it
  ros::WallDuration(0.3).sleep();
  const std::size_t before = received().size();
  motion = turn(controllers, "far", 0.1, 0.5);
  motion.trajectory.points[0].positions[1] += 0.02;
  outcome = controllers.runArm(motion, 10.0);
  EXPECT_EQ(outcome.state, "REJECTED");
  EXPECT_NE(outcome.message.find("joint ur5e_shoulder_lift_joint: starts 0.02"), std::string::npos) << outcome.message;
  EXPECT_NE(outcome.message.find("nothing was sent to the real robot"), std::string::npos) << outcome.message;
  EXPECT_EQ(received().size(), before);
}

TEST(RealRelay, ADriverThatDiesMidGoalAbortsTheGoal)
{
  RobotControllers controllers("ur5e", true);
  controllers.connect(10.0);
  const ArmMotion motion = turn(controllers, "turn", 0.3, 3.0);
  GoalOutcome outcome;
  std::thread runner([&] { outcome = controllers.runArm(motion, 30.0); });
  ASSERT_TRUE(g_driver->waitPast(motion.trajectory.points[0].positions[0] + 0.02, 1.0));
  // kill the stand-in through its XML-RPC shutdown, as rosnode kill does
  XmlRpc::XmlRpcValue args, result, uri;
  args[0] = ros::this_node::getName();
  args[1] = "/stand_in_driver";
  ASSERT_TRUE(ros::master::execute("lookupNode", args, result, uri, false));
  std::string host;
  uint32_t port = 0;
  ASSERT_TRUE(ros::network::splitURI(static_cast<std::string>(uri), host, port));
  XmlRpc::XmlRpcClient client(host.c_str(), static_cast<int>(port), "/");
  XmlRpc::XmlRpcValue request, response;
  request[0] = ros::this_node::getName();
  request[1] = "test: the driver dies mid-goal";
  client.execute("shutdown", request, response);
  runner.join();
  EXPECT_EQ(outcome.state, "ABORTED") << outcome.text();
  EXPECT_NE(outcome.message.find("went away"), std::string::npos) << outcome.text();
}

int main(int argc, char** argv)
{
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_real_relay");
  ros::NodeHandle nh;
  ros::AsyncSpinner spinner(2);
  spinner.start();
  DriverArm driver(nh);
  g_driver = &driver;
  RobotControllers controllers("ur5e", true);
  controllers.connect(30.0);
  ros::WallDuration(0.5).sleep();  // the controller's relay client connects to the stand-in
  return RUN_ALL_TESTS();
}

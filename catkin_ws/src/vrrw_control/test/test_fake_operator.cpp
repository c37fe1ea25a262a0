// Node test (rostest, real master): the interfaces the operator flow needs, on the ur3e controller of
// fake_mode.test (splicing, 1 kHz): goal bursts, the command topic, free-drive, bad tolerances; on simulated time
// that the test advances (test_clock.h).
#include <actionlib/client/simple_action_client.h>
#include <actionlib/client/action_client.h>
#include <gtest/gtest.h>
#include <map>
#include <std_msgs/Bool.h>
#include <std_msgs/String.h>

#include "test_clock.h"

using namespace vrrw_control_test;
using ArmClient = actionlib::SimpleActionClient<control_msgs::FollowJointTrajectoryAction>;
using Result = control_msgs::FollowJointTrajectoryResult;
using State = actionlib::SimpleClientGoalState;

namespace
{
const double kVelocityLimit = 3.14159265, kAccelerationLimit = 3.14159265;  // ur.xacro (ur3e wrists 2 pi), ur3e.yaml
const std::string kAction = "/ur3e/arm_controller/follow_joint_trajectory";
TestClock* sim = nullptr;

struct Ur3e
{
  explicit Ur3e(ros::NodeHandle& nh)
    : arm(kAction, false)
    , states(nh, "/ur3e/joint_states")
    , command(nh.advertise<trajectory_msgs::JointTrajectory>("/ur3e/arm_controller/command", 100))
    , free_drive(nh.advertise<std_msgs::Bool>("/ur3e/free_drive_active", 1, true))
    , errors(nh.subscribe("/ur3e/arm_controller/errors", 100, &Ur3e::onError, this))
  {
    EXPECT_TRUE(waitForServer(*sim, arm));
  }
  std::vector<double> q()
  {
    sensor_msgs::JointState s;
    EXPECT_TRUE(states.waitLatest(s));
    return { s.position.begin(), s.position.begin() + 6 };
  }
  void onError(const std_msgs::String& msg)
  {
    std::lock_guard<std::mutex> lock(mutex);
    error_log.push_back(msg.data);
  }
  /// One-point trajectory to `to` (at `velocity`, or positions only when empty), `ahead` s from now.
  void stream(const std::vector<double>& to, double ahead, const std::vector<double>& velocity = {})
  {
    trajectory_msgs::JointTrajectory t;
    t.joint_names = armJoints("ur3e_");
    t.points = { point(ahead, to, velocity) };
    command.publish(t);
  }
  void setFreeDrive(bool on)
  {
    std_msgs::Bool msg;
    msg.data = on;
    free_drive.publish(msg);
  }
  ArmClient arm;
  JointStateLog states;
  ros::Publisher command, free_drive;
  ros::Subscriber errors;
  std::mutex mutex;
  std::vector<std::string> error_log;
};

Ur3e* ur3e = nullptr;
}  // namespace

TEST(FakeOperator, EveryGoalOfABurstGetsAResult)
{
  // 1000 goals at once from one actionlib client: one in three is invalid (rejected), the others each
  // replace the one before (preempted, the last succeeds); every one must end with a result
  ros::NodeHandle nh;
  actionlib::ActionClient<control_msgs::FollowJointTrajectoryAction> client(kAction);
  ASSERT_TRUE(waitForServer(*sim, client));
  const auto q0 = ur3e->q();
  const int burst = 1000;
  const ros::Time start = sim->now();
  std::vector<actionlib::ClientGoalHandle<control_msgs::FollowJointTrajectoryAction>> handles;
  for (int k = 0; k < burst; ++k)
  {
    auto goal = move("ur3e_", q0, { 0.001 * (k % 7), 0, 0, 0, 0, 0 }, 0.5);
    if (k % 3 == 1)
      goal.trajectory.points[1].positions[2] = std::nan("");
    handles.push_back(client.sendGoal(goal));
  }
  std::map<std::string, int> ended;
  int done = 0;
  sim->advanceUntil(
      [&] {
        done = 0;
        for (auto& h : handles)
          done += h.getCommState() == actionlib::CommState::DONE;
        return done == burst;
      },
      60.0, 0.05);
  const double seconds = (sim->now() - start).toSec();
  for (auto& h : handles)
    if (h.getCommState() == actionlib::CommState::DONE)
      ++ended[h.getTerminalState().toString()];
  std::cout << "burst: " << done << " of " << burst << " goals ended with a result in " << seconds
            << " s of simulated time:";
  for (const auto& [state, count] : ended)
    std::cout << " " << state << " " << count;
  std::cout << std::endl;
  EXPECT_EQ(done, burst);
  EXPECT_EQ(ended["REJECTED"], 333);
  EXPECT_EQ(ended["SUCCEEDED"], 1);
  EXPECT_EQ(ended["PREEMPTED"], 666);
}

TEST(FakeOperator, StreamedCommandsAreFollowedWithinTheLimits)
{
  // a sine streamed as positions and velocities 50 ms ahead, then a 0.4 rad step as positions only,
  // which the splice stretches to the limits
  const auto q0 = ur3e->q();
  auto sine = [&q0](double t, size_t j) { return q0[j] + 0.3 * (j % 2 ? -1.0 : 1.0) * std::sin(M_PI_2 * t); };
  const ros::Time start = sim->now();
  std::vector<double> target = q0, velocity(6);
  for (int k = 0; k < 300; ++k)
  {
    const double t = 0.01 * k, ahead = t + 0.05;
    for (size_t j = 0; j < 6; ++j)
    {
      target[j] = t < 2.0 ? sine(ahead, j) : q0[j] + 0.4;
      velocity[j] = 0.3 * (j % 2 ? -1.0 : 1.0) * M_PI_2 * std::cos(M_PI_2 * ahead);
    }
    ur3e->stream(target, 0.05, t < 2.0 ? velocity : std::vector<double>{});
    sim->advance(0.01);  // 100 Hz of simulated time
  }
  // during the sine the arm stays on its path: distance of each sample to the nearest point of the curve
  double worst_path = 0.0;
  for (const auto& s : ur3e->states.since(start + ros::Duration(0.3)))
  {
    if (s.header.stamp > start + ros::Duration(1.8))
      break;
    double nearest = 1e9;
    for (double tau = 0.0; tau <= 2.05; tau += 0.0005)
    {
      double d = 0.0;
      for (size_t j = 0; j < 6; ++j)
        d = std::max(d, std::abs(s.position[j] - sine(tau, j)));
      nearest = std::min(nearest, d);
    }
    worst_path = std::max(worst_path, nearest);
  }
  sim->advance(1.5);
  const auto run = ur3e->states.since(start);
  expectWithinLimits(run, "streamed commands", kVelocityLimit, kAccelerationLimit);
  std::cout << "streamed sine: largest distance from the streamed path " << worst_path << " rad" << std::endl;
  EXPECT_LT(worst_path, 3.5e-4);  // 1.0e-4 rad measured on simulated time (1.1e-4 on the wall clock; was < 2e-3)
  const auto q1 = ur3e->q();
  for (size_t j = 0; j < 6; ++j)
    EXPECT_NEAR(q1[j], q0[j] + 0.4, 1e-9);
}

TEST(FakeOperator, BadCommandsArePublishedAsErrorsAndAnEmptyOneStops)
{
  const auto q0 = ur3e->q();
  trajectory_msgs::JointTrajectory bad;
  bad.joint_names = armJoints("ur3e_");
  bad.points = { point(0.5, q0) };
  bad.points[0].positions[3] = std::nan("");
  ur3e->command.publish(bad);
  auto far = q0;
  far[0] += 1.5;
  ur3e->stream(far, 2.0);
  sim->advance(0.8);
  ur3e->command.publish(trajectory_msgs::JointTrajectory());  // stop
  const ros::Time stop = sim->now();
  sim->advance(1.5);
  {
    std::lock_guard<std::mutex> lock(ur3e->mutex);
    ASSERT_FALSE(ur3e->error_log.empty());
    EXPECT_EQ(ur3e->error_log.back(), "command: point 0: joint ur3e_wrist_1_joint: value is not finite");
  }
  const auto after = ur3e->states.since(stop);
  expectWithinLimits(after, "empty command stops", kVelocityLimit, kAccelerationLimit);
  EXPECT_EQ(after.back().position[0], after[after.size() - 10].position[0]) << "still moving";
  EXPECT_LT(after.back().position[0], far[0] - 0.1) << "the stop did not end early";
}

TEST(FakeOperator, AOnePointGoalFarAwayIsBlendedNotRefused)
{
  auto q = ur3e->q();
  control_msgs::FollowJointTrajectoryGoal g;
  g.trajectory.joint_names = armJoints("ur3e_");
  q[1] -= 0.6;
  g.trajectory.points = { point(0.0, q) };
  ur3e->arm.sendGoal(g);
  ASSERT_TRUE(sim->advanceUntilDone(ur3e->arm, 10.0));
  EXPECT_EQ(ur3e->arm.getState(), State::SUCCEEDED) << ur3e->arm.getResult()->error_string;
  sim->advance(0.05);
  EXPECT_NEAR(ur3e->q()[1], q[1], 1e-9);
}

TEST(FakeOperator, FreeDriveAbortsRejectsAcceptsCommandsAndHoldsWhenItEnds)
{
  const auto q0 = ur3e->q();
  ur3e->arm.sendGoal(move("ur3e_", q0, { 0.8, 0, 0, 0, 0, 0 }, 3.0));
  ASSERT_TRUE(waitTaken(ur3e->arm));
  sim->advance(0.5);
  ur3e->setFreeDrive(true);
  ASSERT_TRUE(sim->advanceUntilDone(ur3e->arm, 5.0));
  EXPECT_EQ(ur3e->arm.getState(), State::ABORTED);
  EXPECT_EQ(ur3e->arm.getResult()->error_string, "aborted: free-drive active");
  ur3e->arm.sendGoal(move("ur3e_", ur3e->q(), { 0.1, 0, 0, 0, 0, 0 }, 1.0));
  ASSERT_TRUE(sim->advanceUntilDone(ur3e->arm, 5.0));
  EXPECT_EQ(ur3e->arm.getState(), State::REJECTED);
  EXPECT_EQ(ur3e->arm.getResult()->error_string, "free-drive active");

  sim->advance(1.0);  // at rest
  auto target = ur3e->q();
  target[0] -= 1.0;
  ur3e->stream(target, 1.5);  // fake-mode free-drive moves the arm through the command topic
  sim->advance(0.9);
  const ros::Time off = sim->now();
  ur3e->setFreeDrive(false);  // mid-motion: brought to rest where it is, no jump, no swing back
  sim->advance(1.5);
  const auto after = ur3e->states.since(off - ros::Duration(0.05));
  expectWithinLimits(after, "free-drive off mid-motion", kVelocityLimit, kAccelerationLimit);
  EXPECT_GT(after.back().position[0], target[0] + 0.05) << "it went on to the command's target";
  EXPECT_LE(after.back().position[0], after.front().position[0]) << "it swung back";
  ur3e->arm.sendGoal(move("ur3e_", ur3e->q(), { 0.05, 0, 0, 0, 0, 0 }, 0.5));
  ASSERT_TRUE(sim->advanceUntilDone(ur3e->arm, 5.0));
  EXPECT_EQ(ur3e->arm.getState(), State::SUCCEEDED);
}

TEST(FakeOperator, NanPathToleranceAndNegativeGoalTimeToleranceAreNamed)
{
  auto g = move("ur3e_", ur3e->q(), { 0.1, 0, 0, 0, 0, 0 }, 0.5);
  control_msgs::JointTolerance tolerance;
  tolerance.name = "ur3e_elbow_joint";
  tolerance.position = std::nan("");
  g.path_tolerance = { tolerance };
  ur3e->arm.sendGoal(g);
  ASSERT_TRUE(sim->advanceUntilDone(ur3e->arm, 5.0));
  EXPECT_EQ(ur3e->arm.getState(), State::REJECTED);
  EXPECT_EQ(ur3e->arm.getResult()->error_code, Result::INVALID_GOAL);
  EXPECT_EQ(ur3e->arm.getResult()->error_string, "path_tolerance[0] (joint ur3e_elbow_joint): position is not finite");
  g.path_tolerance.clear();
  g.goal_time_tolerance = ros::Duration(-1.0);
  ur3e->arm.sendGoal(g);
  ASSERT_TRUE(sim->advanceUntilDone(ur3e->arm, 5.0));
  EXPECT_EQ(ur3e->arm.getState(), State::REJECTED);
  EXPECT_EQ(ur3e->arm.getResult()->error_string, "goal_time_tolerance -1 s: must be >= 0 (0: the default)");
}

int main(int argc, char** argv)
{
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_fake_operator");
  ros::NodeHandle nh;
  ros::AsyncSpinner spinner(2);
  spinner.start();
  // ticks of 5 ms: the UR3e cycles at each (200 Hz of simulated time), which every check here allows, at a fifth
  // of the cost of 1 ms ticks on a loaded machine. First, since the controllers start at the clock's first tick.
  TestClock clock(nh, ros::Time(1000.0), 0.005);
  sim = &clock;
  // the controller sizes its clients' queues for bursts; clients of this process come after it
  while (ros::ok() && !nh.hasParam(kAction + "/actionlib_client_pub_queue_size"))
    ros::WallDuration(0.05).sleep();
  Ur3e robot(nh);
  clock.follow(robot.states, 0.005);  // a cycle at every tick
  clock.advance(0.1);                 // the first states
  ur3e = &robot;
  return RUN_ALL_TESTS();
}

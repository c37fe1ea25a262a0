// Node test (rostest, real master): the vrrw_arm tool (./vrrw send, ./vrrw move) run as a user runs it.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <fstream>
#include <vrrw_common/run_program.h>
#include <vrrw_trajectory/csv.h>

#include "ros_test_helpers.h"

using namespace vrrw_control_test;

namespace
{
/// Runs the tool with \a arguments as given (no shell); its status and output.
vrrw_common::ProgramRun runTool(std::vector<std::string> arguments)
{
  arguments.insert(arguments.begin(), VRRW_ARM_TOOL);
  return vrrw_common::runCapturing(arguments);
}

/// The tool (or a stand-in) as a child process with its stdout and stderr on a pipe, argv passed as is.
class Child
{
public:
  explicit Child(std::vector<std::string> argv)
  {
    int ends[2];
    EXPECT_EQ(::pipe(ends), 0);
    pid_ = ::fork();
    if (pid_ == 0)
    {
      ::dup2(ends[1], 1);
      ::dup2(ends[1], 2);
      ::close(ends[0]);
      std::vector<char*> words;
      for (auto& word : argv)
        words.push_back(word.data());
      words.push_back(nullptr);
      ::execv(words[0], words.data());
      ::_exit(127);
    }
    ::close(ends[1]);
    out_ = ::fdopen(ends[0], "r");
  }
  ~Child()
  {
    if (pid_ > 0 && status_ < 0)
      ::kill(pid_, SIGKILL), wait();
    if (out_)
      ::fclose(out_);
  }
  /// Reads output lines until one contains \a text (or the output ends); true when found.
  bool readUntil(const std::string& text)
  {
    char buffer[512];
    while (std::fgets(buffer, sizeof(buffer), out_))
    {
      output += buffer;
      if (std::string(buffer).find(text) != std::string::npos)
        return true;
    }
    return false;
  }
  void signal(int number) { ::kill(pid_, number); }
  /// Reads the rest of the output and returns the exit code (-1: killed by a signal).
  int wait()
  {
    readUntil("\x01");
    int status = 0;
    ::waitpid(pid_, &status, 0);
    status_ = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return status_;
  }
  std::string output;

private:
  pid_t pid_ = -1;
  int status_ = -1;
  FILE* out_ = nullptr;
};

std::string join(const std::vector<double>& q)
{
  std::string text;
  for (double v : q)
    text += (text.empty() ? "" : ",") + std::to_string(v);
  return text;
}

JointStateLog* states = nullptr;

std::vector<double> arm()
{
  ros::Duration(0.1).sleep();
  sensor_msgs::JointState s;
  EXPECT_TRUE(states->waitLatest(s));
  return { s.position.begin(), s.position.begin() + 6 };
}

/// The arm once it rests: two readings 0.5 s apart that agree to 1e-9 rad.
std::vector<double> resting()
{
  auto q = arm();
  for (int k = 0; k < 40; ++k)
  {
    ros::WallDuration(0.5).sleep();
    const auto next = arm();
    double change = 0.0;
    for (size_t j = 0; j < q.size(); ++j)
      change = std::max(change, std::abs(next[j] - q[j]));
    q = next;
    if (change < 1e-9)
      break;
  }
  return q;
}

void expectAt(const std::vector<double>& target, double tolerance)
{
  const auto q = arm();
  for (size_t j = 0; j < 6; ++j)
    EXPECT_NEAR(q[j], target[j], tolerance) << "joint " << j;
}
}  // namespace

TEST(ArmTool, SendsACsvAndReportsProgressAndTheResult)
{
  const auto q0 = arm();
  vrrw_trajectory::JointTrajectory csv;
  csv.joint_names = armJoints("ur5e_");
  for (int k = 0; k <= 20; ++k)
  {
    const double u = k / 20.0, s = u * u * (3.0 - 2.0 * u), ds = 6.0 * u * (1.0 - u) / 1.5;
    vrrw_trajectory::TrajectoryPoint p;
    p.time = 10.0 + 1.5 * u;  // a recording's clock: the tool starts it at 0
    p.positions = q0;
    p.velocities.assign(6, 0.0);
    p.positions[0] += 0.3 * s;
    p.velocities[0] = 0.3 * ds;
    csv.points.push_back(p);
  }
  const std::string path = ::testing::TempDir() + "vrrw_arm_tool.csv";
  vrrw_trajectory::writeCsv(path, csv);
  const auto run = runTool({ "send", "ur5e", "--csv", path });
  std::remove(path.c_str());
  EXPECT_EQ(run.status, 0) << run.output;
  EXPECT_NE(run.output.find("sending 21 points over 1.5 s"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("result: SUCCEEDED (error_code 0 SUCCESSFUL)"), std::string::npos) << run.output;
  size_t progress = 0;
  for (size_t at = run.output.find("  t "); at != std::string::npos; at = run.output.find("  t ", at + 1))
    ++progress;
  EXPECT_GE(progress, 3u) << run.output;  // one line every 0.25 s of a 1.5 s motion
  expectAt(csv.points.back().positions, 1e-9);
}

TEST(ArmTool, SendsJointValuesAndTheGripper)
{
  auto target = arm();
  for (auto& q : target)
    q += 0.2;
  const auto run = runTool({ "send", "ur5e", "--joints", join(target) });
  EXPECT_EQ(run.status, 0) << run.output;
  expectAt(target, 1e-6);  // to the printed digits
  const auto grip = runTool({ "send", "ur5e", "--gripper", "0.4" });
  EXPECT_EQ(grip.status, 0) << grip.output;
  EXPECT_NE(grip.output.find("result: SUCCEEDED"), std::string::npos) << grip.output;
}

TEST(ArmTool, PlansAndMoves)
{
  const std::vector<double> target = { 0.4, -1.3, 1.2, -1.5, -1.57, 0.2 };
  const auto run = runTool({ "move", "ur5e", "--joints", join(target), "--seed", "3" });
  EXPECT_EQ(run.status, 0) << run.output;
  EXPECT_NE(run.output.find("planned in "), std::string::npos) << run.output;
  expectAt(target, 1e-6);
}

TEST(ArmTool, BadInputIsOneLineNamingIt)
{
  auto run = runTool({ "send", "nosuchrobot", "--joints", "0,0,0,0,0,0" });
  EXPECT_EQ(run.status, 1);
  EXPECT_EQ(run.output, "vrrw_arm: robot 'nosuchrobot' is not in the running workspace (its robots: ur5e)\n");
  run = runTool({ "send", "ur5e", "--joints", "0,0,0" });
  EXPECT_EQ(run.status, 2);
  EXPECT_EQ(run.output, "vrrw_arm: --joints: 3 values, expected 6\n");
  run = runTool({ "send", "ur5e", "--joints", "0,0,nan,0,0,0" });
  EXPECT_EQ(run.output, "vrrw_arm: --joints value 3: 'nan' is not a finite number\n");
  run = runTool({ "send", "ur5e", "--csv", "/nonexistent/demo.csv" });
  EXPECT_EQ(run.output, "vrrw_arm: /nonexistent/demo.csv:0: cannot open for reading\n");
  run = runTool({ "move", "ur5e", "--pose", "0,0,0,0,0,0" });
  EXPECT_EQ(run.output, "vrrw_arm: --pose: 6 values, expected 7\n");
  run = runTool({ "fly", "ur5e" });
  EXPECT_EQ(run.status, 2);
  EXPECT_EQ(run.output.rfind("vrrw_arm: unknown command 'fly'\nusage: vrrw_arm send ROBOT", 0), 0u) << run.output;
}

/// Ctrl-C (or SIGTERM) while the arm moves: the goal is cancelled, the arm stops short of the target.
void expectInterruptStops(int signal_number)
{
  const auto q0 = resting();
  auto target = q0;
  target[0] += 0.5;
  Child tool({ VRRW_ARM_TOOL, "send", "ur5e", "--joints", join(target), "--duration", "6" });
  ASSERT_TRUE(tool.readUntil("sending 1 points over 6 s")) << tool.output;
  for (int k = 0; k < 200 && std::abs(arm()[0] - q0[0]) < 0.02; ++k)
    ;  // until the arm moves (arm() waits 0.1 s)
  tool.signal(signal_number);
  EXPECT_EQ(tool.wait(), 130) << tool.output;
  EXPECT_NE(tool.output.find("interrupted: cancelling the goal\n"), std::string::npos) << tool.output;
  EXPECT_NE(tool.output.find("result: PREEMPTED"), std::string::npos) << tool.output;
  const auto stopped = resting();
  std::cout << "interrupted at " << stopped[0] - q0[0] << " rad of 0.5" << std::endl;
  EXPECT_GT(stopped[0] - q0[0], 0.02);
  EXPECT_LT(stopped[0] - q0[0], 0.45);  // the 6 s goal, cancelled after its first 0.02 rad, stops well short
}

TEST(ArmTool, InterruptCancelsTheGoal)
{
  expectInterruptStops(SIGINT);
  expectInterruptStops(SIGTERM);
}

TEST(ArmTool, AControllerGoneMidGoalIsNamed)
{
  ros::param::set("/scene/robots/standin/arm_joints", armJoints("standin_"));
  Child controller({ VRRW_SILENT_CONTROLLER, "_robot:=standin", "__name:=silent_controller" });
  ros::master::V_TopicInfo topics;
  const std::string status = "/standin/arm_controller/follow_joint_trajectory/status";
  for (int k = 0; k < 200; ++k, ros::WallDuration(0.1).sleep())
    if (ros::master::getTopics(topics) &&
        std::any_of(topics.begin(), topics.end(), [&](const auto& t) { return t.name == status; }))
      break;
  Child tool({ VRRW_ARM_TOOL, "send", "standin", "--joints", "0,0,0,0,0,0", "--duration", "2" });
  ASSERT_TRUE(tool.readUntil("sending 1 points")) << tool.output;
  ros::WallDuration(0.5).sleep();  // the goal is accepted: the stand-in holds it
  controller.signal(SIGKILL);
  controller.wait();
  EXPECT_EQ(tool.wait(), 1) << tool.output;
  const std::string line = "vrrw_arm: /standin/arm_controller/follow_joint_trajectory: the controller went away during "
                           "the goal (no status for 2 s); where the arm stopped is unknown\n";
  EXPECT_GE(tool.output.size(), line.size());
  EXPECT_EQ(tool.output.substr(tool.output.size() - std::min(line.size(), tool.output.size())), line) << tool.output;
}

TEST(ArmTool, AControllersRefusalIsPrintedWithItsReason)
{
  auto run = runTool({ "send", "ur5e", "--gripper", "5" });
  EXPECT_EQ(run.status, 1);
  EXPECT_NE(run.output.find("result: REJECTED: joint ur5e_finger_joint: position 5 outside limits [0, 0.8"),
            std::string::npos) << run.output;
  run = runTool({ "send", "ur5e", "--gripper", "-1" });
  EXPECT_NE(run.output.find("result: REJECTED: joint ur5e_finger_joint: position -1 outside limits"), std::string::npos)
      << run.output;
  run = runTool({ "send", "ur5e", "--gripper", "0.4", "--effort", "1e9" });
  EXPECT_NE(run.output.find("result: REJECTED: max_effort 1e+09 N exceeds the gripper's rated grip force"),
            std::string::npos) << run.output;
  run = runTool({ "send", "ur5e", "--joints", "9,0,0,0,0,0" });
  EXPECT_EQ(run.status, 1);
  EXPECT_NE(run.output.find("result: REJECTED (error_code -1 INVALID_GOAL): "), std::string::npos) << run.output;
}

TEST(ArmTool, OptionsAreRefusedNamingThem)
{
  auto run = runTool({ "send", "ur5e", "--joints", "0,0,0,0,0,0", "--duration", "1e10" });
  EXPECT_EQ(run.status, 2);
  EXPECT_EQ(run.output, "vrrw_arm: --duration: 1e10 outside [0, 86400] s\n");
  run = runTool({ "move", "ur5e", "--joints", "0,0,0,0,0,0", "--seed", "-1" });
  EXPECT_EQ(run.status, 2);
  EXPECT_EQ(run.output, "vrrw_arm: --seed: -1 is not a whole number >= 0\n");
  run = runTool({ "move", "ur5e", "--joints", "0,0,0,0,0,0", "--seed", "1e30" });
  EXPECT_EQ(run.output, "vrrw_arm: --seed: 1e30 outside [0, 18446744073709551615]\n");
  run = runTool({ "send", "ur5e", "--joints", "0,0,0,0,0,0", "--gripper", "0.1" });
  EXPECT_EQ(run.output, "vrrw_arm: --joints and --gripper exclude each other\n");
  run = runTool({ "send", "ur5e", "--duration", "2" });
  EXPECT_EQ(run.output, "vrrw_arm: give one of --csv, --joints, --gripper\n");
}

int main(int argc, char** argv)
{
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_arm_tool");
  ros::NodeHandle nh;
  ros::AsyncSpinner spinner(1);
  spinner.start();
  JointStateLog log(nh, "/ur5e/joint_states");
  states = &log;
  sensor_msgs::JointState s;
  if (!log.waitLatest(s, 20.0) || !ros::service::waitForService("/ur5e/plan", ros::Duration(60.0)))
    return 1;
  return RUN_ALL_TESTS();
}

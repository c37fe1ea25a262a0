// Node test (rostest, real master): the vrrw_arm tool (./vrrw send, ./vrrw move) run as a user runs it.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <fstream>
#include <vrrw_trajectory/csv.h>

#include "ros_test_helpers.h"

using namespace vrrw_control_test;

namespace
{
struct ToolRun
{
  int status = -1;
  std::string output;  ///< stdout and stderr
};

ToolRun runTool(const std::string& arguments)
{
  ToolRun run;
  FILE* pipe = ::popen((std::string(VRRW_ARM_TOOL) + " " + arguments + " 2>&1").c_str(), "r");
  char buffer[512];
  while (std::fgets(buffer, sizeof(buffer), pipe))
    run.output += buffer;
  const int status = ::pclose(pipe);
  run.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

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
  const auto run = runTool("send ur5e --csv " + path);
  std::remove(path.c_str());
  EXPECT_EQ(run.status, 0) << run.output;
  EXPECT_NE(run.output.find("sending 21 points over 1.5 s"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("result: SUCCEEDED (error_code 0)"), std::string::npos) << run.output;
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
  const auto run = runTool("send ur5e --joints " + join(target));
  EXPECT_EQ(run.status, 0) << run.output;
  expectAt(target, 1e-6);  // to the printed digits
  const auto grip = runTool("send ur5e --gripper 0.4");
  EXPECT_EQ(grip.status, 0) << grip.output;
  EXPECT_NE(grip.output.find("result: SUCCEEDED"), std::string::npos) << grip.output;
}

TEST(ArmTool, PlansAndMoves)
{
  const std::vector<double> target = { 0.4, -1.3, 1.2, -1.5, -1.57, 0.2 };
  const auto run = runTool("move ur5e --joints " + join(target) + " --seed 3");
  EXPECT_EQ(run.status, 0) << run.output;
  EXPECT_NE(run.output.find("planned in "), std::string::npos) << run.output;
  expectAt(target, 1e-6);
}

TEST(ArmTool, BadInputIsOneLineNamingIt)
{
  auto run = runTool("send nosuchrobot --joints 0,0,0,0,0,0");
  EXPECT_EQ(run.status, 1);
  EXPECT_EQ(run.output, "vrrw_arm: robot 'nosuchrobot' is not in the running workspace (its robots: ur5e)\n");
  run = runTool("send ur5e --joints 0,0,0");
  EXPECT_EQ(run.status, 2);
  EXPECT_EQ(run.output, "vrrw_arm: --joints: 3 values, expected 6\n");
  run = runTool("send ur5e --joints 0,0,nan,0,0,0");
  EXPECT_EQ(run.output, "vrrw_arm: --joints value 3: 'nan' is not a finite number\n");
  run = runTool("send ur5e --csv /nonexistent/demo.csv");
  EXPECT_EQ(run.output, "vrrw_arm: /nonexistent/demo.csv:0: cannot open for reading\n");
  run = runTool("move ur5e --pose 0,0,0,0,0,0");
  EXPECT_EQ(run.output, "vrrw_arm: --pose: 6 values, expected 7\n");
  run = runTool("fly ur5e");
  EXPECT_EQ(run.status, 2);
  EXPECT_EQ(run.output.rfind("vrrw_arm: unknown command 'fly'\nusage: vrrw_arm send ROBOT", 0), 0u) << run.output;
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

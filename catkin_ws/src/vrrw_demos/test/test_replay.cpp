// `vrrw demos replay` against running controllers: a scripted pick-and-place (CSV -> bag) replayed whole,
// then one segment; the tool's JSON line carries the error against the de-jittered path.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

#include <ros/ros.h>
#include <vrrw_demos/demo_csv.h>

#include "scripted_demo.h"

namespace
{
std::string g_mode = "fake";

std::string folder()
{
  static const std::string path = [] {
    char name[] = "/tmp/vrrw_replay_test_XXXXXX";
    return std::string(::mkdtemp(name));
  }();
  return path;
}

int run(const std::string& command, std::string& output)
{
  const std::string log = folder() + "/command.log";
  const int status = std::system((command + " >" + log + " 2>&1").c_str());
  std::ifstream in(log);
  std::stringstream text;
  text << in.rdbuf();
  output = text.str();
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

double field(const std::string& output, const std::string& key)
{
  const auto at = output.rfind("\"" + key + "\": ");
  return at == std::string::npos ? 1e9 : std::stod(output.substr(at + key.size() + 4));
}

std::string scriptedBag()
{
  const std::string csv = folder() + "/scripted.csv", bag = folder() + "/scripted.bag";
  if (::access(bag.c_str(), F_OK) == 0)
    return bag;
  vrrw_demos::exportCsv(vrrw_demos_test::scriptedPickPlace(250.0, 2e-4).demo.robots[0], csv);
  std::string output;
  EXPECT_EQ(run(VRRW_TOOL " import " + csv + " --bag " + bag + " --robot ur5e", output), 0) << output;
  return bag;
}
}  // namespace

TEST(Replay, WholeDemonstrationFollowsTheDejitteredPath)
{
  std::string output;
  ASSERT_EQ(run(VRRW_TOOL " replay " + scriptedBag() + " --mode " + g_mode, output), 0) << output;
  std::cout << output;
  EXPECT_NE(output.find("\"result\": \"SUCCEEDED\""), std::string::npos) << output;
  EXPECT_LE(field(output, "dejitter_max"), 1e-3);
  EXPECT_GT(field(output, "samples"), 500);
  if (g_mode == "fake")
    EXPECT_LE(field(output, "max_error"), 1e-9) << output;
  else
    EXPECT_LE(field(output, "rms_error"), 2e-3) << output;
  // The imported bag has no gripper goals: the gripper's own close and open become two goals.
  std::size_t goals = 0;
  for (auto at = output.find("replay: gripper -> "); at != std::string::npos; at = output.find("replay: gripper -> ", at + 1))
    ++goals;
  EXPECT_EQ(goals, 2u) << output;
}

TEST(Replay, OneSegmentAndBadInput)
{
  std::string output;
  ASSERT_EQ(run(VRRW_TOOL " replay " + scriptedBag() + " --mode " + g_mode + " --segment pick", output), 0) << output;
  EXPECT_NE(output.find("\"result\": \"SUCCEEDED\""), std::string::npos) << output;
  EXPECT_EQ(run(VRRW_TOOL " replay " + scriptedBag() + " --mode " + g_mode + " --segment wave", output), 1);
  EXPECT_NE(output.find("has no segment 'wave' (found: near_pick, pick, close_gripper, back_to_near_pick, final, "
                        "open_gripper)"),
            std::string::npos)
      << output;
  EXPECT_EQ(run(VRRW_TOOL " replay " + scriptedBag() + " --mode real", output), 1);
  EXPECT_NE(output.find("--mode real, but /ur5e/controller runs in mode '" + g_mode + "'"), std::string::npos) << output;
  const std::string csv = folder() + "/other.csv", bag = folder() + "/other.bag";
  auto other = vrrw_demos_test::scriptedPickPlace(50.0).demo.robots[0];
  for (auto& name : other.joint_names)
    name = "left_" + name.substr(5);
  vrrw_demos::exportCsv(other, csv);
  ASSERT_EQ(run(VRRW_TOOL " import " + csv + " --bag " + bag + " --robot ur5e", output), 0) << output;
  EXPECT_EQ(run(VRRW_TOOL " replay " + bag + " --mode " + g_mode, output), 1);
  EXPECT_NE(output.find("of the running scene has joints [ ur5e_shoulder_pan_joint"), std::string::npos) << output;
}

TEST(Replay, RealModeSendsEachGoalToTheDriverOnceSimulated)
{
  ASSERT_EQ(g_mode, "real") << "replay_real.test runs this one alone";
  const std::string goals = "/tmp/vrrw_replay_real_goals.jsonl";  // the stand-in driver's record
  std::remove(goals.c_str());
  std::string output;
  ASSERT_EQ(run(VRRW_TOOL " replay " + scriptedBag() + " --mode real --yes", output), 0) << output;
  // the controller ran each goal in simulation and held it for the confirmation, then relayed it
  EXPECT_NE(output.find("replay: to the recorded start: SUCCEEDED"), std::string::npos) << output;
  EXPECT_NE(output.find("\"result\": \"SUCCEEDED\""), std::string::npos) << output;
  EXPECT_EQ(output.find("not confirmed"), std::string::npos) << output;
  std::ifstream in(goals);
  std::vector<std::string> received;
  for (std::string line; std::getline(in, line);)
    received.push_back(line);
  ASSERT_EQ(received.size(), 2u) << output;  // the approach and the demonstration; gripper goals stay simulated
  for (const std::string& goal : received)
    EXPECT_NE(goal.find("\"joint_names\": [\"shoulder_pan_joint\""), std::string::npos) << goal;  // prefix stripped
}

int main(int argc, char** argv)
{
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_replay");
  for (int i = 1; i < argc; ++i)
    if (std::string(argv[i]) == "fake" || std::string(argv[i]) == "physics" || std::string(argv[i]) == "real")
      g_mode = argv[i];
  return RUN_ALL_TESTS();
}

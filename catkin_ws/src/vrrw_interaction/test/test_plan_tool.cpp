// Node test (rostest, real master): ./vrrw plan (vrrw_plan) summarises a plan and keeps it as a CSV that
// ./vrrw send (vrrw_arm) executes.
#include <gtest/gtest.h>

#include <cstdio>
#include <regex>
#include <ros/ros.h>
#include <ros/topic.h>
#include <sensor_msgs/JointState.h>
#include <vrrw_common/joint_mapping.h>
#include <vrrw_common/run_program.h>
#include <vrrw_trajectory/csv.h>

namespace
{
using vrrw_common::runCapturing;  // a tool run as a user runs it: its status and output

const std::vector<std::string> kArm = { "ur5e_shoulder_pan_joint", "ur5e_shoulder_lift_joint", "ur5e_elbow_joint",
                                        "ur5e_wrist_1_joint",      "ur5e_wrist_2_joint",       "ur5e_wrist_3_joint" };

std::vector<double> arm()
{
  const auto state = ros::topic::waitForMessage<sensor_msgs::JointState>("/ur5e/joint_states", ros::Duration(10.0));
  EXPECT_TRUE(state);
  return state ? *vrrw_common::findValues(state->name, state->position, kArm) : std::vector<double>(6, NAN);
}
}  // namespace

TEST(PlanTool, APresetsPlanIsSummarisedKeptAndSent)
{
  char folder[] = "/tmp/vrrw_plan_tool_XXXXXX";
  const std::string csv = std::string(::mkdtemp(folder)) + "/square_left.csv";
  const auto plan = runCapturing({ VRRW_PLAN_TOOL, "ur5e", "--preset", "square_left", "--seed", "2", "--out", csv });
  ASSERT_EQ(plan.status, 0) << plan.output;
  std::smatch m;
  const std::regex summary("planned in ([0-9.e-]+) s: ([0-9]+) points over ([0-9.e-]+) s, max joint speed ([0-9.e-]+) "
                           "rad/s \\((ur5e_[a-z_0-9]+)\\), path length ([0-9.e-]+) rad\n");
  ASSERT_TRUE(std::regex_search(plan.output, m, summary)) << plan.output;
  const std::size_t points = std::stoul(m[2]);
  const double duration = std::stod(m[3]), speed = std::stod(m[4]);
  std::cout << "square_left: " << points << " points over " << duration << " s, max " << speed << " rad/s" << std::endl;
  EXPECT_GT(points, 2u);
  EXPECT_GT(duration, 0.1);
  EXPECT_GT(speed, 0.05);
  EXPECT_LE(speed, 3.1416 * 1.001);  // the UR5e's URDF velocity limits (pi rad/s)
  EXPECT_NE(plan.output.find("written: " + csv + " (./vrrw send ur5e --csv " + csv + " executes it)"),
            std::string::npos) << plan.output;
  const auto kept = vrrw_trajectory::readCsv(csv);
  EXPECT_EQ(kept.points.size(), points);
  EXPECT_NEAR(kept.points.back().time - kept.points.front().time, duration, 1e-3);

  const auto send = runCapturing({ VRRW_ARM_TOOL, "send", "ur5e", "--csv", csv });
  EXPECT_EQ(send.status, 0) << send.output;
  ros::WallDuration(0.2).sleep();
  const auto q = arm();
  const double h = 1.5707963267948966;
  const std::vector<double> square_left = { 0.7853981633974483, -h, h, -h, -h, 0 };  // urdf/config/presets.yaml
  for (std::size_t j = 0; j < 6; ++j)
    EXPECT_NEAR(q[j], square_left[j], 1e-6) << kArm[j];
}

TEST(PlanTool, MistakesAreOneLine)
{
  auto r = runCapturing({ VRRW_PLAN_TOOL, "ur5e", "--preset", "dance" });
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.output.find("vrrw_plan: "), std::string::npos);
  EXPECT_NE(r.output.find("dance"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("square_left"), std::string::npos) << r.output;  // the known ones are named
  EXPECT_EQ(r.output.find('\n'), r.output.size() - 1) << r.output;
  r = runCapturing({ VRRW_PLAN_TOOL, "ur5e", "--out", "/tmp", "--preset", "home" });
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.output.rfind("vrrw_plan: --out: /tmp: exists; not overwritten\n", 0), 0u) << r.output;
  r = runCapturing({ VRRW_PLAN_TOOL, "ur5e", "--joints", "0,0,0" });
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.output.rfind("vrrw_plan: --joints: 3 values, expected 6\n", 0), 0u) << r.output;
  r = runCapturing({ VRRW_PLAN_TOOL, "ur5e", "--preset", "home", "--joints", "0,0,0,0,0,0" });
  EXPECT_EQ(r.output.rfind("vrrw_plan: --joints and --preset exclude each other\n", 0), 0u) << r.output;
}

int main(int argc, char** argv)
{
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_plan_tool");
  ros::NodeHandle node;
  if (!ros::service::waitForService("/ur5e/plan", ros::Duration(60.0)) || arm().size() != 6)
    return 1;
  return RUN_ALL_TESTS();
}

// bagInstructions and bagTrack on bags written here: both annotation forms, and the bad bags a user can hand it.
#include <gtest/gtest.h>

#include <control_msgs/GripperCommandActionGoal.h>
#include <cstdio>
#include <fstream>
#include <rosbag/bag.h>
#include <sensor_msgs/JointState.h>
#include <stdexcept>
#include <vrrw_msgs/Event.h>

#include "../src/ros/bag_instructions.h"

using vrrw_evaluation::bagInstructions;

namespace
{
struct Written
{
  double t;
  std::string kind, detail;
};

std::string writeBag(const std::string& name, const std::vector<Written>& events)
{
  const std::string file = testing::TempDir() + name;
  std::remove(file.c_str());
  rosbag::Bag bag(file, rosbag::bagmode::Write);
  for (const Written& w : events)
  {
    vrrw_msgs::Event e;
    e.header.stamp = ros::Time(100.0 + w.t);
    e.kind = w.kind;
    e.detail = w.detail;
    bag.write("/demos/events", e.header.stamp, e);
  }
  return file;
}

void expectSegment(const vrrw_evaluation::Segment& segment, const std::string& name, double start, double end)
{
  EXPECT_EQ(segment.name, name);
  EXPECT_NEAR(segment.start, start, 1e-6) << name;
  EXPECT_NEAR(segment.end, end, 1e-6) << name;
}

std::string failure(const std::string& bag)
{
  try
  {
    bagInstructions(bag, 100.0);
  }
  catch (const std::runtime_error& e)
  {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(BagInstructions, BothAnnotationFormsGiveTheSegmentsFromTheRecordingStart)
{
  const std::string runner = writeBag("runner.bag", { { 0.5, "instruction_start", "move_to_near_pick" },
                                                      { 2.0, "grab", "hand right grabbed ur5e_wrist_3_link" },
                                                      { 2.5, "instruction_end", "move_to_near_pick" },
                                                      { 2.7, "instruction_start", "move_to_pick" },
                                                      { 4.0, "instruction_failed", "move_to_pick" } });
  const auto segments = bagInstructions(runner, 100.0);
  ASSERT_EQ(segments.size(), 2u);
  expectSegment(segments[0], "move_to_near_pick", 0.5, 2.5);
  expectSegment(segments[1], "move_to_pick", 2.7, 4.0);

  const std::string recorder = writeBag("recorder.bag", { { 1.0, "annotate", "instruction_start close_gripper" },
                                                          { 1.25, "annotate", "drill grasped" },
                                                          { 1.5, "annotate", "instruction_end close_gripper" } });
  const auto annotated = bagInstructions(recorder, 100.0);
  ASSERT_EQ(annotated.size(), 1u);
  expectSegment(annotated[0], "close_gripper", 1.0, 1.5);
}

TEST(BagInstructions, BadBagsAreOneLineNamingTheBag)
{
  const std::string unended = writeBag("unended.bag", { { 0.5, "instruction_start", "move_to_near_pick" } });
  EXPECT_NE(failure(unended).find("unended.bag: /demos/events: move_to_near_pick has no end"), std::string::npos)
      << failure(unended);
  const std::string overlapping = writeBag("overlap.bag", { { 0.5, "instruction_start", "move_to_near_pick" },
                                                            { 1.0, "instruction_start", "move_to_pick" } });
  EXPECT_NE(failure(overlapping).find("move_to_near_pick has no end before move_to_pick"), std::string::npos)
      << failure(overlapping);
  const std::string orphan = writeBag("orphan.bag", { { 0.5, "instruction_end", "move_to_pick" } });
  EXPECT_NE(failure(orphan).find("the end of move_to_pick without its start"), std::string::npos) << failure(orphan);

  EXPECT_NE(failure("/nonexistent/demo.bag").find("/nonexistent/demo.bag: "), std::string::npos);
  const std::string garbage = testing::TempDir() + "garbage.bag";
  std::ofstream(garbage) << "not a bag";
  EXPECT_NE(failure(garbage).find("garbage.bag: "), std::string::npos) << failure(garbage);
  EXPECT_TRUE(bagInstructions(writeBag("empty.bag", {}), 100.0).empty());
}

int main(int argc, char** argv)
{
  testing::InitGoogleTest(&argc, argv);
  ros::Time::init();
  return RUN_ALL_TESTS();
}

TEST(BagTrack, TheArmJointsInOrderAndTheGripperGoalsFromTheRecordingStart)
{
  const std::string file = testing::TempDir() + "track.bag";
  std::remove(file.c_str());
  {
    rosbag::Bag bag(file, rosbag::bagmode::Write);
    for (int k = 0; k < 5; ++k)
    {
      sensor_msgs::JointState state;  // names in another order than the arm's, a gripper joint among them
      state.header.stamp = ros::Time(100.0 + 0.1 * k);
      state.name = { "r_b", "r_finger", "r_a" };
      state.position = { 2.0 + k, 0.5, 1.0 + k };
      bag.write("/r/joint_states", state.header.stamp, state);
      if (k == 2)  // a stamp already seen: kept once
        bag.write("/r/joint_states", state.header.stamp, state);
    }
    control_msgs::GripperCommandActionGoal close, open;
    close.goal.command.position = 0.8, close.goal.command.max_effort = 70.0;
    bag.write("/r/gripper_controller/gripper_cmd/goal", ros::Time(100.2), close);
    bag.write("/r/gripper_controller/gripper_cmd/goal", ros::Time(100.4), open);
  }
  const auto track = vrrw_evaluation::bagTrack(file, "r", { "r_a", "r_b" }, 100.0);
  ASSERT_EQ(track.arm.points.size(), 5u);
  EXPECT_NEAR(track.arm.points[3].time, 0.3, 1e-6);
  EXPECT_EQ(track.arm.points[3].positions, (std::vector<double>{ 4.0, 5.0 }));
  ASSERT_EQ(track.gripper_goals.size(), 2u);
  EXPECT_EQ(track.gripper_goals[0], std::make_pair(0.8, 70.0));
  EXPECT_EQ(track.gripper_goals[1], std::make_pair(0.0, 0.0));
  try
  {
    vrrw_evaluation::bagTrack(file, "other", { "other_a" }, 100.0);
    FAIL() << "a robot that is not in the bag";
  }
  catch (const std::runtime_error& e)
  {
    EXPECT_EQ(std::string(e.what()), file + ": /other/joint_states: no recorded states of other's arm");
  }
}

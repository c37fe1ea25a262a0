// annotatedInstructions on demonstrations as vrrw_demos reads them: both annotation forms, and the bad ones.
#include <gtest/gtest.h>

#include <stdexcept>

#include <vrrw_evaluation/annotations.h>

using vrrw_evaluation::annotatedInstructions;

namespace
{
vrrw_demos::Demonstration withEvents(const std::vector<vrrw_demos::DemoEvent>& events)
{
  vrrw_demos::Demonstration demo;
  demo.source = "demo.bag";
  demo.events = events;
  return demo;
}

void expectSegment(const vrrw_demos::Segment& segment, const std::string& name, double start, double end)
{
  EXPECT_EQ(segment.name, name);
  EXPECT_NEAR(segment.start, start, 1e-9) << name;
  EXPECT_NEAR(segment.end, end, 1e-9) << name;
}

std::string failure(const std::vector<vrrw_demos::DemoEvent>& events)
{
  try
  {
    annotatedInstructions(withEvents(events));
  }
  catch (const std::runtime_error& e)
  {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(Annotations, BothAnnotationFormsGiveTheInstructions)
{
  const auto runner = annotatedInstructions(withEvents({ { 0.5, "", "instruction_start", "move_to_near_pick" },
                                                         { 2.0, "ur5e", "grab", "hand right grabbed ur5e_wrist_3_link" },
                                                         { 2.5, "", "instruction_end", "move_to_near_pick" },
                                                         { 2.7, "", "instruction_start", "close_gripper" },
                                                         { 4.0, "", "instruction_failed", "close_gripper" } }));
  ASSERT_EQ(runner.size(), 2u);
  expectSegment(runner[0], "move_to_near_pick", 0.5, 2.5);
  expectSegment(runner[1], "close_gripper", 2.7, 4.0);
  EXPECT_FALSE(runner[0].gripper);
  EXPECT_TRUE(runner[1].gripper);
  const auto recorder = annotatedInstructions(withEvents({ { 1.0, "", "annotate", "instruction_start close_gripper" },
                                                           { 1.25, "", "annotate", "drill grasped" },
                                                           { 1.5, "", "annotate", "instruction_end close_gripper" } }));
  ASSERT_EQ(recorder.size(), 1u);
  expectSegment(recorder[0], "close_gripper", 1.0, 1.5);
  EXPECT_TRUE(annotatedInstructions(withEvents({})).empty());
}

TEST(Annotations, BadAnnotationsAreOneLineNamingTheBag)
{
  EXPECT_EQ(failure({ { 0.5, "", "instruction_start", "move_to_near_pick" } }),
            "demo.bag: /demos/events: move_to_near_pick has no end");
  EXPECT_EQ(failure({ { 0.5, "", "instruction_start", "move_to_near_pick" }, { 1.0, "", "instruction_start", "move_to_pick" } }),
            "demo.bag: /demos/events: move_to_near_pick has no end before move_to_pick");
  EXPECT_EQ(failure({ { 0.5, "", "instruction_end", "move_to_pick" } }),
            "demo.bag: /demos/events: the end of move_to_pick without its start");
}

#include <vrrw_physics/report_throttle.h>

#include <gtest/gtest.h>

using vrrw_physics::ReportThrottle;

TEST(ReportThrottle, OneLinePerKindAndSecondThatCountsTheRest)
{
  ReportThrottle throttle(1.0);
  EXPECT_EQ(throttle.admit("/ur5e/drive_targets", "joint 'a' position: 90 outside [-3, 3]", 0.0),
            "joint 'a' position: 90 outside [-3, 3]");
  int passed = 0;
  for (int i = 1; i < 1000; ++i)  // 999 more at 1 kHz, each with other numbers
    passed += !throttle.admit("/ur5e/drive_targets", "joint 'a' position: " + std::to_string(90 + i) +
                                                         " outside [-3, 3]", i * 1e-3).empty();
  EXPECT_EQ(passed, 0);
  // Another kind of message from the same source, and the same kind from another source, pass at once.
  EXPECT_FALSE(throttle.admit("/ur5e/drive_targets", "joint 'a' position is not finite", 0.5).empty());
  EXPECT_FALSE(throttle.admit("/ur3e/drive_targets", "joint 'a' position: 1 outside [-3, 3]", 0.5).empty());
  EXPECT_EQ(throttle.admit("/ur5e/drive_targets", "joint 'a' position: 7 outside [-3, 3]", 1.0),
            "joint 'a' position: 7 outside [-3, 3] (999 more like it held back)");
  EXPECT_TRUE(throttle.admit("/ur5e/drive_targets", "joint 'a' position: 8 outside [-3, 3]", 1.5).empty());
  // Time that runs backwards (a reset of simulated time) does not hold a report back.
  EXPECT_FALSE(throttle.admit("/ur5e/drive_targets", "joint 'a' position: 9 outside [-3, 3]", 0.2).empty());
}

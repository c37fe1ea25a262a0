#include <vrrw_physics/realtime_pacer.h>

#include <gtest/gtest.h>

using vrrw_physics::RealtimePacer;

TEST(RealtimePacer, WaitsUntilTheWallClockCatchesUpAndRestartsWhenFarBehind)
{
  using std::chrono::milliseconds;
  RealtimePacer pacer(0.1);
  const RealtimePacer::Clock::time_point t0{};
  pacer.restart(5.0, t0);
  EXPECT_NEAR(pacer.wait(5.010, t0 + milliseconds(4)), 0.006, 1e-9);  // ahead: wait the difference
  EXPECT_EQ(pacer.wait(5.020, t0 + milliseconds(50)), 0.0);           // behind by 30 ms: no wait, no catch-up
  EXPECT_EQ(pacer.wait(5.021, t0 + milliseconds(500)), 0.0);          // behind by 479 ms: a new reference
  EXPECT_NEAR(pacer.wait(5.031, t0 + milliseconds(500)), 0.010, 1e-9);  // paced from there, not racing
}

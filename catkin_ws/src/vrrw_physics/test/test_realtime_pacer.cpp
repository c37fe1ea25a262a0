#include <vrrw_physics/realtime_pacer.h>

#include <gtest/gtest.h>

#include <cmath>

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

TEST(RealtimePacer, RunsAtItsRealTimeFactorOrNeverWaitsAtMax)
{
  using std::chrono::milliseconds;
  const RealtimePacer::Clock::time_point t0{};
  RealtimePacer ten(0.1, 10.0);
  ten.restart(0.0, t0);
  EXPECT_NEAR(ten.wait(0.1, t0 + milliseconds(4)), 0.006, 1e-9);  // 0.1 simulated s take 10 ms
  RealtimePacer max(0.1, vrrw_physics::parseRealTimeFactor("max", "--rtf"));
  max.restart(0.0, t0);
  EXPECT_EQ(max.wait(100.0, t0), 0.0);
}

TEST(RealtimePacer, StepsInBurstsOfMinWaitThenWaitsOnce)
{
  using std::chrono::microseconds;
  const RealtimePacer::Clock::time_point t0{};
  RealtimePacer pacer(0.1, 1.0, 0.005);
  pacer.restart(0.0, t0);
  // 1 ms steps that take 0.1 ms each: no wait until the simulation leads by 5 ms, then one wait for all of it
  int steps = 0;
  double sim = 0.0, waited = 0.0;
  auto now = t0;
  for (; waited == 0.0; ++steps)
  {
    sim += 0.001;
    now += microseconds(100);
    waited = pacer.wait(sim, now);
  }
  EXPECT_EQ(steps, 6);
  EXPECT_NEAR(waited, 0.006 - 0.0006, 1e-9);
  // after the wait the simulation is where the wall clock is: the next 5 steps go on at once again
  now += std::chrono::duration_cast<RealtimePacer::Clock::duration>(std::chrono::duration<double>(waited));
  EXPECT_EQ(pacer.wait(sim + 0.001, now + microseconds(100)), 0.0);
}

TEST(RealtimePacer, RealTimeFactorsAreMaxOrPositiveNumbers)
{
  EXPECT_TRUE(std::isinf(vrrw_physics::parseRealTimeFactor("max", "--rtf")));
  EXPECT_EQ(vrrw_physics::parseRealTimeFactor("2.5", "--rtf"), 2.5);
  for (const char* bad : { "0", "-1", "nan", "inf", "fast", "", "2x" })
  {
    try
    {
      vrrw_physics::parseRealTimeFactor(bad, "~rtf");
      ADD_FAILURE() << bad << " accepted";
    }
    catch (const std::invalid_argument& e)
    {
      EXPECT_EQ(std::string(e.what()),
                std::string("~rtf: '") + bad + "' is not max or a positive number (the real-time factor)");
    }
  }
}

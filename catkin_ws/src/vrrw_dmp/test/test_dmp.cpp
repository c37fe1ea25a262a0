#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <iostream>
#include <new>

#include <vrrw_dmp/dmp.h>
#include <vrrw_dmp/dmp_error.h>

#include "demo_fixture.h"

using vrrw_dmp::AmplitudeScaling;
using vrrw_dmp::Dmp;
using vrrw_dmp::DmpParameters;
using vrrw_dmp::RolloutRequest;
using vrrw_dmp_test::errorOf;
using vrrw_dmp_test::rmse;
using vrrw_dmp_test::sample;
using vrrw_dmp_test::SmoothDemo;

namespace
{
std::atomic<long> allocations{ 0 };
}  // namespace

// Counts heap allocations so that the test can prove step() makes none.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void* operator new(std::size_t size)
{
  ++allocations;
  if (void* p = std::malloc(size == 0 ? 1 : size))
    return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept
{
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept
{
  std::free(p);
}
#pragma GCC diagnostic pop

namespace
{
RolloutRequest fineRollout(double dt = 0.002)
{
  RolloutRequest request;
  request.dt = dt;
  return request;
}
}  // namespace

TEST(Dmp, ReproducesSmoothDemoWith50Basis)
{
  const SmoothDemo demo;
  const Dmp dmp = Dmp::learn(sample(demo, 500, 0.3), DmpParameters{});
  EXPECT_TRUE(dmp.warnings().empty());
  const auto rollout = dmp.rollout(fineRollout());
  for (std::size_t j = 0; j < 6; ++j)
  {
    const double error = rmse(demo, rollout, j);
    EXPECT_LT(error, 1e-2) << "joint " << j;
    RecordProperty("rmse_joint_" + std::to_string(j + 1), std::to_string(error));
  }
}

TEST(Dmp, CoarseControlRateStaysAccurate)
{
  const SmoothDemo demo;
  const Dmp dmp = Dmp::learn(sample(demo, 500, 0.3), DmpParameters{});
  const auto fine = dmp.rollout(fineRollout(0.001));
  const auto coarse = dmp.rollout(fineRollout(0.04));
  for (std::size_t k = 0; k < coarse.points.size() && k * 40 < fine.points.size(); ++k)
    for (std::size_t j = 0; j < 6; ++j)
      EXPECT_NEAR(coarse.points[k].positions[j], fine.points[k * 40].positions[j], 1e-3);
}

TEST(Dmp, ConvergesToNewStartAndGoal)
{
  const SmoothDemo demo;
  const Dmp dmp = Dmp::learn(sample(demo, 500, 0.3), DmpParameters{});
  RolloutRequest request = fineRollout(0.008);
  request.start = { 0.1, -0.2, 0.0, 0.3, -0.1, 0.2 };
  request.goal = { -0.5, 1.2, 0.4, -1.0, 0.9, 0.1 };
  const auto rollout = dmp.rollout(request);
  EXPECT_EQ(rollout.points.front().positions, request.start);
  for (std::size_t j = 0; j < 6; ++j)
  {
    EXPECT_NEAR(rollout.points.back().positions[j], request.goal[j], request.goal_tolerance);
    EXPECT_NEAR(rollout.points.back().velocities[j], 0.0, request.rest_speed);
  }
  EXPECT_GE(rollout.duration(), demo.T);
  EXPECT_LE(rollout.duration(), 4 * demo.T);
}

TEST(Dmp, ASlowDemonstrationEndsSoonAfterTau)
{
  // a person's 23 s segment: with a 1e-4 rad goal tolerance its rollout crept on to 64 s (here 2.6 tau before)
  SmoothDemo demo;
  demo.T = 23.0;
  const Dmp dmp = Dmp::learn(sample(demo, 1400, 0.3, 2e-5), DmpParameters{});
  RolloutRequest request = fineRollout(0.01);
  request.goal = dmp.demoGoal();
  for (double& q : request.goal)
    q += 0.1;
  const auto rollout = dmp.rollout(request);
  RecordProperty("duration_s", std::to_string(rollout.duration()));
  EXPECT_LE(rollout.duration(), 1.1 * demo.T);
  for (std::size_t j = 0; j < 6; ++j)
    EXPECT_NEAR(rollout.points.back().positions[j], request.goal[j], request.goal_tolerance);
}

TEST(Dmp, NewGoalScalesThePathAffinely)
{
  const SmoothDemo demo;
  const Dmp dmp = Dmp::learn(sample(demo, 500, 0.3), DmpParameters{});
  const auto original = dmp.rollout(fineRollout());
  RolloutRequest request = fineRollout();
  request.goal = dmp.demoGoal();
  for (std::size_t j = 0; j < 6; ++j)
    request.goal[j] = dmp.demoStart()[j] + 2.0 * (dmp.demoGoal()[j] - dmp.demoStart()[j]);
  const auto scaled = dmp.rollout(request);
  for (std::size_t k = 0; k < std::min(original.points.size(), scaled.points.size()); k += 50)
    for (std::size_t j = 0; j < 6; ++j)
      EXPECT_NEAR(scaled.points[k].positions[j] - dmp.demoStart()[j],
                  2.0 * (original.points[k].positions[j] - dmp.demoStart()[j]), 1e-9);
}

TEST(Dmp, DoublingTauDoublesDurationAndKeepsPath)
{
  const SmoothDemo demo;
  const Dmp dmp = Dmp::learn(sample(demo, 500, 0.3), DmpParameters{});
  RolloutRequest normal = fineRollout(0.004);
  RolloutRequest slow = fineRollout(0.008);
  slow.tau = 2.0 * dmp.demoDuration();
  const auto a = dmp.rollout(normal);
  const auto b = dmp.rollout(slow);
  ASSERT_EQ(a.points.size(), b.points.size());
  EXPECT_NEAR(b.duration(), 2.0 * a.duration(), 1e-9);
  for (std::size_t k = 0; k < a.points.size(); ++k)
    for (std::size_t j = 0; j < 6; ++j)
    {
      EXPECT_NEAR(b.points[k].positions[j], a.points[k].positions[j], 1e-12);
      EXPECT_NEAR(b.points[k].velocities[j], 0.5 * a.points[k].velocities[j], 1e-12);
    }
  // the slow motion sampled twice as finely: the same path up to the integrator's discretisation
  // error between the two step lengths (second order in the forcing term's linear hold)
  RolloutRequest slow_fine = fineRollout(0.004);
  slow_fine.tau = slow.tau;
  const auto c = dmp.rollout(slow_fine);
  for (std::size_t k = 0; k < a.points.size(); k += 25)
    for (std::size_t j = 0; j < 6; ++j)
      EXPECT_NEAR(c.points[2 * k].positions[j], a.points[k].positions[j], 1e-5);
}

TEST(Dmp, LearnsFromStronglyNonUniformSampling)
{
  const SmoothDemo demo;
  const auto dense_then_sparse = sample(demo, 300, 0.4, 0.0, 8.0);
  const double first_step = dense_then_sparse.points[1].time - dense_then_sparse.points[0].time;
  const double last_step = dense_then_sparse.duration() - dense_then_sparse.points[298].time;
  EXPECT_GT(last_step / first_step, 5.0);
  const auto rollout = Dmp::learn(dense_then_sparse, DmpParameters{}).rollout(fineRollout());
  for (std::size_t j = 0; j < 6; ++j)
    EXPECT_LT(rmse(demo, rollout, j), 1e-2) << "joint " << j;
}

TEST(Dmp, LearnsFromJitteryNoisyRecording)
{
  const SmoothDemo demo;
  const auto recording = sample(demo, 120, 0.45, 2e-4);  // ~60 Hz render rate, 0.2 mrad noise
  const auto rollout = Dmp::learn(recording, DmpParameters{}).rollout(fineRollout());
  for (std::size_t j = 0; j < 6; ++j)
    EXPECT_LT(rmse(demo, rollout, j), 1e-2) << "joint " << j;
}

TEST(Dmp, GoalEqualToStartWarnsAndAmplitudeScalingReproduces)
{
  auto demo = sample(SmoothDemo{}, 400, 0.2);
  for (auto& point : demo.points)  // joint 3 goes out and comes back
    point.positions[2] = 0.4 + 0.6 * std::pow(std::sin(M_PI * point.time / 2.0), 2);
  const Dmp paper = Dmp::learn(demo, DmpParameters{});
  ASSERT_EQ(paper.warnings().size(), 1u);
  EXPECT_NE(paper.warnings()[0].find("joint 'joint_3': g - x0 = 0 "), std::string::npos) << paper.warnings()[0];
  EXPECT_NE(paper.warnings()[0].find("scaling 'auto' or 'amplitude'"), std::string::npos);
  auto errorOfJoint3 = [&](const Dmp& dmp) {
    const auto rollout = dmp.rollout(fineRollout());
    double worst = 0.0;
    for (const auto& point : rollout.points)
      if (point.time <= 2.0)
        worst = std::max(worst, std::abs(point.positions[2] -
                                         (0.4 + 0.6 * std::pow(std::sin(M_PI * point.time / 2.0), 2))));
    return worst;
  };
  EXPECT_GT(errorOfJoint3(paper), 0.5);  // the paper's formulation loses the motion

  DmpParameters remedy;
  remedy.scaling = AmplitudeScaling::automatic;
  const Dmp fixed = Dmp::learn(demo, remedy);
  EXPECT_EQ(fixed.jointScaling()[2], AmplitudeScaling::demo_amplitude);
  EXPECT_EQ(fixed.jointScaling()[0], AmplitudeScaling::goal_offset);
  ASSERT_EQ(fixed.warnings().size(), 1u);
  EXPECT_LT(errorOfJoint3(fixed), 1e-2);

  RolloutRequest elsewhere = fineRollout();
  elsewhere.start = fixed.demoStart();
  elsewhere.goal = fixed.demoGoal();
  elsewhere.start[2] = elsewhere.goal[2] = -0.2;
  const auto moved = fixed.rollout(elsewhere);
  double peak = -1.0;
  for (const auto& point : moved.points)
    peak = std::max(peak, point.positions[2]);
  EXPECT_NEAR(peak, 0.4, 1e-2);  // the same 0.6 rad excursion around the new start
  EXPECT_NEAR(moved.points.back().positions[2], -0.2, 1e-3);
}

TEST(Dmp, PlanWarnsWhenTheNewGoalEqualsTheNewStart)
{
  const Dmp dmp = Dmp::learn(sample(SmoothDemo{}, 400, 0.2), DmpParameters{});
  ASSERT_TRUE(dmp.warnings().empty());
  EXPECT_TRUE(dmp.planWarnings(RolloutRequest{}).empty());
  const auto& x0 = dmp.demoStart();
  const auto& range = dmp.demoAmplitude();
  const double ratio = dmp.parameters().degenerate_ratio;
  RolloutRequest request = fineRollout();
  request.start = x0;
  request.goal = dmp.demoGoal();
  request.goal[1] = x0[1];                               // g == x0 exactly
  request.goal[3] = x0[3] + 0.99 * ratio * range[3];     // just inside the tolerance
  request.goal[4] = x0[4] - 1.01 * ratio * range[4];     // just outside, same sign as the demo (factor > 0)
  ASSERT_LT(dmp.demoGoal()[4] - x0[4], 0.0);
  const auto warnings = dmp.planWarnings(request);
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_EQ(warnings[0].find("joint 'joint_2': new g - x0 = 0 is within 5% of the demonstrated range "), 0u)
      << warnings[0];
  EXPECT_NE(warnings[0].find("learn with --scaling amplitude"), std::string::npos) << warnings[0];
  EXPECT_EQ(warnings[1].find("joint 'joint_4': new g - x0 = "), 0u) << warnings[1];

  // the warning is true: joint 2 moves straight to its goal (here: not at all), the demonstration did not
  const auto rollout = dmp.rollout(request);
  double excursion = 0.0;
  for (const auto& point : rollout.points)
    excursion = std::max(excursion, std::abs(point.positions[1] - x0[1]));
  EXPECT_EQ(excursion, 0.0);
  EXPECT_GT(range[1], 0.1);

  // amplitude scaling keeps the shape: nothing to warn about
  DmpParameters amplitude;
  amplitude.scaling = AmplitudeScaling::demo_amplitude;
  EXPECT_TRUE(Dmp::learn(sample(SmoothDemo{}, 400, 0.2), amplitude).planWarnings(request).empty());

  RolloutRequest wrong;
  wrong.goal = { 1.0 };
  EXPECT_EQ(errorOf([&] { dmp.planWarnings(wrong); }), "goal: 1 values for 6 joints");
}

TEST(Dmp, AJointThatHardlyMovesIsNotStretchedToANewGoalWithAStillRange)
{
  // Joint 3 drifts 3 mrad, wobbling on the way (as a wrist does while the arm carries); a new goal 80 mrad
  // away in the other direction would scale that wobble by -27 with the paper's g - x0.
  auto demo = sample(SmoothDemo{}, 400, 0.0);
  for (auto& point : demo.points)
    point.positions[2] = 0.4 - 0.003 * point.time / 2.0 + 0.002 * std::sin(M_PI * point.time);
  RolloutRequest elsewhere = fineRollout();
  auto excursion = [&](const Dmp& dmp) {
    elsewhere.start = dmp.demoStart();
    elsewhere.goal = dmp.demoGoal();
    elsewhere.goal[2] = elsewhere.start[2] + 0.08;
    double worst = 0.0;
    for (const auto& point : dmp.rollout(elsewhere).points)  // outside [start, goal]
      worst = std::max({ worst, elsewhere.start[2] - point.positions[2], point.positions[2] - elsewhere.goal[2] });
    return worst;
  };
  DmpParameters automatic;
  automatic.scaling = AmplitudeScaling::automatic;
  EXPECT_EQ(automatic.still_range, 0.02);  // on by default (20 mrad); off here to show what it prevents
  automatic.still_range = 0.0;
  const Dmp stretched = Dmp::learn(demo, automatic);
  EXPECT_EQ(stretched.jointScaling()[2], AmplitudeScaling::goal_offset);
  automatic.still_range = 0.01;
  const Dmp kept = Dmp::learn(demo, automatic);
  EXPECT_EQ(kept.jointScaling()[2], AmplitudeScaling::demo_amplitude);
  EXPECT_EQ(kept.jointScaling()[0], AmplitudeScaling::goal_offset);
  std::cout << "joint 3 outside [start, goal]: " << excursion(stretched) << " rad stretched, " << excursion(kept)
            << " rad with a still range\n";
  EXPECT_GT(excursion(stretched), 0.02);
  EXPECT_LT(excursion(kept), 0.003);
  EXPECT_THROW(
      {
        DmpParameters bad;
        bad.still_range = -1.0;
        bad.validate();
      },
      vrrw_dmp::DmpError);
}

TEST(Dmp, PlanWarnsWhenTheGoalScalingMirrorsOrAmplifiesTheShape)
{
  const Dmp dmp = Dmp::learn(sample(SmoothDemo{}, 400, 0.2), DmpParameters{});
  RolloutRequest request = fineRollout();
  request.start = dmp.demoStart();
  for (double& q : request.start)
    q += 0.1;
  const std::vector<double> factors = { -0.5, 3.5, 3.0, -4.0, 1.0, 2.9 };
  request.goal.resize(6);
  for (std::size_t j = 0; j < 6; ++j)
    request.goal[j] = request.start[j] + factors[j] * (dmp.demoGoal()[j] - dmp.demoStart()[j]);
  const auto warnings = dmp.planWarnings(request);
  ASSERT_EQ(warnings.size(), 3u);
  EXPECT_EQ(warnings[0].find("joint 'joint_1': goal scaling factor (g - x0)/(g_demo - x0_demo) = -0.5 mirrors the "
                             "demonstrated shape"),
            0u)
      << warnings[0];
  EXPECT_EQ(warnings[1].find("joint 'joint_2': goal scaling factor (g - x0)/(g_demo - x0_demo) = 3.5 amplifies"), 0u)
      << warnings[1];
  EXPECT_EQ(warnings[2].find("joint 'joint_4': goal scaling factor (g - x0)/(g_demo - x0_demo) = -4 mirrors and "
                             "amplifies"),
            0u)
      << warnings[2];

  // the factor is what the rollout does: joint 2's path is the demonstrated one stretched 3.5 times
  const auto original = dmp.rollout(fineRollout());
  const auto scaled = dmp.rollout(request);
  for (std::size_t k = 0; k < std::min(original.points.size(), scaled.points.size()); k += 50)
    EXPECT_NEAR(scaled.points[k].positions[1] - request.start[1],
                3.5 * (original.points[k].positions[1] - dmp.demoStart()[1]), 1e-9);
}

TEST(Dmp, PlanDoesNotRepeatLearnTimeWarnings)
{
  auto demo = sample(SmoothDemo{}, 400, 0.2);
  for (auto& point : demo.points)  // joint 3 goes out and comes back: learn() already warns
    point.positions[2] = 0.4 + 0.6 * std::pow(std::sin(M_PI * point.time / 2.0), 2);
  const Dmp dmp = Dmp::learn(demo, DmpParameters{});
  ASSERT_EQ(dmp.warnings().size(), 1u);
  RolloutRequest request;
  request.start = dmp.demoStart();
  request.goal = dmp.demoGoal();
  request.goal[2] += 0.5;
  EXPECT_TRUE(dmp.planWarnings(request).empty());
}

TEST(Dmp, StepIsAllocationFreeAndMatchesRollout)
{
  const Dmp dmp = Dmp::learn(sample(SmoothDemo{}, 200, 0.2), DmpParameters{});
  const auto rollout = dmp.rollout(fineRollout(0.01));
  vrrw_dmp::DmpState state = dmp.begin(dmp.demoStart(), dmp.demoGoal(), dmp.demoDuration());
  const long before = allocations.load();
  for (int k = 0; k < 150; ++k)
    dmp.step(state, 0.01);
  EXPECT_EQ(allocations.load() - before, 0);
  for (std::size_t j = 0; j < 6; ++j)
  {
    EXPECT_EQ(state.positions[j], rollout.points[150].positions[j]);
    EXPECT_EQ(state.velocities[j], rollout.points[150].velocities[j]);
    EXPECT_EQ(state.accelerations[j], rollout.points[150].accelerations[j]);
  }
}

TEST(Dmp, BadDemonstrationsAreNamed)
{
  const DmpParameters p;
  auto demo = sample(SmoothDemo{}, 10, 0.0, 0.0, 1.0, 2);
  vrrw_trajectory::JointTrajectory empty;
  empty.joint_names = demo.joint_names;
  EXPECT_EQ(errorOf([&] { Dmp::learn(empty, p); }), "demo: 0 sample(s), learning needs at least 3");
  auto one = empty;
  one.points.push_back(demo.points[0]);
  EXPECT_EQ(errorOf([&] { Dmp::learn(one, p); }), "demo: 1 sample(s), learning needs at least 3");
  auto nan = demo;
  nan.points[4].positions[1] = std::nan("");
  EXPECT_EQ(errorOf([&] { Dmp::learn(nan, p); }), "demo: sample 4: joint 'joint_2' position is not finite");
  auto backwards = demo;
  backwards.points[5].time = backwards.points[4].time;
  EXPECT_NE(errorOf([&] { Dmp::learn(backwards, p); }).find("demo: sample 5: time"), std::string::npos);
  auto short_row = demo;
  short_row.points[3].positions.pop_back();
  EXPECT_EQ(errorOf([&] { Dmp::learn(short_row, p); }), "demo: sample 3: 1 positions for 2 joints");
  auto nameless = demo;
  nameless.joint_names.clear();
  EXPECT_EQ(errorOf([&] { Dmp::learn(nameless, p); }), "demo: no joints");
}

TEST(Dmp, BadParametersAreNamed)
{
  const auto demo = sample(SmoothDemo{}, 20, 0.0, 0.0, 1.0, 2);
  DmpParameters p;
  p.basis_count = 0;
  EXPECT_EQ(errorOf([&] { Dmp::learn(demo, p); }), "basis count N = 0: need at least one basis function");
  p = DmpParameters{};
  p.K = -5.0;
  EXPECT_EQ(errorOf([&] { Dmp::learn(demo, p); }), "K = -5: must be a finite number > 0");
  p = DmpParameters{};
  p.alpha = 0.0;
  EXPECT_NE(errorOf([&] { Dmp::learn(demo, p); }).find("alpha = 0"), std::string::npos);
  p = DmpParameters{};
  p.D = -1.0;
  EXPECT_NE(errorOf([&] { Dmp::learn(demo, p); }).find("D = -1"), std::string::npos);
}

TEST(Dmp, BadRolloutRequestsAreNamed)
{
  const Dmp dmp = Dmp::learn(sample(SmoothDemo{}, 20, 0.0, 0.0, 1.0, 2), DmpParameters{});
  RolloutRequest r;
  r.tau = -1.0;
  EXPECT_EQ(errorOf([&] { dmp.rollout(r); }), "tau = -1: must be a finite number > 0");
  r = RolloutRequest{};
  r.dt = 0.0;
  EXPECT_EQ(errorOf([&] { dmp.rollout(r); }), "dt = 0: must be a finite number > 0");
  r = RolloutRequest{};
  r.goal = { 1.0 };
  EXPECT_EQ(errorOf([&] { dmp.rollout(r); }), "goal: 1 values for 2 joints");
  r = RolloutRequest{};
  r.start = { 1.0, std::nan("") };
  EXPECT_EQ(errorOf([&] { dmp.rollout(r); }), "start: value 2 is not finite");
  EXPECT_EQ(errorOf([&] { dmp.begin(dmp.demoStart(), dmp.demoGoal(), 0.0); }), "tau = 0: must be a finite number > 0");
}

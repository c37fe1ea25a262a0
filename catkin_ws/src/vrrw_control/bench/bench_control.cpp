// vrrw_bench_control [points]: cost of the validation gate and of one interpolation sample for a
// 6-joint quintic trajectory. Last line: one JSON object.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vrrw_control/trajectory_interpolator.h>
#include <vrrw_control/trajectory_validator.h>

using namespace vrrw_control;
using Clock = std::chrono::steady_clock;

int main(int argc, char** argv)
{
  const int points = argc > 1 ? std::stoi(argv[1]) : 1000;
  std::vector<JointLimits> limits(6);
  vrrw_trajectory::JointTrajectory goal;
  for (int j = 0; j < 6; ++j)
  {
    limits[j].name = "ur5e_joint_" + std::to_string(j);
    limits[j].has_position_limits = true;
    limits[j].min_position = -6.28;
    limits[j].max_position = 6.28;
    limits[j].max_velocity = 3.14;
    limits[j].max_acceleration = 8.0;
    goal.joint_names.push_back(limits[j].name);
  }
  const double dt = 0.01, w = 1.0;
  for (int i = 0; i < points; ++i)
  {
    vrrw_trajectory::TrajectoryPoint p;
    p.time = i * dt;
    for (int j = 0; j < 6; ++j)
    {
      const double a = 0.5 + 0.1 * j;
      p.positions.push_back(a * std::sin(w * p.time));
      p.velocities.push_back(a * w * std::cos(w * p.time));
      p.accelerations.push_back(-a * w * w * std::sin(w * p.time));
    }
    goal.points.push_back(p);
  }
  const TrajectoryValidator gate(limits, {});
  JointSample rest(6);
  const int repeats = 20;
  const auto t0 = Clock::now();
  Validation v;
  for (int r = 0; r < repeats; ++r)
    v = gate.validate(goal, rest);
  const double gate_ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count() / repeats;
  if (!v.ok())
  {
    std::fprintf(stderr, "gate rejected the benchmark trajectory: %s\n", v.message.c_str());
    return 1;
  }
  const TrajectoryInterpolator interp(v.executable);
  const int samples = 200000;
  double sink = 0.0;
  const auto t1 = Clock::now();
  for (int k = 0; k < samples; ++k)
    sink += interp.sample(interp.endTime() * k / samples).positions[0];
  const double sample_us = std::chrono::duration<double, std::micro>(Clock::now() - t1).count() / samples;
  std::fprintf(stderr, "checksum %g\n", sink);
  std::printf("{\"bench\": \"control\", \"points\": %d, \"joints\": 6, \"gate_ms\": %.4f, \"sample_us\": %.4f}\n",
              points, gate_ms, sample_us);
  return 0;
}

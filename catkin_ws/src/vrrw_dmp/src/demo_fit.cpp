#include <vrrw_dmp/demo_fit.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace vrrw_dmp
{
namespace
{
std::string number(double value)
{
  char text[32];
  std::snprintf(text, sizeof(text), "%.3g", value);
  return text;
}

std::string severalMotions(const DemoSource& demo)
{
  std::string starts;
  for (const auto& motion : demo.motions)
    starts += (starts.empty() ? "" : ", ") + number(motion.first);
  std::string how = "cut it at the rests";
  if (demo.from_bag && !demo.segments.empty())
  {
    how = "learn one instruction at a time with --segment NAME (this bag has";
    for (const auto& name : demo.segments)
      how += " " + name;
    how += ")";
  }
  return "the demonstration holds " + std::to_string(demo.motions.size()) +
         " motions with rests between them (starting at " + starts + " s); a DMP is one motion: " + how;
}
}  // namespace

double reproductionRmse(const Dmp& dmp, const vrrw_trajectory::JointTrajectory& demo)
{
  RolloutRequest request;
  // 2 ms (the controllers' rate) or a hundredth of the motion, whichever is finer
  request.dt = std::min(0.002, dmp.demoDuration() / 100.0);
  const auto rollout = dmp.rollout(request);
  double worst = 0.0;
  for (std::size_t j = 0; j < dmp.dofs(); ++j)
  {
    double sum = 0.0;
    for (const auto& point : demo.points)
    {
      const double t = point.time - demo.points.front().time;
      const auto k = std::min(static_cast<std::size_t>(t / request.dt), rollout.points.size() - 2);
      const double u = (t - rollout.points[k].time) / request.dt;
      const double q = (1.0 - u) * rollout.points[k].positions[j] + u * rollout.points[k + 1].positions[j];
      sum += (q - point.positions[j]) * (q - point.positions[j]);
    }
    worst = std::max(worst, std::sqrt(sum / static_cast<double>(demo.points.size())));
  }
  return worst;
}

std::vector<std::string> fitAdvice(const DemoSource& demo, const DmpParameters& parameters, double rmse)
{
  std::vector<std::string> advice;
  if (rmse <= kGoodFit)
    return advice;
  if (demo.motions.size() > 1)
    advice.push_back(severalMotions(demo));
  // Doubling from the given count keeps the search to a few learns (at most nine from N = 2 up to 1000).
  for (std::size_t count = 2 * parameters.basis_count; count <= 1000; count *= 2)
  {
    DmpParameters more = parameters;
    more.basis_count = count;
    const double fit = reproductionRmse(Dmp::learn(demo.trajectory, more), demo.trajectory);
    if (fit <= kGoodFit)
    {
      advice.push_back("--basis " + std::to_string(count) + " reproduces it within " + number(fit) + " rad");
      return advice;
    }
  }
  advice.push_back("no basis count up to 1000 reproduces it within " + number(kGoodFit) + " rad");
  return advice;
}
}  // namespace vrrw_dmp

#include "path_simplification.h"

#include <algorithm>
#include <random>

namespace vrrw_kinematics
{
namespace
{
constexpr int kShortcutFailures = 5;
}  // namespace

void reduceVertices(std::vector<Eigen::VectorXd>& path, SegmentChecker& segments)
{
  for (std::size_t i = 0; i + 2 < path.size(); ++i)
    for (std::size_t j = path.size() - 1; j > i + 1; --j)
      if (segments.valid(path[i], path[j]))
      {
        path.erase(path.begin() + static_cast<std::ptrdiff_t>(i + 1), path.begin() + static_cast<std::ptrdiff_t>(j));
        break;
      }
}

void simplifyPath(std::vector<Eigen::VectorXd>& path, SegmentChecker& segments, int attempts, std::uint64_t seed)
{
  reduceVertices(path, segments);
  std::mt19937_64 rng(seed);
  for (int attempt = 0, failures = 0; attempt < attempts && failures < kShortcutFailures && path.size() > 2;
       ++attempt)
  {
    std::vector<double> cumulative(1, 0.0);
    for (std::size_t i = 1; i < path.size(); ++i)
      cumulative.push_back(cumulative.back() + (path[i] - path[i - 1]).norm());
    std::uniform_real_distribution<double> along(0.0, cumulative.back());
    double a = along(rng), b = along(rng);
    if (a > b)
      std::swap(a, b);
    const std::size_t ia = static_cast<std::size_t>(std::upper_bound(cumulative.begin(), cumulative.end(), a) -
                                                    cumulative.begin()) - 1;
    const std::size_t ib = static_cast<std::size_t>(std::upper_bound(cumulative.begin(), cumulative.end(), b) -
                                                    cumulative.begin()) - 1;
    if (ia == ib || ib + 1 >= path.size())
    {
      ++failures;
      continue;
    }
    const auto point = [&](std::size_t i, double s) {
      const double t = (s - cumulative[i]) / std::max(cumulative[i + 1] - cumulative[i], 1e-12);
      return Eigen::VectorXd(path[i] + t * (path[i + 1] - path[i]));
    };
    const Eigen::VectorXd pa = point(ia, a), pb = point(ib, b);
    if (!segments.valid(pa, pb))
    {
      ++failures;
      continue;
    }
    failures = 0;
    std::vector<Eigen::VectorXd> shorter(path.begin(), path.begin() + static_cast<std::ptrdiff_t>(ia + 1));
    shorter.push_back(pa);
    shorter.push_back(pb);
    shorter.insert(shorter.end(), path.begin() + static_cast<std::ptrdiff_t>(ib + 1), path.end());
    path.clear();
    for (const Eigen::VectorXd& q : shorter)
      if (path.empty() || (q - path.back()).norm() > 1e-9)
        path.push_back(q);
  }
  reduceVertices(path, segments);
}
}  // namespace vrrw_kinematics

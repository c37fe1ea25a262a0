#include <vrrw_skills/trial_poses.h>

#include <cmath>
#include <random>

namespace vrrw_skills
{
PlanarPose planarPose(const Eigen::Isometry3d& pose)
{
  const Eigen::Vector3d x_axis = pose.rotation().col(0);
  return { pose.translation().x(), pose.translation().y(), std::atan2(x_axis.y(), x_axis.x()) };
}

Eigen::Isometry3d placeOnTable(const Eigen::Isometry3d& reference, const PlanarPose& planar)
{
  const double turn = planar.yaw - planarPose(reference).yaw;
  Eigen::Isometry3d pose = reference;
  pose.linear() = Eigen::AngleAxisd(turn, Eigen::Vector3d::UnitZ()).toRotationMatrix() * reference.linear();
  pose.translation().x() = planar.x;
  pose.translation().y() = planar.y;
  return pose;
}

std::vector<PlanarPose> sampleTrialPoses(const PlanarPose& around, const TrialSpread& spread, std::size_t count,
                                         std::uint64_t seed)
{
  // A fixed generator and our own mapping to [-1, 1]: std::uniform_real_distribution differs between
  // standard libraries, the seed must name the same poses everywhere.
  std::mt19937_64 generator(seed);
  auto unit = [&] { return 2.0 * (double(generator() >> 11) * 0x1.0p-53) - 1.0; };
  std::vector<PlanarPose> poses;
  for (std::size_t i = 0; i < count; ++i)
  {
    double u[3] = { unit(), unit(), unit() };
    if (i % 2 == 1)
    {
      const std::size_t axis = std::size_t(generator() % 3);
      u[axis] = std::copysign(0.8 + 0.2 * std::abs(u[axis]), u[axis]);
    }
    poses.push_back({ around.x + spread.x * u[0], around.y + spread.y * u[1], around.yaw + spread.yaw * u[2] });
  }
  return poses;
}
}  // namespace vrrw_skills

#pragma once
#include <Eigen/Geometry>
#include <cstdint>
#include <vector>

namespace vrrw_skills
{
/// \brief Where an object stands on the table: position in the world's x-y plane and yaw about z.
struct PlanarPose
{
  double x = 0.0;
  double y = 0.0;
  double yaw = 0.0;  ///< rad
};

/// \brief Half-widths of the box trial poses are drawn from, around the demonstrated pose.
struct TrialSpread
{
  double x = 0.10;    ///< m
  double y = 0.10;    ///< m
  double yaw = 0.5236;  ///< rad (30 deg)
};

/// \brief The planar part of a pose (yaw of its x axis projected on the table).
PlanarPose planarPose(const Eigen::Isometry3d& pose);
/// \brief `reference` moved to `planar`: same height, roll and pitch, new x, y and yaw.
Eigen::Isometry3d placeOnTable(const Eigen::Isometry3d& reference, const PlanarPose& planar);

/// \brief `count` poses drawn uniformly from `around` +- `spread` with a seeded generator; the same seed
/// gives the same poses on any run. Every second draw is pushed to the box's rim (at least 80 % of each
/// half-width on one axis), so the edges of the claimed range are exercised, not only its centre.
std::vector<PlanarPose> sampleTrialPoses(const PlanarPose& around, const TrialSpread& spread, std::size_t count,
                                         std::uint64_t seed);
}  // namespace vrrw_skills

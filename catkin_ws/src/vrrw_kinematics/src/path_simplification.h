#pragma once
#include <Eigen/Dense>
#include <cstdint>
#include <vector>

#include "vrrw_kinematics/segment_checker.h"

namespace vrrw_kinematics
{
/// \brief Drops every waypoint a straight valid segment can skip (greedy, farthest first).
void reduceVertices(std::vector<Eigen::VectorXd>& path, SegmentChecker& segments);

/// \brief reduceVertices, then up to `attempts` seeded random shortcuts between points on the path
/// (stopping after 5 failures in a row), then reduceVertices again.
void simplifyPath(std::vector<Eigen::VectorXd>& path, SegmentChecker& segments, int attempts, std::uint64_t seed);
}  // namespace vrrw_kinematics

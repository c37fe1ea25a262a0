#pragma once
#include <Eigen/Core>
#include <memory>
#include <string>

class btConvexHullShape;

namespace vrrw_physics
{
/// \brief A convex hull (at most ~100 vertices) of a mesh file (STL binary/ASCII or OBJ), scaled;
/// throws std::runtime_error "path: reason" when the file cannot be read.
std::unique_ptr<btConvexHullShape> loadConvexHull(const std::string& path, const Eigen::Vector3d& scale);
}  // namespace vrrw_physics

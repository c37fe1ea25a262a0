#pragma once
#include <Eigen/Core>
#include <memory>
#include <string>

class btConvexHullShape;

namespace vrrw_physics
{
/// \brief Resolves file://, package:// and plain paths to a file path (package:// through
/// ROS_PACKAGE_PATH); throws std::runtime_error naming the URI when it cannot.
std::string resolveMeshPath(const std::string& uri);

/// \brief A convex hull (at most ~100 vertices) of a mesh file (STL binary/ASCII or OBJ), scaled;
/// throws std::runtime_error "path: reason" when the file cannot be read.
std::unique_ptr<btConvexHullShape> loadConvexHull(const std::string& path, const Eigen::Vector3d& scale);
}  // namespace vrrw_physics

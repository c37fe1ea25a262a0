#pragma once
#include <string>

namespace vrrw_scene
{
/// \brief The file a URDF mesh URI names, or "" when it names none.
///
/// `file://PATH`; `package://PKG/PATH`, PKG found on ROS_PACKAGE_PATH the way rospack crawls it (an entry
/// that is the package itself, or holds it up to three folders down; a folder counts as PKG when it is
/// named PKG and holds a package.xml); an absolute path; or a path relative to `base_dir`.
std::string resolveMeshPath(const std::string& uri, const std::string& base_dir = "");
}  // namespace vrrw_scene

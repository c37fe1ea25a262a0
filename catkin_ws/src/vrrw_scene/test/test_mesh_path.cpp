// resolveMeshPath: the one resolver of URDF mesh URIs (scene checks, kinematics, physics).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "vrrw_scene/mesh_path.h"

namespace fs = std::filesystem;
using vrrw_scene::resolveMeshPath;

namespace
{
/// TMP/mesh_path/ws/src/deep/my_pkg/{package.xml, meshes/part.stl}
fs::path makeWorkspace()
{
  const fs::path root = fs::path(testing::TempDir()) / "mesh_path";
  fs::remove_all(root);
  const fs::path package = root / "ws" / "src" / "deep" / "my_pkg";
  fs::create_directories(package / "meshes");
  std::ofstream(package / "package.xml") << "<package/>";
  std::ofstream(package / "meshes" / "part.stl") << "solid part\nendsolid part\n";
  fs::create_directories(root / "ws" / "src" / "my_pkg_copy_without_manifest" / "meshes");
  return root;
}
}  // namespace

TEST(MeshPath, ResolvesPackageUrisOnRosPackagePathLikeRospack)
{
  const fs::path root = makeWorkspace();
  const std::string part = (root / "ws/src/deep/my_pkg/meshes/part.stl").string();
  setenv("ROS_PACKAGE_PATH", ("/nonexistent:" + (root / "ws").string()).c_str(), 1);
  EXPECT_EQ(resolveMeshPath("package://my_pkg/meshes/part.stl"), part);
  setenv("ROS_PACKAGE_PATH", (root / "ws/src/deep/my_pkg").string().c_str(), 1);  // the package itself
  EXPECT_EQ(resolveMeshPath("package://my_pkg/meshes/part.stl"), part);
  EXPECT_EQ(resolveMeshPath("package://my_pkg/meshes/missing.stl"), "");
  EXPECT_EQ(resolveMeshPath("package://other_pkg/meshes/part.stl"), "");
  EXPECT_EQ(resolveMeshPath("package://my_pkg"), "");
  unsetenv("ROS_PACKAGE_PATH");
  EXPECT_EQ(resolveMeshPath("package://my_pkg/meshes/part.stl"), "");
}

TEST(MeshPath, ResolvesFileAbsoluteAndRelativePaths)
{
  const fs::path root = makeWorkspace();
  const fs::path package = root / "ws/src/deep/my_pkg";
  const std::string part = (package / "meshes/part.stl").string();
  EXPECT_EQ(resolveMeshPath("file://" + part), part);
  EXPECT_EQ(resolveMeshPath(part), part);
  EXPECT_EQ(resolveMeshPath("meshes/part.stl", package.string()), part);
  EXPECT_EQ(resolveMeshPath("file://" + part + ".missing"), "");
  EXPECT_EQ(resolveMeshPath("meshes/part.stl", root.string()), "");
}

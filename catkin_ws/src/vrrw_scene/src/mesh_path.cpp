#include "vrrw_scene/mesh_path.h"

#include <cstdlib>
#include <filesystem>
#include <sstream>

namespace fs = std::filesystem;

namespace vrrw_scene
{
namespace
{
constexpr int kPackageSearchDepth = 3;

bool isPackage(const fs::path& dir, const std::string& package)
{
  std::error_code ignored;
  return dir.filename() == package && fs::is_regular_file(dir / "package.xml", ignored);
}

/// The folder of `package` at or below `dir`, depth-first; a package's own folders are not searched.
fs::path findPackage(const fs::path& dir, const std::string& package, int depth)
{
  if (isPackage(dir, package))
    return dir;
  std::error_code error;
  if (depth == 0 || fs::is_regular_file(dir / "package.xml", error))
    return {};
  for (fs::directory_iterator entry(dir, error), end; !error && entry != end; entry.increment(error))
    if (entry->is_directory(error) && entry->path().filename().string().front() != '.')
    {
      const fs::path found = findPackage(entry->path(), package, depth - 1);
      if (!found.empty())
        return found;
    }
  return {};
}

std::string existing(const fs::path& path)
{
  std::error_code ignored;
  return fs::is_regular_file(path, ignored) ? path.string() : "";
}
}  // namespace

std::string resolveMeshPath(const std::string& uri, const std::string& base_dir)
{
  const std::string file_scheme = "file://";
  const std::string package_scheme = "package://";
  if (uri.rfind(file_scheme, 0) == 0)
    return existing(uri.substr(file_scheme.size()));
  if (uri.rfind(package_scheme, 0) != 0)
    return existing(fs::path(uri).is_relative() && !base_dir.empty() ? fs::path(base_dir) / uri : fs::path(uri));
  const std::string rest = uri.substr(package_scheme.size());
  const std::size_t slash = rest.find('/');
  if (slash == std::string::npos || slash == 0)
    return "";
  const std::string package = rest.substr(0, slash);
  const char* path = std::getenv("ROS_PACKAGE_PATH");
  std::istringstream entries(path ? path : "");
  for (std::string entry; std::getline(entries, entry, ':');)
  {
    if (entry.empty())
      continue;
    const fs::path dir = findPackage(entry, package, kPackageSearchDepth);
    if (!dir.empty())
      return existing(dir / rest.substr(slash + 1));
  }
  return "";
}
}  // namespace vrrw_scene

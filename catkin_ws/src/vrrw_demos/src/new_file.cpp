#include <vrrw_demos/new_file.h>

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <vrrw_demos/demo_error.h>

namespace vrrw_demos
{
namespace
{
bool exists(const std::string& path)
{
  struct stat info;
  return ::lstat(path.c_str(), &info) == 0;
}

std::string folderOf(const std::string& path)
{
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? "." : slash == 0 ? "/" : path.substr(0, slash);
}

std::string fileOf(const std::string& path)
{
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}
}  // namespace

void refuseTaken(const std::string& path)
{
  if (path.empty())
    throw DemoError("file: empty; give a path");
  if (exists(path))
    throw DemoError(path + ": exists; not overwritten (remove it or choose another name)");
  const std::string active = path + kActiveSuffix;
  if (exists(active))
    throw DemoError(path + ": a recording is being written to " + active +
                    " (or was killed there: ./vrrw demos recover " + active + "); choose another name");
}

std::string temporaryBeside(const std::string& path)
{
  std::string name = folderOf(path) + "/." + fileOf(path) + ".partial-XXXXXX";
  const int fd = ::mkstemp(name.data());
  if (fd < 0)
    throw DemoError(path + ": cannot create a file in " + folderOf(path) + " (" + std::strerror(errno) + ")");
  ::close(fd);
  return name;
}

void publishNewFile(const std::string& temporary, const std::string& path)
{
  const bool linked = ::link(temporary.c_str(), path.c_str()) == 0;
  const int error = errno;
  ::unlink(temporary.c_str());
  if (!linked && error == EEXIST)
    throw DemoError(path + ": exists; not overwritten (remove it or choose another name)");
  if (!linked)
    throw DemoError(path + ": cannot be created (" + std::strerror(error) + ")");
}

void writeNewFile(const std::string& path, const std::string& contents)
{
  refuseTaken(path);
  const std::string temporary = temporaryBeside(path);
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
  std::size_t written = 0;
  while (fd >= 0 && written < contents.size())
  {
    const ssize_t n = ::write(fd, contents.data() + written, contents.size() - written);
    if (n < 0 && errno == EINTR)
      continue;
    if (n <= 0)
      break;
    written += static_cast<std::size_t>(n);
  }
  const int error = errno;
  const bool complete = fd >= 0 && written == contents.size() && ::fsync(fd) == 0;
  if (fd >= 0 && ::close(fd) != 0)
    written = 0;
  if (!complete || written != contents.size())
  {
    ::unlink(temporary.c_str());
    throw DemoError(path + ": write failed (" + std::strerror(error) + ")");
  }
  publishNewFile(temporary, path);
}
}  // namespace vrrw_demos

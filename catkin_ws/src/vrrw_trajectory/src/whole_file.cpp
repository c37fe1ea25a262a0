#include <vrrw_trajectory/whole_file.h>

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include <vrrw_trajectory/trajectory_error.h>

namespace vrrw_trajectory
{
namespace
{
[[noreturn]] void fail(const std::string& path, const std::string& temporary, const std::string& what, int error)
{
  ::unlink(temporary.c_str());
  throw TrajectoryError(path + ": " + what + ": " + std::strerror(error));
}

void writeAll(int fd, const std::string& contents, const std::string& path, const std::string& temporary)
{
  const char* data = contents.data();
  std::size_t left = contents.size();
  while (left > 0)
  {
    const ssize_t written = ::write(fd, data, left);
    if (written < 0 && errno == EINTR)
      continue;
    if (written <= 0)
    {
      const int error = errno;
      ::close(fd);
      fail(path, temporary, "write failed", error);
    }
    data += written;
    left -= static_cast<std::size_t>(written);
  }
}
}  // namespace

void writeWholeFile(const std::string& path, const std::string& contents)
{
  const std::string temporary = path + ".partial-" + std::to_string(::getpid());
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0)
    throw TrajectoryError(path + ": cannot open for writing: " + std::strerror(errno));
  writeAll(fd, contents, path, temporary);
  if (::fsync(fd) != 0)
  {
    const int error = errno;
    ::close(fd);
    fail(path, temporary, "write failed", error);
  }
  if (::close(fd) != 0)
    fail(path, temporary, "write failed", errno);
  if (std::rename(temporary.c_str(), path.c_str()) != 0)
    fail(path, temporary, "cannot replace", errno);
}
}  // namespace vrrw_trajectory

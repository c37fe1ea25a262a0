#include "workspace_process.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <deque>
#include <fstream>
#include <thread>

#include <vrrw_skills/skill_error.h>

namespace vrrw_skills
{
namespace
{
bool portFree(int port)
{
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  const int reuse = 1;  // as the master binds: a port whose last connections wait out TIME_WAIT is free
  ::setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &reuse, sizeof(reuse));
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  address.sin_port = htons(static_cast<uint16_t>(port));
  const bool free = ::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof(address)) == 0;
  ::close(fd);
  return free;
}
}  // namespace

int workspacePort()
{
  if (const char* text = std::getenv("VRRW_ROS_PORT"))
  {
    // the workspace is evaluate's own: a master already there (the user's workspace) would get a second
    // set of nodes
    const int port = std::atoi(text);
    if (port <= 0 || port > 65535)
      throw SkillError(std::string("VRRW_ROS_PORT: '") + text + "' is not a port number");
    if (!portFree(port))
      throw SkillError("VRRW_ROS_PORT: port " + std::to_string(port) +
                       " is in use (a running workspace?); evaluate starts its own: unset it or choose a free port");
    return port;
  }
  for (int port = 11611; port < 11711; ++port)
    if (portFree(port))
      return port;
  throw SkillRefusal("no free port for a ROS master in 11611-11710 (set VRRW_ROS_PORT)");
}

WorkspaceProcess::WorkspaceProcess(const std::string& scene, const std::string& rtf, const std::string& log_file,
                                   int port)
  : log_file_(log_file)
{
  const char* root = std::getenv("VRRW_ROOT");
  if (!root)
    throw SkillRefusal("VRRW_ROOT is not set: run it as ./vrrw skill evaluate ...");
  const std::string vrrw = std::string(root) + "/vrrw";
  master_uri_ = "http://localhost:" + std::to_string(port);
  ::setenv("ROS_MASTER_URI", master_uri_.c_str(), 1);
  const int log = ::open(log_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (log < 0)
    throw SkillRefusal(log_file + ": cannot be written");
  const pid_t evaluate = ::getpid();
  pid_ = ::fork();
  if (pid_ == 0)
  {
    ::setpgid(0, 0);
    // If evaluate dies without its destructor (a crash, SIGKILL), the launcher is ended with it, and its
    // watchdog ends the workspace's nodes (a crashed evaluate once left a whole workspace running).
    ::prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (::getppid() != evaluate)
      ::_exit(1);
    ::dup2(log, STDOUT_FILENO);
    ::dup2(log, STDERR_FILENO);
    const char* argv[] = { vrrw.c_str(), "up", scene.c_str(), "--mode", "physics", "--rtf", rtf.c_str(), nullptr };
    ::execv(vrrw.c_str(), const_cast<char* const*>(argv));
    ::_exit(127);
  }
  ::close(log);
  if (pid_ < 0)
    throw SkillRefusal("cannot start " + vrrw);
  ::setpgid(pid_, pid_);
}

WorkspaceProcess::~WorkspaceProcess()
{
  if (pid_ <= 0)
    return;
  ::kill(-pid_, SIGINT);
  for (int k = 0; k < 150; ++k)
  {
    ::waitpid(pid_, nullptr, WNOHANG);  // reaps ./vrrw itself once it ended
    if (::kill(-pid_, 0) != 0)          // nothing of the group is left
      return;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  ::kill(-pid_, SIGKILL);
  ::waitpid(pid_, nullptr, WNOHANG);
}

bool WorkspaceProcess::running() const
{
  return pid_ > 0 && ::kill(pid_, 0) == 0 && ::waitpid(pid_, nullptr, WNOHANG) == 0;
}

std::string WorkspaceProcess::trouble() const
{
  std::ifstream in(log_file_);
  std::deque<std::string> lines;
  for (std::string line; std::getline(in, line);)
    if (line.find("ERROR") != std::string::npos || line.find("FATAL") != std::string::npos ||
        line.find("process has died") != std::string::npos || line.find("vrrw:") != std::string::npos)
    {
      lines.push_back(line);
      if (lines.size() > 5)
        lines.pop_front();
    }
  std::string out;
  for (const std::string& line : lines)
    out += "\n  " + line;
  return out;
}
}  // namespace vrrw_skills

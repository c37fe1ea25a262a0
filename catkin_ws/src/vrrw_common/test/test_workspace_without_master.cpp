// vrrw_workspace_check without a master, and with one that never answers: one line, no endless retrying.
#include <chrono>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

namespace
{
struct Outcome
{
  int status = -1;
  std::string error;
  double seconds = 0.0;
};

/// Runs vrrw_workspace_check with ROS_MASTER_URI at \a port and returns its exit status and stderr.
Outcome check(int port)
{
  int pipe_ends[2];
  EXPECT_EQ(pipe(pipe_ends), 0);
  const auto start = std::chrono::steady_clock::now();
  const pid_t child = fork();
  if (child == 0)
  {
    dup2(pipe_ends[1], 2);
    close(pipe_ends[0]);
    const std::string uri = "ROS_MASTER_URI=http://localhost:" + std::to_string(port);
    putenv(const_cast<char*>(uri.c_str()));
    execl(VRRW_WORKSPACE_CHECK, VRRW_WORKSPACE_CHECK, "--robot", "ur5e", static_cast<char*>(nullptr));
    _exit(127);
  }
  close(pipe_ends[1]);
  Outcome outcome;
  char buffer[512];
  for (ssize_t n; (n = read(pipe_ends[0], buffer, sizeof buffer)) > 0;)
    outcome.error.append(buffer, static_cast<std::size_t>(n));
  close(pipe_ends[0]);
  waitpid(child, &outcome.status, 0);
  outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return outcome;
}

/// A listening TCP socket on a free port of localhost; its port.
int listenOnFreePort(int& fd)
{
  fd = socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  EXPECT_EQ(bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof address), 0);
  EXPECT_EQ(listen(fd, 8), 0);
  socklen_t length = sizeof address;
  getsockname(fd, reinterpret_cast<sockaddr*>(&address), &length);
  return ntohs(address.sin_port);
}
}  // namespace

TEST(WorkspaceWithoutMaster, NoMasterIsOneLine)
{
  int fd = -1;
  const int port = listenOnFreePort(fd);
  close(fd);  // nothing listens there now
  const Outcome outcome = check(port);
  std::cout << "no master: answered in " << outcome.seconds << " s" << std::endl;
  EXPECT_EQ(WEXITSTATUS(outcome.status), 1);
  EXPECT_EQ(outcome.error, "no workspace at http://localhost:" + std::to_string(port) +
                               ": start one with ./vrrw up SCENE\n");
}

TEST(WorkspaceWithoutMaster, AMasterThatNeverAnswersIsNoWorkspace)
{
  int fd = -1;
  const int port = listenOnFreePort(fd);  // connections are accepted by the kernel, never answered
  const Outcome outcome = check(port);
  close(fd);
  std::cout << "silent master: answered in " << outcome.seconds << " s" << std::endl;
  EXPECT_EQ(WEXITSTATUS(outcome.status), 1);
  EXPECT_EQ(outcome.error, "no workspace at http://localhost:" + std::to_string(port) +
                               ": start one with ./vrrw up SCENE\n");
  EXPECT_LT(outcome.seconds, 30.0);  // bounded (2 s); only a hang fails this
}

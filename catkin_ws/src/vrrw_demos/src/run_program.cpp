#include <vrrw_demos/run_program.h>

#include <cerrno>
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace vrrw_demos
{
int runProgram(const std::vector<std::string>& argv, std::string* output, bool quiet)
{
  if (argv.empty())
    return -1;
  std::vector<char*> args;
  for (const std::string& arg : argv)
    args.push_back(const_cast<char*>(arg.c_str()));
  args.push_back(nullptr);
  int pipe_ends[2] = { -1, -1 };
  if (output && ::pipe2(pipe_ends, O_CLOEXEC) != 0)
    return -1;
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (output)
    posix_spawn_file_actions_adddup2(&actions, pipe_ends[1], STDOUT_FILENO);
  if (quiet)
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  pid_t pid = -1;
  const int spawned = ::posix_spawnp(&pid, args[0], &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (output)
  {
    ::close(pipe_ends[1]);
    char buffer[4096];
    for (ssize_t n; spawned == 0 && (n = ::read(pipe_ends[0], buffer, sizeof(buffer))) != 0;)
      if (n > 0)
        output->append(buffer, static_cast<std::size_t>(n));
      else if (errno != EINTR)
        break;
    ::close(pipe_ends[0]);
  }
  if (spawned != 0)
    return -1;
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0)
    if (errno != EINTR)
      return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}
}  // namespace vrrw_demos

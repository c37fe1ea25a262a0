#include <vrrw_common/run_program.h>

#include <cerrno>
#include <csignal>
#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace vrrw_common
{
namespace
{
/// A pipe whose ends close with it; both ends close-on-exec (the child gets its end by dup2).
struct Pipe
{
  int read = -1, write = -1;
  bool open()
  {
    int ends[2];
    if (::pipe2(ends, O_CLOEXEC) != 0)
      return false;
    read = ends[0], write = ends[1];
    return true;
  }
  static void close(int& fd)
  {
    if (fd >= 0)
      ::close(fd);
    fd = -1;
  }
  ~Pipe() { close(read), close(write); }
};

/// Feeds \a input to the child and drains its output and errors together (poll), so that neither side waits
/// on a full pipe of the other: a plot script's megabytes of JSON in, xacro's URDF out.
void exchange(Pipe& in, const std::string* input, Pipe& out, std::string* output, Pipe& err, std::string* errors)
{
  std::size_t written = 0;
  char buffer[65536];
  for (;;)
  {
    pollfd fds[3];
    nfds_t n = 0;
    if (in.write >= 0)
      fds[n++] = { in.write, POLLOUT, 0 };
    if (out.read >= 0)
      fds[n++] = { out.read, POLLIN, 0 };
    if (err.read >= 0)
      fds[n++] = { err.read, POLLIN, 0 };
    if (n == 0)
      return;
    if (::poll(fds, n, -1) < 0)
    {
      if (errno == EINTR)
        continue;
      return;
    }
    for (nfds_t i = 0; i < n; ++i)
    {
      if (fds[i].revents == 0)
        continue;
      if (fds[i].fd == in.write)
      {
        const ssize_t k = ::write(in.write, input->data() + written, input->size() - written);
        if (k > 0)
          written += std::size_t(k);
        if ((k < 0 && errno != EINTR && errno != EAGAIN) || written == input->size())
          Pipe::close(in.write);  // done, or the child stopped reading: it gets end-of-file
        continue;
      }
      Pipe& source = fds[i].fd == out.read ? out : err;
      std::string* sink = fds[i].fd == out.read ? output : errors;
      const ssize_t k = ::read(source.read, buffer, sizeof(buffer));
      if (k > 0)
        sink->append(buffer, std::size_t(k));
      else if (k == 0 || errno != EINTR)
        Pipe::close(source.read);
    }
  }
}
}  // namespace

int runProgram(const std::vector<std::string>& argv, const ProgramStreams& streams)
{
  if (argv.empty())
    return -1;
  std::vector<char*> args;
  for (const std::string& arg : argv)
    args.push_back(const_cast<char*>(arg.c_str()));
  args.push_back(nullptr);
  Pipe in, out, err;
  if ((streams.input && !in.open()) || (streams.output && !out.open()) || (streams.errors && !err.open()))
    return -1;
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (streams.input)
    posix_spawn_file_actions_adddup2(&actions, in.read, STDIN_FILENO);
  if (streams.output)
    posix_spawn_file_actions_adddup2(&actions, out.write, STDOUT_FILENO);
  if (streams.errors)
    posix_spawn_file_actions_adddup2(&actions, err.write, STDERR_FILENO);
  else if (streams.quiet)
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  pid_t pid = -1;
  const int spawned = ::posix_spawnp(&pid, args[0], &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  Pipe::close(in.read), Pipe::close(out.write), Pipe::close(err.write);  // the child's ends
  if (spawned != 0)
    return -1;
  // A child that exits without reading all its input must not kill us with SIGPIPE: the write fails instead.
  struct sigaction ignore = {}, previous = {};
  ignore.sa_handler = SIG_IGN;
  if (streams.input)
    ::sigaction(SIGPIPE, &ignore, &previous);
  exchange(in, streams.input, out, streams.output, err, streams.errors);
  if (streams.input)
    ::sigaction(SIGPIPE, &previous, nullptr);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0)
    if (errno != EINTR)
      return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

int runProgram(const std::vector<std::string>& argv, std::string* output, bool quiet)
{
  ProgramStreams streams;
  streams.output = output;
  streams.quiet = quiet;
  return runProgram(argv, streams);
}

ProgramRun runCapturing(const std::vector<std::string>& argv)
{
  std::string errors;
  ProgramRun run;
  run.status = runProgram(argv, { nullptr, &run.output, &errors, false });
  run.output += errors;
  return run;
}
}  // namespace vrrw_common

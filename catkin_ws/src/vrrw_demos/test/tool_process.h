#pragma once
// The vrrw_demos tests' way to run the tool: a command line with its output kept, or a process with its
// arguments as given (no shell), its output read line by line through a pipe (as a user piping it sees it).
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace vrrw_demos_test
{
/// \brief A folder of this test process's own under /tmp.
inline const std::string& folder()
{
  static const std::string path = [] {
    char name[] = "/tmp/vrrw_demos_test_XXXXXX";
    return std::string(::mkdtemp(name));
  }();
  return path;
}

/// \brief Runs a command line of the test's own words; its exit status and (optional) output.
inline int run(const std::string& command, std::string* output = nullptr)
{
  const std::string log = folder() + "/command.log";
  const int status = std::system((command + " >" + log + " 2>&1").c_str());
  std::ifstream in(log);
  std::stringstream text;
  text << in.rdbuf();
  if (output)
    *output = text.str();
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// \brief \a args[0] with the arguments as given, in \a cwd; stdout and stderr through one pipe.
class ToolProcess
{
public:
  explicit ToolProcess(const std::vector<std::string>& args, const std::string& cwd = "")
  {
    int ends[2];
    EXPECT_EQ(::pipe(ends), 0);
    pid_ = ::fork();
    if (pid_ == 0)
    {
      ::dup2(ends[1], STDOUT_FILENO);
      ::dup2(ends[1], STDERR_FILENO);
      ::close(ends[0]);
      if (!cwd.empty() && ::chdir(cwd.c_str()) != 0)
        ::_exit(126);
      std::vector<char*> argv;
      for (const std::string& arg : args)
        argv.push_back(const_cast<char*>(arg.c_str()));
      argv.push_back(nullptr);
      ::execv(argv[0], argv.data());
      ::_exit(127);
    }
    ::close(ends[1]);
    out_ = ::fdopen(ends[0], "r");
  }
  ~ToolProcess()
  {
    std::fclose(out_);
    if (pid_ > 0)
      wait();
  }
  /// \brief The next line; false at the end of the output.
  bool line(std::string& text)
  {
    char buffer[8192];
    if (!std::fgets(buffer, sizeof(buffer), out_))
      return false;
    text = buffer;
    return true;
  }
  /// \brief Everything up to the end of the output.
  std::string rest()
  {
    std::string all, text;
    while (line(text))
      all += text;
    return all;
  }
  void signal(int number) { ::kill(pid_, number); }
  int wait()
  {
    int status = 0;
    ::waitpid(pid_, &status, 0);
    pid_ = -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }

private:
  pid_t pid_ = -1;
  FILE* out_ = nullptr;
};
}  // namespace vrrw_demos_test

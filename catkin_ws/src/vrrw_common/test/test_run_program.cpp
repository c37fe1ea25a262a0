// runProgram: a program's arguments are never shell text; its input, output and errors pass whole.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <sys/stat.h>
#include <unistd.h>

#include <vrrw_common/run_program.h>

using vrrw_common::ProgramStreams;
using vrrw_common::runProgram;

namespace
{
std::string folder()
{
  static const std::string path = [] {
    char name[] = "/tmp/vrrw_run_program_XXXXXX";
    return std::string(::mkdtemp(name));
  }();
  return path;
}

bool exists(const std::string& path)
{
  struct stat info;
  return ::stat(path.c_str(), &info) == 0;
}
}  // namespace

TEST(RunProgram, ArgumentsAreNeverShellText)
{
  const std::string hostile = folder() + "/y';touch " + folder() + "/PWNED;'$(touch " + folder() + "/PWNED2)|&<.png";
  std::string output;
  EXPECT_EQ(runProgram({ "printf", "%s", hostile }, &output), 0);
  EXPECT_EQ(output, hostile);  // one argument, as given
  EXPECT_FALSE(exists(folder() + "/PWNED"));
  EXPECT_FALSE(exists(folder() + "/PWNED2"));
  const auto run = vrrw_common::runCapturing(
      { "/usr/bin/python3", "-c", "import sys; print('said'); sys.stderr.write('refused\\n'); sys.exit(2)" });
  EXPECT_EQ(run.status, 2);
  EXPECT_EQ(run.output, "said\nrefused\n");  // its output, then its errors
  EXPECT_EQ(runProgram({ "/nonexistent/program" }), -1);
  EXPECT_EQ(runProgram({ "false" }), 1);
  EXPECT_EQ(runProgram({}), -1);
}

TEST(RunProgram, InputOutputAndErrorsPassWholeEvenWhenLarge)
{
  // 4 MB through the child and back: far beyond a pipe's 64 kB, so a run that wrote all before reading would
  // wait forever on the full output pipe.
  std::string input;
  for (int k = 0; input.size() < 4000000; ++k)
    input += std::to_string(k) + "\n";
  std::string output, errors;
  ProgramStreams streams;
  streams.input = &input;
  streams.output = &output;
  streams.errors = &errors;
  EXPECT_EQ(runProgram({ "/usr/bin/python3", "-c",
                        "import sys; sys.stdout.write(sys.stdin.read()); sys.stderr.write('one reason\\n'); sys.exit(3)" },
                      streams), 3);
  EXPECT_EQ(output.size(), input.size());
  EXPECT_TRUE(output == input);
  EXPECT_EQ(errors, "one reason\n");
}

TEST(RunProgram, AChildThatStopsReadingEndsTheRunNotThisProcess)
{
  const std::string input(2000000, 'x');
  std::string output;
  ProgramStreams streams;
  streams.input = &input;
  streams.output = &output;
  EXPECT_EQ(runProgram({ "head", "-c", "10" }, streams), 0);  // head exits after 10 bytes: no SIGPIPE for us
  EXPECT_EQ(output, std::string(10, 'x'));
}

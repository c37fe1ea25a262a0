// New files never replace another writer's: an existing file, or a recording's FILE.active.
#include <gtest/gtest.h>

#include <cstdio>
#include <functional>
#include <fstream>
#include <sstream>
#include <sys/stat.h>
#include <unistd.h>

#include <vrrw_demos/demo_error.h>
#include <vrrw_demos/new_file.h>
#include <vrrw_common/run_program.h>

#include "file_text.h"

using namespace vrrw_demos;

namespace
{
std::string folder()
{
  static const std::string path = [] {
    char name[] = "/tmp/vrrw_new_file_XXXXXX";
    return std::string(::mkdtemp(name));
  }();
  return path;
}

std::string errorOf(const std::function<void()>& write)
{
  try
  {
    write();
  }
  catch (const DemoError& e)
  {
    return e.what();
  }
  return "no error";
}

std::size_t filesIn(const std::string& dir)
{
  std::string listing;
  vrrw_common::runProgram({ "ls", "-A", dir }, &listing);
  std::size_t lines = 0;
  for (char c : listing)
    lines += c == '\n';
  return lines;
}
}  // namespace

TEST(NewFile, WritesWholeAndRefusesATakenNameOrARecordingsActiveFile)
{
  const std::string path = folder() + "/clash.bag";
  writeNewFile(path + ".yaml", "a: 1\n");
  EXPECT_EQ(slurp(path + ".yaml"), "a: 1\n");
  EXPECT_EQ(errorOf([&] { writeNewFile(path + ".yaml", "b: 2\n"); }),
            path + ".yaml: exists; not overwritten (remove it or choose another name)");
  EXPECT_EQ(slurp(path + ".yaml"), "a: 1\n");

  std::ofstream(path + kActiveSuffix) << "a recording";  // the recorder writes clash.bag.active
  EXPECT_EQ(errorOf([&] { refuseTaken(path); }),
            path + ": a recording is being written to " + path + ".active (or was killed there: ./vrrw demos recover " +
                path + ".active); choose another name");
  EXPECT_EQ(errorOf([&] { writeNewFile(path, "x"); }).substr(0, path.size() + 34),
            path + ": a recording is being written to ");
  EXPECT_EQ(slurp(path + kActiveSuffix), "a recording");
  EXPECT_EQ(errorOf([&] { refuseTaken(""); }), "file: empty; give a path");
  EXPECT_EQ(filesIn(folder()), 2u);  // no temporary left behind
}

TEST(NewFile, APublishedTemporaryNeverReplacesAFileThatAppearedMeanwhile)
{
  const std::string path = folder() + "/late.png";
  const std::string temporary = temporaryBeside(path);
  std::ofstream(temporary) << "new";
  std::ofstream(path) << "someone else's";
  EXPECT_EQ(errorOf([&] { publishNewFile(temporary, path); }),
            path + ": exists; not overwritten (remove it or choose another name)");
  EXPECT_EQ(slurp(path), "someone else's");
  struct stat info;
  EXPECT_NE(::stat(temporary.c_str(), &info), 0);  // removed
  EXPECT_EQ(errorOf([&] { temporaryBeside("/nonexistent/folder/x.png"); }),
            "/nonexistent/folder/x.png: cannot create a file in /nonexistent/folder (No such file or directory)");
}

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <vrrw_trajectory/csv.h>
#include <vrrw_trajectory/whole_file.h>

using vrrw_trajectory::TrajectoryError;
using vrrw_trajectory::writeWholeFile;

namespace
{
namespace fs = std::filesystem;

/// A fresh empty folder per test.
fs::path emptyFolder(const std::string& name)
{
  const fs::path folder = fs::path(::testing::TempDir()) / ("vrrw_whole_file_" + name + std::to_string(::getpid()));
  fs::remove_all(folder);
  fs::create_directories(folder);
  return folder;
}

std::string contentsOf(const fs::path& path)
{
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::size_t entries(const fs::path& folder)
{
  return static_cast<std::size_t>(std::distance(fs::directory_iterator(folder), fs::directory_iterator()));
}
}  // namespace

TEST(WholeFile, WritesAndReplacesLeavingNothingBeside)
{
  const fs::path folder = emptyFolder("replace");
  const fs::path path = folder / "model.yaml";
  writeWholeFile(path, "first\n");
  writeWholeFile(path, "second\n");
  EXPECT_EQ(contentsOf(path), "second\n");
  EXPECT_EQ(entries(folder), 1u);
  fs::remove_all(folder);
}

TEST(WholeFile, FailedReplaceKeepsTheOldFileAndRemovesTheTemporary)
{
  const fs::path folder = emptyFolder("fail");
  const fs::path target = folder / "out.csv";
  fs::create_directories(target / "inside");  // a non-empty folder cannot be replaced by a file
  try
  {
    writeWholeFile(target, "text");
    FAIL() << "no error";
  }
  catch (const TrajectoryError& e)
  {
    EXPECT_EQ(std::string(e.what()).rfind(target.string() + ": cannot replace: ", 0), 0u) << e.what();
  }
  EXPECT_TRUE(fs::is_directory(target / "inside"));
  EXPECT_EQ(entries(folder), 1u);
  fs::remove_all(folder);
}

TEST(WholeFile, UnwritableFolderIsNamed)
{
  try
  {
    writeWholeFile("/nonexistent/dir/out.csv", "text");
    FAIL() << "no error";
  }
  catch (const TrajectoryError& e)
  {
    EXPECT_STREQ(e.what(), "/nonexistent/dir/out.csv: cannot open for writing: No such file or directory");
  }
}

TEST(WholeFile, FullDiskLeavesNoPartialFile)
{
  // /dev/full takes the open but fails every write with ENOSPC, as a full disk does.
  if (::access("/dev/full", W_OK) != 0)
    GTEST_SKIP() << "/dev/full not writable";
  const fs::path folder = emptyFolder("full");
  const fs::path path = folder / "rollout.csv";
  fs::create_symlink("/dev/full", folder / ("rollout.csv.partial-" + std::to_string(::getpid())));
  EXPECT_THROW(writeWholeFile(path, std::string(1 << 16, 'x')), TrajectoryError);
  EXPECT_FALSE(fs::exists(path));
  EXPECT_EQ(entries(folder), 0u);
  fs::remove_all(folder);
}

TEST(WholeFile, CsvWriterRefusingATrajectoryLeavesTheOldFile)
{
  const fs::path folder = emptyFolder("csv");
  const fs::path path = folder / "demo.csv";
  writeWholeFile(path, "old\n");
  vrrw_trajectory::JointTrajectory bad;
  bad.joint_names = { "a" };
  bad.points = { { 0.0, { 1.0 }, { 0.0 }, {} }, { 0.0, { 1.0 }, { 0.0 }, {} } };
  EXPECT_THROW(vrrw_trajectory::writeCsv(path, bad), TrajectoryError);
  EXPECT_EQ(contentsOf(path), "old\n");
  EXPECT_EQ(entries(folder), 1u);
  fs::remove_all(folder);
}

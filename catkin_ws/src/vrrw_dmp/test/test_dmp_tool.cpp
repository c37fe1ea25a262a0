// The vrrw_dmp command-line tool as a user runs it: refused parameters leave no file behind and
// never touch an existing one; what it writes appears whole.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <vrrw_common/run_program.h>
#include <vrrw_trajectory/csv.h>

#include "demo_fixture.h"

namespace
{
namespace fs = std::filesystem;

/// Runs the tool with \a arguments as given (no shell); its status and output.
vrrw_common::ProgramRun runTool(std::vector<std::string> arguments)
{
  arguments.insert(arguments.begin(), VRRW_DMP_TOOL);
  return vrrw_common::runCapturing(arguments);
}

std::string contentsOf(const fs::path& path)
{
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::set<std::string> filesIn(const fs::path& folder)
{
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(folder))
    names.insert(entry.path().filename().string());
  return names;
}

class DmpTool : public ::testing::Test
{
protected:
  void SetUp() override
  {
    folder_ = fs::path(::testing::TempDir()) / ("vrrw_dmp_tool_" + std::to_string(::getpid()));
    fs::remove_all(folder_);
    fs::create_directories(folder_);
    vrrw_trajectory::writeCsv(path("demo.csv"), vrrw_dmp_test::sample(vrrw_dmp_test::SmoothDemo{}, 200, 0.2));
  }
  void TearDown() override { fs::remove_all(folder_); }
  std::string path(const std::string& name) const { return (folder_ / name).string(); }

  fs::path folder_;
};
}  // namespace

TEST_F(DmpTool, LearnsAndRollsOutWholeFiles)
{
  const auto learned = runTool({ "learn", "--demo", path("demo.csv"), "--out", path("model.yaml") });
  ASSERT_EQ(learned.status, 0) << learned.output;
  const auto rolled = runTool({ "rollout", "--model", path("model.yaml"), "--dt", "0.01", "--out", path("plan.csv") });
  ASSERT_EQ(rolled.status, 0) << rolled.output;
  const auto plan = vrrw_trajectory::readCsv(path("plan.csv"));
  EXPECT_GE(plan.points.size(), 201u);  // 2 s at 100 Hz, then settling
  EXPECT_NE(rolled.output.find("rolled out " + std::to_string(plan.points.size()) + " samples"), std::string::npos);
  const auto plotted =
      runTool({ "plot", "--demo", path("demo.csv"), "--rollout", path("plan.csv"), "--out", path("dmp.png") });
  ASSERT_EQ(plotted.status, 0) << plotted.output;
  EXPECT_EQ(contentsOf(folder_ / "dmp.png").substr(1, 3), "PNG");
  EXPECT_EQ(filesIn(folder_), (std::set<std::string>{ "demo.csv", "model.yaml", "plan.csv", "dmp.png" }));
}

TEST_F(DmpTool, RefusedRolloutsKeepTheOldFileAndLeaveNothingBeside)
{
  ASSERT_EQ(runTool({ "learn", "--demo", path("demo.csv"), "--out", path("model.yaml") }).status, 0);
  std::ofstream(path("plan.csv")) << "the previous plan\n";
  for (const auto& [option, value] : { std::pair{ "--tau", "1e6" }, std::pair{ "--dt", "1e-7" } })
  {
    const auto refused =
        runTool({ "rollout", "--model", path("model.yaml"), option, value, "--out", path("plan.csv") });
    EXPECT_EQ(refused.status, 2) << option;
    EXPECT_NE(refused.output.find("more than the limit of 1000000: raise dt or shorten tau"), std::string::npos)
        << refused.output;
    EXPECT_EQ(std::count(refused.output.begin(), refused.output.end(), '\n'), 1) << refused.output;
  }
  EXPECT_EQ(contentsOf(folder_ / "plan.csv"), "the previous plan\n");
  EXPECT_EQ(filesIn(folder_), (std::set<std::string>{ "demo.csv", "model.yaml", "plan.csv" }));
}

TEST_F(DmpTool, RefusedLearningWritesNoModel)
{
  const auto refused =
      runTool({ "learn", "--demo", path("demo.csv"), "--basis", "1000000000", "--out", path("model.yaml") });
  EXPECT_EQ(refused.status, 2);
  EXPECT_EQ(refused.output, "vrrw dmp learn: basis count N = 1000000000: more than the limit of 10000\n");
  const auto unwritable = runTool({ "learn", "--demo", path("demo.csv"), "--out", path("missing/model.yaml") });
  EXPECT_EQ(unwritable.status, 2);
  EXPECT_NE(unwritable.output.find("missing/model.yaml: cannot open for writing"), std::string::npos)
      << unwritable.output;
  EXPECT_EQ(filesIn(folder_), (std::set<std::string>{ "demo.csv" }));
}

TEST_F(DmpTool, AFileItCannotUseIsBadInput)
{
  std::ofstream(path("model.yaml")) << "format: [not, a, model\n";
  const auto model = runTool({ "rollout", "--model", path("model.yaml"), "--out", path("plan.csv") });
  EXPECT_EQ(model.status, 2);
  EXPECT_EQ(model.output.rfind("vrrw dmp rollout: " + path("model.yaml") + ":", 0), 0u) << model.output;
  EXPECT_EQ(std::count(model.output.begin(), model.output.end(), '\n'), 1) << model.output;
  const auto demo = runTool({ "learn", "--demo", path("missing.csv"), "--out", path("new.yaml") });
  EXPECT_EQ(demo.status, 2);
  EXPECT_EQ(demo.output.rfind("vrrw dmp learn: " + path("missing.csv") + ":", 0), 0u) << demo.output;
  EXPECT_EQ(filesIn(folder_), (std::set<std::string>{ "demo.csv", "model.yaml" }));
}

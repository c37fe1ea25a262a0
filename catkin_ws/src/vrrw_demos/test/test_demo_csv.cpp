#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include <vrrw_demos/demo_csv.h>
#include <vrrw_demos/demo_error.h>

#include "file_text.h"
#include "scripted_demo.h"

using namespace vrrw_demos;

namespace
{
std::string temporary(const std::string& name)
{
  return "/tmp/vrrw_demos_csv_" + std::to_string(::getpid()) + "_" + name;
}

std::string errorOf(const std::string& text)
{
  const std::string path = temporary("bad.csv");
  std::ofstream(path) << text;
  try
  {
    importCsv(path, "ur5e");
  }
  catch (const DemoError& e)
  {
    std::remove(path.c_str());
    return std::string(e.what()).substr(path.size());
  }
  std::remove(path.c_str());
  return "no error";
}
}  // namespace

TEST(DemoCsv, ExportImportExportIsIdenticalBitForBit)
{
  const RobotTrack track = vrrw_demos_test::scriptedPickPlace(1000.0).demo.robots[0];
  const std::string first = temporary("first.csv"), second = temporary("second.csv");
  exportCsv(track, first);
  const RobotTrack back = importCsv(first, "ur5e");
  ASSERT_EQ(back.states.size(), track.states.size());
  for (std::size_t k = 0; k < track.states.size(); ++k)
  {
    ASSERT_EQ(back.states[k].time, track.states[k].time);
    ASSERT_EQ(back.states[k].positions, track.states[k].positions);
    ASSERT_EQ(back.states[k].velocities, track.states[k].velocities);
    ASSERT_EQ(back.states[k].gripper, track.states[k].gripper);
  }
  exportCsv(back, second);
  EXPECT_EQ(slurp(first), slurp(second));
  const std::string header = slurp(first).substr(0, slurp(first).find('\n'));
  EXPECT_EQ(header.substr(header.size() - 8), ",gripper");
  std::remove(first.c_str());
  std::remove(second.c_str());
}

TEST(DemoCsv, NeverOverwritesAndNamesBadInput)
{
  const RobotTrack track = vrrw_demos_test::scriptedPickPlace(50.0).demo.robots[0];
  const std::string path = temporary("exists.csv");
  std::ofstream(path) << "keep me";
  try
  {
    exportCsv(track, path);
    FAIL() << "overwrote";
  }
  catch (const DemoError& e)
  {
    EXPECT_EQ(std::string(e.what()), path + ": exists; not overwritten (remove it or choose another name)");
  }
  EXPECT_EQ(slurp(path), "keep me");
  std::remove(path.c_str());

  EXPECT_EQ(errorOf("t,a,b,a_vel\n0,1,2,3\n1,1,2,3\n"),
            ":1: wrong column count: header has 4 columns, expected 1 + 2n ('t', n joint positions, n '<joint>_vel' velocities)");
  EXPECT_EQ(errorOf("t,a,a_vel,gripper\n0,1,2,0\n0.1,nan,2,0\n"), ":3: column 'a': 'nan' is not finite");
  EXPECT_EQ(errorOf("t,a,a_vel,gripper\n0,1,2,0\n0,1,2,0\n"),
            ":3: time 0 is not after the previous time 0 (times must strictly increase)");
}

TEST(DemoCsv, ImportTakesOnlyTheRobotsJointsWithinPhysicalBounds)
{
  // another robot's joints (a ur10e recording imported as ur5e), an empty robot name, values of another unit
  EXPECT_EQ(errorOf("t,ur10e_a,ur10e_a_vel,gripper\n0,1,2,0\n0.1,1,2,0\n"),
            ":1: joint 'ur10e_a' is not one of robot 'ur5e' (its joints are named ur5e_<joint>)");
  EXPECT_EQ(errorOf("t,ur5e_a,ur5e_a_vel,gripper\n0,1,2,0\n0.1,1,2,1e6\n"),
            ": row 2: column 'gripper': 1e+06 is outside [-3.14159, 3.14159]");
  EXPECT_EQ(errorOf("t,ur5e_a,ur5e_a_vel,gripper\n0,90,0,0\n0.1,91,10,0\n"),
            ": row 1: column 'ur5e_a': 90 is outside [-12.5664, 12.5664]");
  EXPECT_EQ(errorOf("t,ur5e_a,ur5e_a_vel,gripper\n0,1,0,0\n0.1,1,1000,0\n"),
            ": row 2: column 'ur5e_a_vel': 1000 is outside [-100, 100]");
  const std::string path = temporary("good.csv");
  std::ofstream(path) << "t,ur5e_a,ur5e_a_vel,gripper\n0,1,0,0\n0.1,1,0,0.8\n";
  for (const char* robot : { "", "ur5e/", "5e", "ur 5e" })
  {
    try
    {
      importCsv(path, robot);
      ADD_FAILURE() << "robot '" << robot << "' accepted";
    }
    catch (const DemoError& e)
    {
      EXPECT_EQ(std::string(e.what()),
                "robot: '" + std::string(robot) + "' is not a robot's name (a letter, then letters, digits and _)");
    }
  }
  EXPECT_EQ(importCsv(path, "ur5e").states.back().gripper, 0.8);
  std::remove(path.c_str());
}

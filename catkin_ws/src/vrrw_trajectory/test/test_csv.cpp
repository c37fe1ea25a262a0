#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include <vrrw_trajectory/csv.h>

using vrrw_trajectory::JointTrajectory;
using vrrw_trajectory::readCsv;
using vrrw_trajectory::TrajectoryError;
using vrrw_trajectory::writeCsv;

namespace
{
JointTrajectory parse(const std::string& text)
{
  std::istringstream in(text);
  return readCsv(in, "demo.csv");
}

std::string errorOf(const std::string& text)
{
  try
  {
    parse(text);
  }
  catch (const TrajectoryError& e)
  {
    return e.what();
  }
  return "no error";
}

const char* const kHeader = "t,a,b,a_vel,b_vel\n";
}  // namespace

TEST(Csv, ReadsNamedHeaderPositionsAndVelocities)
{
  const JointTrajectory trajectory = parse(std::string(kHeader) + "0,1,2,3,4\n0.5, -1e-3 ,+2.5,0,-4\n");
  ASSERT_EQ(trajectory.joint_names, (std::vector<std::string>{ "a", "b" }));
  ASSERT_EQ(trajectory.points.size(), 2u);
  EXPECT_EQ(trajectory.points[1].time, 0.5);
  EXPECT_EQ(trajectory.points[1].positions, (std::vector<double>{ -1e-3, 2.5 }));
  EXPECT_EQ(trajectory.points[1].velocities, (std::vector<double>{ 0.0, -4.0 }));
  EXPECT_TRUE(trajectory.points[1].accelerations.empty());
  EXPECT_DOUBLE_EQ(trajectory.duration(), 0.5);
}

TEST(Csv, ReadsSeedThirteenColumnLayoutWithCrlfAndBlankLines)
{
  std::string text = "t,q1,q2,q3,q4,q5,q6,qd1,qd2,qd3,qd4,qd5,qd6\r\n";
  for (int k = 0; k < 3; ++k)
    text += std::to_string(0.02 * k) + ",0,-1.57,0,-1.57,0,0,0,0,0,0,0,0\r\n";
  text += "\r\n\n";
  const JointTrajectory trajectory = parse(text);
  EXPECT_EQ(trajectory.joint_names.size(), 6u);
  EXPECT_EQ(trajectory.joint_names[0], "q1");
  EXPECT_EQ(trajectory.points.size(), 3u);
  EXPECT_DOUBLE_EQ(trajectory.points[2].positions[1], -1.57);
}

TEST(Csv, FileRoundTripIsBitExact)
{
  JointTrajectory trajectory;
  trajectory.joint_names = { "ur5e_shoulder_pan_joint", "ur5e_elbow_joint" };
  for (int k = 0; k < 50; ++k)
  {
    const double t = 0.013 * k + 1e-4 * std::sin(k);
    trajectory.points.push_back({ t, { std::sin(t) / 3.0, std::exp(-t) * 1e-9 }, { std::cos(t) / 3.0, -M_PI }, {} });
  }
  const std::string path = ::testing::TempDir() + "vrrw_csv_roundtrip.csv";
  writeCsv(path, trajectory);
  const JointTrajectory back = readCsv(path);
  std::remove(path.c_str());
  EXPECT_EQ(back.joint_names, trajectory.joint_names);
  ASSERT_EQ(back.points.size(), trajectory.points.size());
  for (std::size_t k = 0; k < back.points.size(); ++k)
  {
    EXPECT_EQ(back.points[k].time, trajectory.points[k].time);
    EXPECT_EQ(back.points[k].positions, trajectory.points[k].positions);
    EXPECT_EQ(back.points[k].velocities, trajectory.points[k].velocities);
  }
}

TEST(Csv, WrittenHeaderNamesVelocityColumns)
{
  JointTrajectory trajectory;
  trajectory.joint_names = { "j1" };
  trajectory.points = { { 0.0, { 1.0 }, { 0.5 }, {} }, { 0.25, { 2.0 }, { -0.5 }, {} } };
  std::ostringstream out;
  writeCsv(out, trajectory, "mem");
  EXPECT_EQ(out.str(), "t,j1,j1_vel\n0,1,0.5\n0.25,2,-0.5\n");
}

TEST(Csv, EmptyFileIsAnError)
{
  EXPECT_EQ(errorOf(""), "demo.csv:1: empty file: expected a header row 't,<joints>,<joints>_vel' and at least two samples");
  EXPECT_NE(errorOf("\n  \n").find("empty file"), std::string::npos);
}

TEST(Csv, HeaderOnlyOrOneRowIsAnError)
{
  EXPECT_EQ(errorOf(kHeader), "demo.csv:1: 0 sample row(s): a trajectory needs at least two samples");
  EXPECT_EQ(errorOf(std::string(kHeader) + "0,1,2,3,4\n"),
            "demo.csv:2: 1 sample row(s): a trajectory needs at least two samples");
}

TEST(Csv, WrongColumnCountNamesTheLine)
{
  EXPECT_EQ(errorOf(std::string(kHeader) + "0,1,2,3,4\n0.1,1,2,3\n"),
            "demo.csv:3: wrong column count: 4 cells, the header has 5");
  EXPECT_EQ(errorOf(std::string(kHeader) + "0,1,2,3,4,5\n0.1,1,2,3,4\n"),
            "demo.csv:2: wrong column count: 6 cells, the header has 5");
  EXPECT_NE(errorOf("t,a,b,a_vel\n0,1,2,3\n1,1,2,3\n").find("demo.csv:1: wrong column count: header has 4"),
            std::string::npos);
  EXPECT_NE(errorOf("t\n0\n1\n").find("demo.csv:1: wrong column count"), std::string::npos);
}

TEST(Csv, BadHeaderIsAnError)
{
  EXPECT_NE(errorOf("0,1,2\n1,1,2\n").find("demo.csv:1: header must start with 't'"), std::string::npos);
  EXPECT_EQ(errorOf("t,a,b,b_vel,a_vel\n0,1,2,3,4\n1,1,2,3,4\n"),
            "demo.csv:1: header column 4 is 'b_vel', expected 'a_vel' (velocity of joint 'a')");
  EXPECT_EQ(errorOf("t,a,a,a_vel,a_vel\n0,1,2,3,4\n1,1,2,3,4\n"), "demo.csv:1: joint 'a' appears twice in the header");
  EXPECT_EQ(errorOf("t,,_vel\n0,1,2\n1,1,2\n"), "demo.csv:1: header column 2 has no joint name");
}

TEST(Csv, NonNumericCellNamesColumnAndLine)
{
  EXPECT_EQ(errorOf(std::string(kHeader) + "0,1,2,3,4\n0.1,1,x2,3,4\n"),
            "demo.csv:3: column 'b': 'x2' is not a number");
  EXPECT_EQ(errorOf(std::string(kHeader) + "0,1,2,3,4\n0.1,1,2e,3,4\n"),
            "demo.csv:3: column 'b': '2e' is not a number");
  EXPECT_EQ(errorOf(std::string(kHeader) + "0,1,,3,4\n0.1,1,2,3,4\n"), "demo.csv:2: column 'b': '' is not a number");
  EXPECT_EQ(errorOf(std::string(kHeader) + "0,1,2,3,4\n0.1,1,2,3,4 5\n"),
            "demo.csv:3: column 'b_vel': '4 5' is not a number");
}

TEST(Csv, NanAndInfAreErrors)
{
  EXPECT_EQ(errorOf(std::string(kHeader) + "0,1,2,3,4\n0.1,nan,2,3,4\n"), "demo.csv:3: column 'a': 'nan' is not finite");
  EXPECT_EQ(errorOf(std::string(kHeader) + "0,1,2,3,-inf\n0.1,1,2,3,4\n"),
            "demo.csv:2: column 'b_vel': '-inf' is not finite");
  EXPECT_EQ(errorOf(std::string(kHeader) + "0,1,2,3,4\n1e999,1,2,3,4\n"),
            "demo.csv:3: column 't': '1e999' is out of range");
}

TEST(Csv, NonIncreasingTimeIsAnError)
{
  EXPECT_EQ(errorOf(std::string(kHeader) + "0,1,2,3,4\n0.5,1,2,3,4\n0.5,1,2,3,4\n"),
            "demo.csv:4: time 0.5 is not after the previous time 0.5 (times must strictly increase)");
  EXPECT_NE(errorOf(std::string(kHeader) + "0,1,2,3,4\n-0.1,1,2,3,4\n").find("demo.csv:3: time -0.1 is not after"),
            std::string::npos);
}

TEST(Csv, MissingFileIsAnError)
{
  try
  {
    readCsv("/nonexistent/dir/demo.csv");
    FAIL() << "no error";
  }
  catch (const TrajectoryError& e)
  {
    EXPECT_STREQ(e.what(), "/nonexistent/dir/demo.csv:0: cannot open for reading");
  }
}

TEST(Csv, WriterRejectsWhatTheReaderWouldReject)
{
  JointTrajectory trajectory;
  trajectory.joint_names = { "a" };
  trajectory.points = { { 0.0, { 1.0 }, { 0.0 }, {} }, { 0.0, { 1.0 }, { 0.0 }, {} } };
  std::ostringstream out;
  EXPECT_THROW(writeCsv(out, trajectory, "mem"), TrajectoryError);
  trajectory.points[1] = { 0.1, { 1.0 }, {}, {} };
  EXPECT_THROW(writeCsv(out, trajectory, "mem"), TrajectoryError);
  trajectory.points[1] = { 0.1, { NAN }, { 0.0 }, {} };
  EXPECT_THROW(writeCsv(out, trajectory, "mem"), TrajectoryError);
  EXPECT_TRUE(out.str().empty());
}

TEST(Csv, ExtraColumnsAfterTheVelocitiesRoundTrip)
{
  const JointTrajectory read = parse("t,q1,q2,qd1,qd2,gripper\n0,1,2,3,4,0.5\n0.1,1,2,3,4,0.25\n");
  ASSERT_EQ(read.joint_names.size(), 2u);
  ASSERT_EQ(read.extra_names, std::vector<std::string>{ "gripper" });
  ASSERT_EQ(read.extras.size(), 2u);
  EXPECT_EQ(read.extras[1], std::vector<double>{ 0.25 });
  std::ostringstream out;
  writeCsv(out, read, "demo.csv");
  EXPECT_EQ(out.str(), "t,q1,q2,q1_vel,q2_vel,gripper\n0,1,2,3,4,0.5\n0.1,1,2,3,4,0.25\n");
  EXPECT_EQ(errorOf("t,a,a_vel,a\n0,1,2,3\n1,1,2,3\n"),
            "demo.csv:1: header column 4 ('a') must be a new, non-empty name (an extra column after the velocities)");
  EXPECT_EQ(errorOf("t,a,a_vel,g\n0,1,2,3\n1,1,2\n"), "demo.csv:3: wrong column count: 3 cells, the header has 4");
}

namespace
{
/// An endless input: "t,a,a_vel\n" and then one line that never ends (a 1 GB one-line file, or worse).
class EndlessLine : public std::streambuf
{
public:
  EndlessLine()
  {
    std::fill(std::begin(block_), std::end(block_), '7');
    std::copy(header_.begin(), header_.end(), block_);
    setg(block_, block_, block_ + sizeof(block_));
  }

private:
  int_type underflow() override
  {
    std::fill(std::begin(block_), std::end(block_), '7');
    setg(block_, block_, block_ + sizeof(block_));
    return traits_type::to_int_type(block_[0]);
  }
  const std::string header_ = "t,a,a_vel\n";
  char block_[4096];
};
}  // namespace

TEST(Csv, AnEndlessLineStopsAtTheBoundAndQuotesAFewCharacters)
{
  EndlessLine endless;
  std::istream in(&endless);
  try
  {
    readCsv(in, "huge.csv");
    FAIL() << "no error";
  }
  catch (const TrajectoryError& e)
  {
    EXPECT_STREQ(e.what(), "huge.csv:2: longer than 65536 characters: not a row of a trajectory (a row of joint values "
                           "has a few hundred)");
  }
  // a long cell on a line within the bound is quoted by its first 32 characters only
  const std::string cell(60000, 'x');
  EXPECT_EQ(errorOf(std::string(kHeader) + "0,1,2,3,4\n0.1,1," + cell + ",3,4\n"),
            "demo.csv:3: column 'b': '" + std::string(32, 'x') + "... (60000 characters)' is not a number");
  EXPECT_EQ(errorOf("t," + cell + ",b_vel\n0,1,2\n1,1,2\n"),
            "demo.csv:1: header column 3 is 'b_vel', expected '" + std::string(32, 'x') +
                "... (60004 characters)' (velocity of joint '" + std::string(32, 'x') + "... (60000 characters)')");
}

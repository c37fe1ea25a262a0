#include <vrrw_trajectory/csv.h>

#include <charconv>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include <vrrw_trajectory/whole_file.h>

namespace vrrw_trajectory
{
namespace
{
const char* const kVelocitySuffix = "_vel";
/// Characters of a cell an error message quotes; a longer cell is cut and its length said.
constexpr std::size_t kQuotedCharacters = 32;

/// A cell as an error message shows it: at most kQuotedCharacters of it.
std::string shown(const std::string& cell)
{
  if (cell.size() <= kQuotedCharacters)
    return cell;
  return cell.substr(0, kQuotedCharacters) + "... (" + std::to_string(cell.size()) + " characters)";
}

std::string quoted(const std::string& cell)
{
  return "'" + shown(cell) + "'";
}

std::string trim(const std::string& text)
{
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos)
    return "";
  const auto last = text.find_last_not_of(" \t\r");
  return text.substr(first, last - first + 1);
}

std::vector<std::string> splitCells(const std::string& line)
{
  std::vector<std::string> cells;
  std::string::size_type begin = 0;
  while (true)
  {
    const auto comma = line.find(',', begin);
    cells.push_back(trim(line.substr(begin, comma == std::string::npos ? std::string::npos : comma - begin)));
    if (comma == std::string::npos)
      return cells;
    begin = comma + 1;
  }
}

std::string formatNumber(double value)
{
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  return std::string(buffer, result.ptr);
}

class CsvParser
{
public:
  CsvParser(std::istream& in, const std::string& source) : in_(in), source_(source) {}

  JointTrajectory parse()
  {
    std::vector<std::string> header;
    if (!nextRow(header))
      fail(1, "empty file: expected a header row 't,<joints>,<joints>_vel' and at least two samples");
    const std::size_t header_line = line_number_;
    JointTrajectory trajectory;
    trajectory.joint_names = jointNames(header, header_line);
    const std::size_t n = trajectory.joint_names.size();
    trajectory.extra_names.assign(header.begin() + static_cast<std::ptrdiff_t>(1 + 2 * n), header.end());

    std::vector<std::string> row;
    while (nextRow(row))
    {
      if (row.size() != header.size())
        fail(line_number_, "wrong column count: " + std::to_string(row.size()) + " cells, the header has " +
                               std::to_string(header.size()));
      TrajectoryPoint point;
      point.time = number(row[0], header[0]);
      point.positions.resize(n);
      point.velocities.resize(n);
      for (std::size_t j = 0; j < n; ++j)
      {
        point.positions[j] = number(row[1 + j], header[1 + j]);
        point.velocities[j] = number(row[1 + n + j], header[1 + n + j]);
      }
      if (!trajectory.extra_names.empty())
        trajectory.extras.emplace_back();
      for (std::size_t e = 1 + 2 * n; e < row.size(); ++e)
        trajectory.extras.back().push_back(number(row[e], header[e]));
      if (!trajectory.points.empty() && !(point.time > trajectory.points.back().time))
        fail(line_number_, "time " + shown(row[0]) + " is not after the previous time " +
                               formatNumber(trajectory.points.back().time) + " (times must strictly increase)");
      trajectory.points.push_back(std::move(point));
    }
    if (trajectory.points.size() < 2)
      fail(line_number_, std::to_string(trajectory.points.size()) +
                             " sample row(s): a trajectory needs at least two samples");
    return trajectory;
  }

private:
  /// The next non-blank row's cells; false at the end. A line is read only up to kMaxLineLength, so a
  /// file that is one huge line costs that much memory, not its size.
  bool nextRow(std::vector<std::string>& cells)
  {
    while (in_.peek() != std::char_traits<char>::eof())
    {
      ++line_number_;
      if (++rows_ > kMaxRows)
        fail(line_number_, "more than " + std::to_string(kMaxRows) + " rows (the reader's bound)");
      in_.getline(line_.data(), static_cast<std::streamsize>(line_.size()));
      if (in_.fail() && !in_.eof())
        fail(line_number_, "longer than " + std::to_string(kMaxLineLength) +
                               " characters: not a row of a trajectory (a row of joint values has a few hundred)");
      in_.clear(in_.rdstate() & std::ios::eofbit);
      const std::string line(line_.data());
      if (!trim(line).empty())
      {
        cells = splitCells(line);
        return true;
      }
    }
    return false;
  }

  std::vector<std::string> jointNames(const std::vector<std::string>& header, std::size_t line) const
  {
    if (header[0] != "t" && header[0] != "time")
      fail(line, "header must start with 't' (time in seconds), found " + quoted(header[0]) +
                     " (is the header row missing?)");
    const std::size_t n = jointCount(header);
    if (n == 0)
      fail(line, "wrong column count: header has " + std::to_string(header.size()) +
                     " columns, expected 1 + 2n ('t', n joint positions, n '<joint>_vel' velocities)");
    std::vector<std::string> names(header.begin() + 1, header.begin() + 1 + static_cast<std::ptrdiff_t>(n));
    std::set<std::string> seen;
    for (std::size_t j = 0; j < n; ++j)
    {
      if (names[j].empty())
        fail(line, "header column " + std::to_string(j + 2) + " has no joint name");
      if (!seen.insert(names[j]).second)
        fail(line, "joint " + quoted(names[j]) + " appears twice in the header");
      const std::string& velocity = header[1 + n + j];
      if (velocity != names[j] + kVelocitySuffix && velocity != seedVelocityName(names[j]))
        fail(line, "header column " + std::to_string(n + j + 2) + " is " + quoted(velocity) + ", expected " +
                       quoted(names[j] + kVelocitySuffix) + " (velocity of joint " + quoted(names[j]) + ")");
    }
    std::set<std::string> extras;
    for (std::size_t e = 1 + 2 * n; e < header.size(); ++e)
      if (header[e].empty() || seen.count(header[e]) || !extras.insert(header[e]).second)
        fail(line, "header column " + std::to_string(e + 1) + " (" + quoted(header[e]) +
                       ") must be a new, non-empty name (an extra column after the velocities)");
    return names;
  }

  /// The joint count n: the first velocity column names joint 1's velocity; columns after the 2n
  /// joint columns are extras. Without such a column the header must be exactly 1 + 2n (0: it is not).
  static std::size_t jointCount(const std::vector<std::string>& header)
  {
    for (std::size_t n = 1; header.size() >= 1 + 2 * n; ++n)
      if (header[1 + n] == header[1] + kVelocitySuffix ||
          (!seedVelocityName(header[1]).empty() && header[1 + n] == seedVelocityName(header[1])))
        return n;
    return header.size() < 3 || header.size() % 2 == 0 ? 0 : (header.size() - 1) / 2;
  }

  static std::string seedVelocityName(const std::string& position_name)
  {
    if (position_name.size() > 1 && position_name[0] == 'q' &&
        position_name.find_first_not_of("0123456789", 1) == std::string::npos)
      return "qd" + position_name.substr(1);
    return "";
  }

  double number(const std::string& cell, const std::string& column) const
  {
    double value = 0.0;
    const char* begin = cell.data();
    const char* end = begin + cell.size();
    if (begin != end && *begin == '+')
      ++begin;
    const auto result = std::from_chars(begin, end, value);
    if (result.ec == std::errc::result_out_of_range && result.ptr == end)
      fail(line_number_, "column " + quoted(column) + ": " + quoted(cell) + " is out of range");
    if (cell.empty() || result.ec != std::errc() || result.ptr != end)
      fail(line_number_, "column " + quoted(column) + ": " + quoted(cell) + " is not a number");
    if (!std::isfinite(value))
      fail(line_number_, "column " + quoted(column) + ": " + quoted(cell) + " is not finite");
    return value;
  }

  [[noreturn]] void fail(std::size_t line, const std::string& reason) const
  {
    throw TrajectoryError(source_ + ":" + std::to_string(line) + ": " + reason);
  }

  std::istream& in_;
  std::string source_;
  std::size_t line_number_ = 0;
  std::size_t rows_ = 0;
  std::vector<char> line_ = std::vector<char>(kMaxLineLength + 1);  ///< getline's buffer: the bound plus '\0'
};

void checkWritable(const JointTrajectory& trajectory, const std::string& source)
{
  const std::size_t n = trajectory.joint_names.size();
  if (n == 0)
    throw TrajectoryError(source + ": no joint names");
  if (!trajectory.extra_names.empty() && trajectory.extras.size() != trajectory.points.size())
    throw TrajectoryError(source + ": " + std::to_string(trajectory.extras.size()) + " rows of extra values for " +
                          std::to_string(trajectory.points.size()) + " points");
  for (std::size_t k = 0; k < trajectory.points.size(); ++k)
  {
    const TrajectoryPoint& point = trajectory.points[k];
    const std::string where = source + ": point " + std::to_string(k) + ": ";
    if (point.positions.size() != n || point.velocities.size() != n)
      throw TrajectoryError(where + std::to_string(point.positions.size()) + " positions and " +
                            std::to_string(point.velocities.size()) + " velocities for " + std::to_string(n) +
                            " joints");
    const std::size_t extras = trajectory.extra_names.empty() ? 0 : trajectory.extras.at(k).size();
    if (extras != trajectory.extra_names.size())
      throw TrajectoryError(where + std::to_string(extras) + " extra values for " +
                            std::to_string(trajectory.extra_names.size()) + " extra columns");
    bool finite = std::isfinite(point.time);
    for (std::size_t j = 0; j < n; ++j)
      finite = finite && std::isfinite(point.positions[j]) && std::isfinite(point.velocities[j]);
    for (std::size_t e = 0; e < extras; ++e)
      finite = finite && std::isfinite(trajectory.extras[k][e]);
    if (!finite)
      throw TrajectoryError(where + "value is not finite");
    if (k > 0 && !(point.time > trajectory.points[k - 1].time))
      throw TrajectoryError(where + "time is not after the previous point's");
  }
}
}  // namespace

JointTrajectory readCsv(std::istream& in, const std::string& source)
{
  return CsvParser(in, source).parse();
}

JointTrajectory readCsv(const std::string& path)
{
  std::ifstream in(path);
  if (!in)
    throw TrajectoryError(path + ":0: cannot open for reading");
  return readCsv(in, path);
}

namespace
{
std::string csvText(const JointTrajectory& trajectory)
{
  std::string text = "t";
  for (const auto& name : trajectory.joint_names)
    text += "," + name;
  for (const auto& name : trajectory.joint_names)
    text += "," + name + kVelocitySuffix;
  for (const auto& name : trajectory.extra_names)
    text += "," + name;
  text += '\n';
  for (std::size_t k = 0; k < trajectory.points.size(); ++k)
  {
    const TrajectoryPoint& point = trajectory.points[k];
    text += formatNumber(point.time);
    for (double q : point.positions)
      (text += ',') += formatNumber(q);
    for (double qd : point.velocities)
      (text += ',') += formatNumber(qd);
    if (!trajectory.extra_names.empty())
      for (double value : trajectory.extras[k])
        (text += ',') += formatNumber(value);
    text += '\n';
  }
  return text;
}
}  // namespace

void writeCsv(std::ostream& out, const JointTrajectory& trajectory, const std::string& source)
{
  checkWritable(trajectory, source);
  out << csvText(trajectory);
  if (!out)
    throw TrajectoryError(source + ": write failed");
}

void writeCsv(const std::string& path, const JointTrajectory& trajectory)
{
  checkWritable(trajectory, path);
  writeWholeFile(path, csvText(trajectory));
}
}  // namespace vrrw_trajectory

#include <vrrw_demos/demo_csv.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <sstream>

#include <vrrw_demos/demo_error.h>
#include <vrrw_demos/new_file.h>
#include <vrrw_trajectory/csv.h>

namespace vrrw_demos
{
vrrw_trajectory::JointTrajectory toTrajectory(const RobotTrack& track)
{
  if (track.states.empty())
    throw DemoError("robot '" + track.robot + "': no recorded state");
  vrrw_trajectory::JointTrajectory trajectory;
  trajectory.joint_names = track.joint_names;
  trajectory.extra_names = { kGripperColumn };
  trajectory.points.reserve(track.states.size());
  for (const RobotState& state : track.states)
  {
    vrrw_trajectory::TrajectoryPoint point;
    point.time = state.time;
    point.positions = state.positions;
    point.velocities = state.velocities;
    trajectory.extras.push_back({ state.gripper });
    trajectory.points.push_back(std::move(point));
  }
  return trajectory;
}

RobotTrack fromTrajectory(const vrrw_trajectory::JointTrajectory& trajectory, const std::string& robot,
                          const std::string& source)
{
  RobotTrack track;
  track.robot = robot;
  track.joint_names = trajectory.joint_names;
  const auto gripper = std::find(trajectory.extra_names.begin(), trajectory.extra_names.end(), kGripperColumn);
  const auto gripper_index = static_cast<std::size_t>(gripper - trajectory.extra_names.begin());
  for (std::size_t k = 0; k < trajectory.points.size(); ++k)
  {
    const vrrw_trajectory::TrajectoryPoint& point = trajectory.points[k];
    if (point.velocities.size() != point.positions.size())
      throw DemoError(source + ": point " + std::to_string(k) + ": no velocities");
    RobotState state;
    state.time = point.time;
    state.positions = point.positions;
    state.velocities = point.velocities;
    state.gripper = gripper_index < trajectory.extra_names.size() ? trajectory.extras[k][gripper_index] : 0.0;
    track.states.push_back(std::move(state));
  }
  return track;
}

void exportCsv(const RobotTrack& track, const std::string& path)
{
  refuseTaken(path);
  std::ostringstream text;
  try
  {
    vrrw_trajectory::writeCsv(text, toTrajectory(track), path);
  }
  catch (const vrrw_trajectory::TrajectoryError& e)
  {
    throw DemoError(e.what());
  }
  writeNewFile(path, text.str());
}

void checkRobotName(const std::string& robot)
{
  const bool valid = !robot.empty() && std::isalpha(static_cast<unsigned char>(robot[0])) &&
                     std::all_of(robot.begin(), robot.end(),
                                 [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
  if (!valid)
    throw DemoError("robot: '" + robot + "' is not a robot's name (a letter, then letters, digits and _)");
}

// An import must be the robot's own: a scene prefixes every joint with its robot's name, so a CSV of another
// robot (ur10e_shoulder_pan_joint for --robot ur5e) is refused rather than recorded under the wrong name; and
// every value within the sanity bounds of demo_csv.h.
void checkImported(const RobotTrack& track, const std::string& source)
{
  const std::string prefix = track.robot + "_";
  const auto anonymous = [](const std::string& joint) {  // the seed's q1..qn: no robot named, none claimed
    return joint.size() > 1 && joint[0] == 'q' && joint.find_first_not_of("0123456789", 1) == std::string::npos;
  };
  for (const std::string& joint : track.joint_names)
    if (joint.rfind(prefix, 0) != 0 && !anonymous(joint))
      throw DemoError(source + ":1: joint '" + joint.substr(0, 48) + "' is not one of robot '" + track.robot +
                      "' (its joints are named " + prefix + "<joint>)");
  const auto outside = [&](std::size_t row, const std::string& column, double value, double bound) {
    char text[64];
    std::snprintf(text, sizeof(text), "%g is outside [-%g, %g]", value, bound, bound);
    return DemoError(source + ": row " + std::to_string(row + 1) + ": column '" + column + "': " + text);
  };
  for (std::size_t k = 0; k < track.states.size(); ++k)
  {
    const RobotState& state = track.states[k];
    for (std::size_t j = 0; j < state.positions.size(); ++j)
    {
      if (std::abs(state.positions[j]) > kMaxJointPosition)
        throw outside(k, track.joint_names[j], state.positions[j], kMaxJointPosition);
      if (std::abs(state.velocities[j]) > kMaxJointVelocity)
        throw outside(k, track.joint_names[j] + "_vel", state.velocities[j], kMaxJointVelocity);
    }
    if (std::abs(state.gripper) > kMaxGripperPosition)
      throw outside(k, kGripperColumn, state.gripper, kMaxGripperPosition);
  }
}

RobotTrack importCsv(const std::string& path, const std::string& robot)
{
  checkRobotName(robot);
  RobotTrack track;
  try
  {
    track = fromTrajectory(vrrw_trajectory::readCsv(path), robot, path);
  }
  catch (const vrrw_trajectory::TrajectoryError& e)
  {
    throw DemoError(e.what());
  }
  checkImported(track, path);
  return track;
}
}  // namespace vrrw_demos

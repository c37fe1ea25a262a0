#include <vrrw_demos/demo_csv.h>

#include <algorithm>
#include <sys/stat.h>

#include <vrrw_demos/demo_error.h>
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
  struct stat info;
  if (::stat(path.c_str(), &info) == 0)
    throw DemoError(path + ": exists; not overwritten (remove it or choose another name)");
  try
  {
    vrrw_trajectory::writeCsv(path, toTrajectory(track));
  }
  catch (const vrrw_trajectory::TrajectoryError& e)
  {
    throw DemoError(e.what());
  }
}

RobotTrack importCsv(const std::string& path, const std::string& robot)
{
  try
  {
    return fromTrajectory(vrrw_trajectory::readCsv(path), robot, path);
  }
  catch (const vrrw_trajectory::TrajectoryError& e)
  {
    throw DemoError(e.what());
  }
}
}  // namespace vrrw_demos

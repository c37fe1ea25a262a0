#include "bag_reader.h"

#include <stdexcept>

#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <sensor_msgs/JointState.h>
#include <vrrw_common/joint_mapping.h>
#include <vrrw_trajectory/msg_conversions.h>

namespace vrrw_dmp
{
namespace
{
void appendJointState(const sensor_msgs::JointState& state, double time, std::vector<std::string>& names,
                      vrrw_trajectory::JointTrajectory& trajectory, std::size_t& dropped)
{
  if (names.empty())
    names = state.name;
  vrrw_trajectory::TrajectoryPoint point;
  point.time = time;
  const auto at = vrrw_common::findJoints(state.name, names);
  if (!at)
    return;  // a message of another publisher (e.g. a gripper) without these joints
  for (const std::size_t index : *at)
  {
    if (index >= state.position.size())
      return;
    point.positions.push_back(state.position[index]);
    if (state.velocity.size() == state.name.size())
      point.velocities.push_back(state.velocity[index]);
  }
  if (point.velocities.size() != point.positions.size())
    point.velocities.clear();
  if (!trajectory.points.empty() && !(time > trajectory.points.back().time))
  {
    ++dropped;
    return;
  }
  trajectory.points.push_back(std::move(point));
}
}  // namespace

vrrw_trajectory::JointTrajectory readBag(const std::string& path, const std::string& topic,
                                         const std::vector<std::string>& joint_names, std::size_t& dropped)
{
  dropped = 0;
  if (topic.empty())
    throw std::runtime_error("bag " + path + ": no topic given");
  rosbag::Bag bag;
  try
  {
    bag.open(path, rosbag::bagmode::Read);
  }
  catch (const rosbag::BagException& e)
  {
    throw std::runtime_error("bag " + path + ": " + e.what());
  }
  rosbag::View view(bag, rosbag::TopicQuery(topic));
  if (view.size() == 0)
    throw std::runtime_error("bag " + path + ": no messages on topic '" + topic + "'");
  vrrw_trajectory::JointTrajectory trajectory;
  std::vector<std::string> names = joint_names;
  for (const rosbag::MessageInstance& message : view)
  {
    if (const auto state = message.instantiate<sensor_msgs::JointState>())
    {
      const double time = state->header.stamp.isZero() ? message.getTime().toSec() : state->header.stamp.toSec();
      appendJointState(*state, time, names, trajectory, dropped);
    }
    else if (const auto plan = message.instantiate<trajectory_msgs::JointTrajectory>())
    {
      return vrrw_trajectory::fromMsg(*plan);
    }
    else
    {
      throw std::runtime_error("bag " + path + ": topic '" + topic + "' has " + message.getDataType() +
                               ", expected sensor_msgs/JointState or trajectory_msgs/JointTrajectory");
    }
  }
  trajectory.joint_names = names;
  if (trajectory.points.empty())
    throw std::runtime_error("bag " + path + ": no message on '" + topic + "' has all the requested joints");
  return trajectory;
}
}  // namespace vrrw_dmp

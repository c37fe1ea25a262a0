#pragma once
#include <string>
#include <vector>

#include <vrrw_trajectory/joint_trajectory.h>

namespace vrrw_dmp
{
/// \brief A demonstration from a bag topic of sensor_msgs/JointState (every message that carries all
/// wanted joints is a sample; stamps, or bag times when zero; repeated times are dropped and counted in
/// \a dropped) or trajectory_msgs/JointTrajectory (the first message). Throws std::runtime_error
/// "bag PATH: reason".
vrrw_trajectory::JointTrajectory readBag(const std::string& path, const std::string& topic,
                                         const std::vector<std::string>& joint_names, std::size_t& dropped);
}  // namespace vrrw_dmp

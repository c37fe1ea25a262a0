#include "loaded_controllers.h"

#include <ros/console.h>

namespace vrrw_physics
{
LoadedControllers::LoadedControllers(PhysicsWorld& world, const vrrw_scene::Scene& scene, const std::string& plugin,
                                     const std::function<ros::Time()>& clock)
  : world_(world), plugin_(plugin), loader_("vrrw_physics", "vrrw_physics::RobotController")
{
  if (plugin.empty())
    return;
  for (const std::string& robot : world_.robotNames())
    load(scene, robot, clock);
}

LoadedControllers::~LoadedControllers()
{
  entries_.clear();  // the instances go before the loader that owns their library
}

void LoadedControllers::load(const vrrw_scene::Scene& scene, const std::string& robot,
                             const std::function<ros::Time()>& clock)
{
  try
  {
    Entry e;
    e.robot = robot;
    e.controller = loader_.createUniqueInstance(plugin_);
    ros::NodeHandle nh(robot);
    e.controller->initialize(nh, scene, robot, clock);
    const std::vector<std::string> joints = e.controller->joints();
    e.drive = world_.drives(robot, joints);
    const ArticulatedRobot& r = world_.robot(robot);
    for (const std::string& joint : joints)
      e.joint.push_back(std::size_t(r.jointIndex(joint)));
    const std::size_t n = joints.size();
    e.measured = { std::vector<double>(n), std::vector<double>(n), std::vector<double>(n) };
    e.targets = { std::vector<double>(n), std::vector<double>(n), std::vector<double>(n) };
    // it measures the robot at once: a client may send goals before the first step (a paused start)
    const std::string refused = update(e, ros::Time(world_.time()), ros::Duration(0));
    if (!refused.empty())
      throw std::runtime_error(refused);
    entries_.push_back(std::move(e));
  }
  catch (const std::exception& error)
  {
    ROS_ERROR_STREAM("physics_node: robot " << robot << ": controller " << plugin_ << " not loaded: " << error.what()
                                            << "; the robot holds its targets");
  }
}

std::vector<std::string> LoadedControllers::update(const ros::Duration& period)
{
  std::vector<std::string> refused;
  const ros::Time now(world_.time());
  for (Entry& e : entries_)
  {
    std::string why = update(e, now, period);
    if (!why.empty())
      refused.push_back(std::move(why));
  }
  return refused;
}

std::string LoadedControllers::update(Entry& e, const ros::Time& now, const ros::Duration& period)
{
  const ArticulatedRobot& r = world_.robot(e.robot);
  const std::vector<double> q = r.positions(), qd = r.velocities(), effort = r.efforts(world_.options().dt);
  for (std::size_t j = 0; j < e.joint.size(); ++j)
  {
    e.measured.position[j] = q[e.joint[j]];
    e.measured.velocity[j] = qd[e.joint[j]];
    e.measured.effort[j] = effort[e.joint[j]];
  }
  e.controller->update(now, period, e.measured, e.targets);
  try
  {
    world_.setDriveTargetsByIndex(e.robot, e.drive, e.targets.position, e.targets.velocity, e.targets.force_limit);
    return "";
  }
  catch (const InputError& error)
  {
    return e.robot + " controller: " + error.what();
  }
}

bool LoadedControllers::idle() const
{
  for (const Entry& e : entries_)
    if (!e.controller->idle())
      return false;
  return true;
}

void LoadedControllers::interrupt(const std::string& why)
{
  for (Entry& e : entries_)
    e.controller->interrupt(why);
}

std::vector<std::string> LoadedControllers::describe() const
{
  std::vector<std::string> out;
  for (const Entry& e : entries_)
    out.push_back(e.robot + " (" + plugin_ + ")");
  return out;
}
}  // namespace vrrw_physics

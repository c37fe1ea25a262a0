#pragma once
// A tool that needs a running workspace says within seconds what is missing, instead of roscpp's endless
// "Failed to contact master ... Retrying".
#include <ros/init.h>
#include <stdexcept>
#include <string>
#include <vector>

namespace vrrw_common
{
/// \brief No (whole) workspace runs; what() is one line: `no workspace at http://localhost:11311: start one
/// with ./vrrw up SCENE`, or the robot / action / service looked for and not found.
class WorkspaceError : public std::runtime_error
{
public:
  explicit WorkspaceError(const std::string& what) : std::runtime_error(what) {}
};

/// \brief What a tool needs of the running workspace.
struct WorkspaceNeeds
{
  std::string robot;                 ///< a robot of the scene (its /scene/robots/<robot> parameters); "" for none
  std::vector<std::string> actions;  ///< action namespaces, e.g. /ur5e/arm_controller/follow_joint_trajectory
  std::vector<std::string> services; ///< e.g. /ur5e/plan
};

/// \brief Checks that a master answers at ROS_MASTER_URI within \a master_seconds, then that every need is
/// there (one look each, no waiting); throws WorkspaceError naming the first thing missing. Call it after
/// ros::init() and before the first NodeHandle: a NodeHandle without a master retries forever.
void checkWorkspace(const WorkspaceNeeds& needs = WorkspaceNeeds(), double master_seconds = 2.0);

/// \brief A command-line tool's node, unregistered from the master when main returns (declare it in main right
/// after ros::init()): without it a tool that returned while its spinner thread ran could stay in `rosnode list`.
struct ToolNode
{
  ToolNode() = default;
  ToolNode(const ToolNode&) = delete;
  ToolNode& operator=(const ToolNode&) = delete;
  ~ToolNode() { ros::shutdown(); }
};

/// \brief True when the master at ROS_MASTER_URI answers within \a seconds.
bool masterAnswers(double seconds);

/// \brief The robots of the running workspace (the keys of /scene/robots), sorted.
std::vector<std::string> workspaceRobots();
}  // namespace vrrw_common

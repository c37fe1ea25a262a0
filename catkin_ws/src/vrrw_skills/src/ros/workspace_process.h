#pragma once
// A workspace of its own for `skill evaluate`: `./vrrw up SCENE --mode physics --rtf R` (the one way a workspace comes
// up) in a process group of its own, on a master port nobody uses, its output in a log; stopped whole.
#include <string>
#include <sys/types.h>

namespace vrrw_skills
{
/// \brief The master port of evaluate's workspace: VRRW_ROS_PORT, else the first free one from 11611. Throws
/// SkillError when VRRW_ROS_PORT is no port or in use (a master there would get a second set of nodes).
int workspacePort();

class WorkspaceProcess
{
public:
  /// \brief Starts it on \a port; the scene is an argument of ./vrrw (argv, no shell). ROS_MASTER_URI of this
  /// process is set to the new master (call before ros::init). Throws SkillRefusal when ./vrrw cannot be found
  /// (VRRW_ROOT) or started.
  /// \a rtf: physics' real-time factor ("max" or a positive number, checked by the caller).
  WorkspaceProcess(const std::string& scene, const std::string& rtf, const std::string& log_file, int port);
  /// \brief Stops the process group: SIGINT, and SIGKILL if it is not gone after 15 s.
  ~WorkspaceProcess();
  WorkspaceProcess(const WorkspaceProcess&) = delete;
  WorkspaceProcess& operator=(const WorkspaceProcess&) = delete;

  const std::string& masterUri() const { return master_uri_; }
  /// \brief False once the process has ended (a bad scene, a crash).
  bool running() const;
  /// \brief The log's last lines that say what went wrong (errors, dead processes).
  std::string trouble() const;

private:
  pid_t pid_ = -1;
  std::string master_uri_;
  std::string log_file_;
};
}  // namespace vrrw_skills

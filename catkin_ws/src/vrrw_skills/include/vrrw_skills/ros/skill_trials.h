#pragma once
// Trials of a skill on a running physics workspace: the object put at a pose, the skill run, judged by the
// demo's rule (lifted, released near the demonstrated place, no arm link but the fingers touched anything).
#include <functional>
#include <mutex>
#include <set>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <ros/ros.h>
#include <vrrw_physics/Contacts.h>

#include <vrrw_common/ros/persistent_service.h>
#include <vrrw_skills/evaluation.h>
#include <vrrw_skills/skill.h>
#include <vrrw_skills/trial_outcome.h>

#include <vrrw_skills/ros/arm_services.h>
#include <vrrw_skills/ros/workspace_arm.h>

namespace vrrw_skills
{
class SkillTrials
{
public:
  /// \brief \a obstacles: the scene's objects (an arm link other than a finger touching one fails a trial);
  /// \a object: the scene object the skill picks. The arm's joints now are its home between trials.
  SkillTrials(ros::NodeHandle& node, const Skill& skill, WorkspaceArm& arm, ArmServices& kinematics,
              vrrw_common::PersistentServices& services, std::string object, std::set<std::string> obstacles);

  /// \brief Trial \a index with the object at \a pose (on the table as the demonstration's start stood): the arm
  /// home and open, the object placed, the skill run, the outcome judged. Progress lines through \a progress,
  /// \a done (when given) at the end of each instruction (SkillRunner::run).
  TrialResult trial(int index, const PlanarPose& pose, const std::function<void(const std::string&)>& progress,
                    const std::function<void(const std::string&)>& done = {});

  /// s of simulated time the object is given to come to rest on the table (placed, or released).
  static constexpr double kSettle = 0.5;

private:
  void onContacts(const vrrw_physics::Contacts::ConstPtr& message);
  void onSample(const ros::TimerEvent&);
  void reset(const Eigen::Isometry3d& object, const std::function<void(const std::string&)>& progress);
  void goHome();

  const Skill& skill_;
  WorkspaceArm& arm_;
  ArmServices& kinematics_;
  vrrw_common::PersistentServices& services_;
  std::string object_;
  std::set<std::string> obstacles_;
  std::vector<double> home_;
  ros::Subscriber contacts_;
  ros::Timer sampler_;

  std::mutex mutex_;                    ///< protects the observation below
  bool watching_ = false;               ///< PROTECTED BY mutex_
  TrialObservation seen_;               ///< PROTECTED BY mutex_
  std::vector<Eigen::Vector3d> path_;   ///< PROTECTED BY mutex_: the TCP at 10 Hz
};
}  // namespace vrrw_skills

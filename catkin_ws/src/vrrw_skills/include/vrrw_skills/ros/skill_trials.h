#pragma once
// Trials of a skill on a running physics workspace in lockstep: the object put at a pose, the skill run, judged by
// the demo's rule (lifted, released near the demonstrated place, no arm link but the fingers touched anything).
// Every observation is taken at simulated stamps (the TCP and the object every 0.1 s, the contacts between the
// trial's start and end), so the same poses give the same trials bit for bit.
#include <condition_variable>
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
  /// \a object: the scene object the skill picks. The arm's joints now are its home between trials. The arm holds
  /// the simulation (WorkspaceArm::holdSimulation); throws SkillError otherwise.
  SkillTrials(ros::NodeHandle& node, const Skill& skill, WorkspaceArm& arm, ArmServices& kinematics,
              vrrw_common::PersistentServices& services, std::string object, std::set<std::string> obstacles);
  ~SkillTrials();
  SkillTrials(const SkillTrials&) = delete;
  SkillTrials& operator=(const SkillTrials&) = delete;

  /// \brief Trial number \a index (from 1) with the object at \a pose (on the table as the demonstration's start stood): the arm
  /// home and open, the object placed, the skill run, the outcome judged. Progress lines through \a progress,
  /// \a done (when given) at the end of each instruction (SkillRunner::run).
  TrialResult trial(int index, const PlanarPose& pose, const std::function<void(const std::string&)>& progress,
                    const std::function<void(const std::string&)>& done = {});

  /// s of simulated time the object is given to come to rest on the table (placed, or released).
  static constexpr double kSettle = 0.5;

private:
  void onContacts(const vrrw_physics::Contacts::ConstPtr& message);
  /// At every stop of the simulation: the TCP and the object at each sample time up to \a stop.
  void sample(const ros::Time& stop);
  /// The trial's observation ends at simulated \a end: waits (wall clock, bounded) for the contacts published there.
  void stopWatching(const ros::Time& end);
  void reset(const Eigen::Isometry3d& object, const std::function<void(const std::string&)>& progress);
  void goHome();

  const Skill& skill_;
  WorkspaceArm& arm_;
  ArmServices& kinematics_;
  vrrw_common::PersistentServices& services_;
  std::string object_;
  std::set<std::string> obstacles_;
  std::vector<double> home_;
  int stop_observer_ = -1;  ///< sample() among the simulation's stop observers

  std::mutex mutex_;                    ///< protects the observation below
  std::condition_variable contacts_arrived_;  ///< a contacts message arrived (stopWatching waits for it)
  bool watching_ = false;               ///< PROTECTED BY mutex_
  ros::Time watch_from_, watch_until_;  ///< PROTECTED BY mutex_: contacts stamped in (from, until] count
  ros::Time next_sample_;               ///< PROTECTED BY mutex_: simulated time of the next sample
  ros::Time contacts_stamp_;            ///< PROTECTED BY mutex_: the latest contacts message's stamp
  TrialObservation seen_;               ///< PROTECTED BY mutex_
  std::vector<Eigen::Vector3d> path_;   ///< PROTECTED BY mutex_: the TCP every 0.1 s of simulated time

  ros::Subscriber contacts_;  ///< last: destroyed first, so no callback runs into freed members
};
}  // namespace vrrw_skills

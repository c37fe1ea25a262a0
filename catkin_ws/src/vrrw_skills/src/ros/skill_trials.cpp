#include <vrrw_skills/ros/skill_trials.h>

#include <chrono>
#include <cmath>
#include <cstdio>

#include <vrrw_msgs/Plan.h>
#include <vrrw_physics/SetObjectPose.h>
#include <vrrw_skills/poses.h>
#include <vrrw_skills/skill_error.h>
#include <vrrw_trajectory/msg_conversions.h>

#include <vrrw_skills/ros/skill_runner.h>

namespace vrrw_skills
{
namespace
{
constexpr double kSamplePeriod = 0.1;  ///< s of simulated time between samples of the TCP and the object
constexpr double kContactsSeconds = 10.0;  ///< wall s the last contacts of a trial may take to arrive
}  // namespace

SkillTrials::SkillTrials(ros::NodeHandle& node, const Skill& skill, WorkspaceArm& arm, ArmServices& kinematics,
                         vrrw_common::PersistentServices& services, std::string object,
                         std::set<std::string> obstacles)
  : skill_(skill)
  , arm_(arm)
  , kinematics_(kinematics)
  , services_(services)
  , object_(object.empty() ? skill.object : std::move(object))
  , obstacles_(std::move(obstacles))
  , home_(arm.joints())
{
  if (!arm.simulation())
    throw SkillError("skill trials run in lockstep: the arm must hold the simulation (WorkspaceArm::holdSimulation)");
  arm.watchFrame(object_);
  stop_observer_ = arm.simulation()->addStopObserver([this](const ros::Time& stop) { sample(stop); });
  // a queue far beyond what one step slice publishes (0.25 s at 100 Hz): no contact message is dropped
  contacts_ = node.subscribe("/physics/contacts", 1000, &SkillTrials::onContacts, this);
}

SkillTrials::~SkillTrials()
{
  arm_.simulation()->removeStopObserver(stop_observer_);
}

void SkillTrials::onContacts(const vrrw_physics::Contacts::ConstPtr& message)
{
  {
    std::lock_guard<std::mutex> lock(mutex_);
    contacts_stamp_ = std::max(contacts_stamp_, message->header.stamp);
    if (watching_ && message->header.stamp > watch_from_ && message->header.stamp <= watch_until_)
      for (const auto& contact : message->contacts)
        if (isArmCollision(contact.body_a, contact.body_b, arm_.robot(), obstacles_))
          seen_.arm_contacts.insert(contact.body_a + "|" + contact.body_b);
  }
  contacts_arrived_.notify_all();
}

void SkillTrials::sample(const ros::Time& stop)
{
  std::lock_guard<std::mutex> lock(mutex_);
  if (!watching_)
    return;
  for (; next_sample_ <= stop; next_sample_ += ros::Duration(kSamplePeriod))
  {
    if (const auto tcp = arm_.poseAt(arm_.tcpLink(), next_sample_))
      path_.push_back(tcp->position);
    if (const auto object = arm_.poseAt(object_, next_sample_))
      seen_.max_lift = std::max(seen_.max_lift, object->position.z() - seen_.object_start.translation().z());
  }
}

void SkillTrials::stopWatching(const ros::Time& end)
{
  std::unique_lock<std::mutex> lock(mutex_);
  watch_until_ = end;
  contacts_arrived_.wait_for(lock, std::chrono::duration<double>(kContactsSeconds),
                             [&] { return contacts_stamp_ >= end; });
  watching_ = false;
}

void SkillTrials::goHome()
{
  if (home_.empty())
    return;
  const auto now = arm_.joints();
  double off = 0.0;
  for (std::size_t j = 0; j < now.size() && j < home_.size(); ++j)
    off = std::max(off, std::abs(now[j] - home_[j]));
  if (off < 1e-3)
    return;
  // first 10 cm straight up: a released object between the open fingers is a start the planner refuses
  const auto tcp = arm_.pose(arm_.tcpLink());
  if (tcp)
  {
    CartesianPose up = *tcp;
    up.position.z() += 0.10;
    const IkAnswer lift = kinematics_.ik(up, now, false);
    if (lift.joints)
    {
      vrrw_trajectory::JointTrajectory motion;
      motion.joint_names = arm_.armJoints();
      const std::vector<double> rest(now.size(), 0.0);
      motion.points = { { 0.0, now, rest, {} }, { 1.0, *lift.joints, rest, {} } };
      arm_.execute("reset", motion);
    }
  }
  vrrw_msgs::Plan plan;
  // from the state where the simulation waits, not the planner's own joint_states (which may lag it)
  plan.request.start.name = arm_.armJoints();
  plan.request.start.position = arm_.joints();
  plan.request.goal_joints.name = arm_.armJoints();
  plan.request.goal_joints.position = home_;
  plan.request.seed = 1;
  services_.call("/" + arm_.robot() + "/plan", plan);
  if (plan.response.error_code != 0)
    throw SkillRefusal("reset: no plan home: " + plan.response.message);
  arm_.execute("reset", vrrw_trajectory::fromMsg(plan.response.trajectory));
}

void SkillTrials::reset(const Eigen::Isometry3d& object, const std::function<void(const std::string&)>& progress)
{
  // open first: a trial that failed holding the object must not carry it home
  const SkillInstruction* open = skill_.instruction("open_gripper");
  arm_.grip("reset", open ? open->gripper_position : 0.0, 0.0);
  goHome();
  vrrw_physics::SetObjectPose place;
  place.request.object = object_;
  const CartesianPose pose = toPose(object);
  place.request.pose.position.x = pose.position.x();
  place.request.pose.position.y = pose.position.y();
  place.request.pose.position.z = pose.position.z();
  place.request.pose.orientation.x = pose.orientation.x();
  place.request.pose.orientation.y = pose.orientation.y();
  place.request.pose.orientation.z = pose.orientation.z();
  place.request.pose.orientation.w = pose.orientation.w();
  services_.call("/physics/set_object_pose", place);
  if (!place.response.success)
    throw SkillRefusal("reset: /physics/set_object_pose: " + place.response.message);
  arm_.settle(kSettle);
  progress("object at (" + std::to_string(pose.position.x()).substr(0, 6) + ", " +
           std::to_string(pose.position.y()).substr(0, 6) + ")");
}

TrialResult SkillTrials::trial(int index, const PlanarPose& pose,
                               const std::function<void(const std::string&)>& progress,
                               const std::function<void(const std::string&)>& done)
{
  TrialResult result;
  result.trial = index;
  result.x = pose.x;
  result.y = pose.y;
  result.yaw_deg = pose.yaw * 180.0 / M_PI;
  const Eigen::Isometry3d start = placeOnTable(toIsometry(skill_.object_start), pose);
  try
  {
    reset(start, progress);
  }
  catch (const SkillRefusal& e)
  {
    result.reason = e.what();
    return result;
  }
  {
    std::lock_guard<std::mutex> lock(mutex_);
    seen_ = TrialObservation();
    seen_.object_start = toIsometry(arm_.pose(object_).value_or(toPose(start)));
    path_.clear();
    watching_ = true;
    watch_from_ = next_sample_ = arm_.now();
    watch_until_ = ros::TIME_MAX;
  }
  SkillRunner runner(skill_, arm_, kinematics_, object_);
  try
  {
    const RunReport run = runner.run(progress, done);
    result.reachable = true;
    result.cycle_seconds = run.cycle_seconds;
    result.planning_ms = 1000.0 * run.planning_seconds;
    std::lock_guard<std::mutex> lock(mutex_);
    seen_.gripper_open_at_end = true;
  }
  catch (const SkillRefusal& e)
  {
    const std::string why = e.what();
    result.reachable = why.find("no IK for its goal") == std::string::npos;
    std::lock_guard<std::mutex> lock(mutex_);
    seen_.failed_instruction = why;
  }
  arm_.settle(kSettle);
  stopWatching(arm_.now());
  std::lock_guard<std::mutex> lock(mutex_);
  const auto end = arm_.pose(object_);
  seen_.object_end = end ? toIsometry(*end) : seen_.object_start;
  const TrialOutcome outcome = judgeTrial(seen_, toIsometry(skill_.object_end));
  result.success = outcome.success;
  result.reason = outcome.reason;
  result.place_error_m = outcome.final_error_m;
  result.place_angle_deg = outcome.final_angle_deg;
  result.object_end = seen_.object_end.translation();
  result.tcp_path = path_;
  return result;
}
}  // namespace vrrw_skills

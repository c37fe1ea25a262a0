// SkillPlanner: goals from keyframes (goalPoses, solveGoals), a motion per arm instruction (joint DMP on the
// taught arm, Cartesian DMP + IK on another or where the joint rollout collides), each checked state by state
// (checkPiece, armStep).
#include <vrrw_skills/skill_plan.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <vrrw_skills/poses.h>
#include <vrrw_skills/skill_error.h>
#include <vrrw_skills/trial_outcome.h>

namespace vrrw_skills
{
namespace
{
/// s: a motion ends at its goal, at rest, this long after the rollout came within its tolerance.
constexpr double kFinish = 0.2;
/// s between the TCP poses of a Cartesian rollout that another arm follows by IK.
constexpr double kIkPeriod = 0.05;
/// rad: a larger change of any joint between two IK solutions along a path is a branch flip.
constexpr double kMaxJump = 0.5;
/// rad: a carry goal re-solved with the measured hold further than this from the planned one is not trusted
/// (the hold slipped a lot: the planned goal is the safer guess).
constexpr double kMaxRetarget = 0.3;
/// rad: within this of the grasp (pick's end) the fingers may touch the object ...
constexpr double kGraspZone = 0.05;
/// rad: ... and within this of the lift's start or the set-down's end the held object what it stands on.
constexpr double kSupportZone = 0.03;

double largestDifference(const std::vector<double>& a, const std::vector<double>& b)
{
  double largest = 0.0;
  for (std::size_t j = 0; j < a.size() && j < b.size(); ++j)
    largest = std::max(largest, std::abs(a[j] - b[j]));
  return largest;
}

std::string seconds(double value)
{
  char text[32];
  std::snprintf(text, sizeof(text), "%.2f s", value);
  return text;
}

/// How much slower \a motion must run for every joint to stay within kVelocityMargin of its velocity and
/// acceleration limits (1: it does already).
double slowdown(const vrrw_trajectory::JointTrajectory& motion, const SkillScene& scene)
{
  double velocity = 0.0, acceleration = 0.0;
  for (const auto& point : motion.points)
    for (std::size_t j = 0; j < point.positions.size(); ++j)
    {
      if (j < scene.max_velocity.size() && j < point.velocities.size() && scene.max_velocity[j] > 0.0)
        velocity = std::max(velocity, std::abs(point.velocities[j]) / scene.max_velocity[j]);
      if (j < scene.max_acceleration.size() && j < point.accelerations.size() && scene.max_acceleration[j] > 0.0)
        acceleration = std::max(acceleration, std::abs(point.accelerations[j]) / scene.max_acceleration[j]);
    }
  const double margin = SkillPlanner::kVelocityMargin;
  return std::max({ 1.0, velocity / margin, std::sqrt(acceleration / margin) });
}

/// Velocities and accelerations by central differences (at rest at both ends).
void addVelocities(vrrw_trajectory::JointTrajectory& motion)
{
  auto& p = motion.points;
  for (std::size_t k = 0; k < p.size(); ++k)
  {
    p[k].velocities.assign(p[k].positions.size(), 0.0);
    p[k].accelerations.assign(p[k].positions.size(), 0.0);
    if (k == 0 || k + 1 == p.size())
      continue;
    const double before = p[k].time - p[k - 1].time, after = p[k + 1].time - p[k].time;
    for (std::size_t j = 0; j < p[k].positions.size(); ++j)
    {
      const double v0 = (p[k].positions[j] - p[k - 1].positions[j]) / before;
      const double v1 = (p[k + 1].positions[j] - p[k].positions[j]) / after;
      p[k].velocities[j] = (p[k + 1].positions[j] - p[k - 1].positions[j]) / (before + after);
      p[k].accelerations[j] = 2.0 * (v1 - v0) / (before + after);
    }
  }
}

void endAtRest(vrrw_trajectory::JointTrajectory& motion, const std::vector<double>& goal)
{
  const double end = motion.points.back().time + kFinish;
  motion.points.push_back({ end, goal, std::vector<double>(goal.size(), 0.0), std::vector<double>(goal.size(), 0.0) });
}
}  // namespace

std::map<std::string, CartesianPose> goalPoses(const Skill& skill, const SkillScene& scene,
                                               const CartesianPose& object_in_hand)
{
  std::map<std::string, CartesianPose> poses;
  for (const SkillInstruction* instruction : skill.armInstructions())
  {
    const Keyframe& end = instruction->end;
    CartesianPose world = end.pose;
    if (end.frame == Frame::object)
      world = inWorld(scene.object, end.pose);
    else if (end.frame == Frame::place)
    {
      if (!scene.place)
        throw SkillRefusal(instruction->name + ": no pose of '" + skill.place_on + "', the object to place on");
      world = inWorld(*scene.place, end.pose);
    }
    if (instruction->name == "final")
    {
      // where the object came to rest in the demonstration, reached with the object held as it is now
      const CartesianPose released = inWorld(world, skill.object_in_hand);
      world = inWorld(released, toPose(toIsometry(object_in_hand).inverse()));
    }
    poses[instruction->name] = world;
  }
  return poses;
}

SkillPlanner::SkillPlanner(const Skill& skill, ArmKinematics& arm) : skill_(skill), arm_(arm)
{
}

bool SkillPlanner::taughtArm(const SkillScene& scene) const
{
  return scene.robot == skill_.robot && scene.arm_joints == skill_.arm_joints;
}

void SkillPlanner::solveGoals(const SkillScene& scene, const CartesianPose& object_in_hand,
                              const std::vector<std::string>& names)
{
  const auto poses = goalPoses(skill_, scene, object_in_hand);
  std::vector<double> seed = scene.joints;
  for (const std::string& name : names)
  {
    const SkillInstruction* instruction = skill_.instruction(name);
    poses_[name] = poses.at(name);
    if (taughtArm(scene))
      seed = instruction->joints_end;
    // near_pick must touch nothing; at the grasp the fingers are around the object, and from there on the
    // object is in the hand: those goals may touch the object where it stands now (the pieces' checks judge
    // the rest)
    const bool touches_object = name != "near_pick";
    const IkAnswer answer = arm_.ik(poses_[name], seed, !touches_object);
    if (!answer.joints)
      throw SkillRefusal(name + ": no IK for its goal: " + answer.reason);
    if (touches_object)
    {
      const ContactPair pair = arm_.checkPath({ *answer.joints }).front();
      if (pair.touching() && pair.a != skill_.object && pair.b != skill_.object)
        throw SkillRefusal(name + ": no IK for its goal: collision (" + pair.a + " - " + pair.b + ")");
    }
    goals_[name] = *answer.joints;
    seed = *answer.joints;
  }
}

vrrw_trajectory::JointTrajectory SkillPlanner::motion(const SkillInstruction& instruction, const SkillScene& scene,
                                                      const std::vector<double>& start,
                                                      const std::vector<double>& goal)
{
  if (!taughtArm(scene))
    return cartesianMotion(instruction, scene, start, goal);
  vrrw_dmp::RolloutRequest request;
  request.start = start;
  request.goal = goal;
  request.dt = 0.01;
  request.tau = instruction.joint_dmp->demoDuration();
  request.goal_tolerance = kSettledWithin;
  vrrw_trajectory::JointTrajectory path = instruction.joint_dmp->rollout(request);
  // a DMP's speed is 1/tau: a rollout over the limits runs again, exactly as much slower as it needs
  const double over = slowdown(path, scene);
  if (over > 1.0)
  {
    request.tau *= over;
    path = instruction.joint_dmp->rollout(request);
  }
  path.joint_names = scene.arm_joints;
  endAtRest(path, goal);
  return path;
}

vrrw_trajectory::JointTrajectory SkillPlanner::cartesianMotion(const SkillInstruction& instruction,
                                                               const SkillScene& scene, const std::vector<double>& start,
                                                               const std::vector<double>& goal)
{
  vrrw_dmp::CartesianRolloutRequest request;
  request.start = arm_.tcp(start);
  request.goal = poses_.at(instruction.name);
  request.dt = kIkPeriod;
  const auto path = instruction.cartesian_dmp->rollout(request);
  vrrw_trajectory::JointTrajectory out;
  out.joint_names = scene.arm_joints;
  out.points.push_back({ 0.0, start, {}, {} });
  std::vector<double> seed = start;
  for (std::size_t k = 1; k + 1 < path.size(); ++k)
  {
    const IkAnswer answer = arm_.ik(path[k].pose, seed, false);
    if (!answer.joints)
      throw SkillRefusal(instruction.name + ": no IK at " + seconds(path[k].time) + " of its TCP path: " +
                         answer.reason);
    if (largestDifference(*answer.joints, seed) > kMaxJump)
      throw SkillRefusal(instruction.name + ": the arm would turn over at " + seconds(path[k].time) +
                         " of its TCP path (a joint jumps more than 0.5 rad between IK solutions)");
    seed = *answer.joints;
    out.points.push_back({ path[k].time, seed, {}, {} });
  }
  out.points.push_back({ path.back().time, goal, {}, {} });
  addVelocities(out);
  const double over = slowdown(out, scene);
  if (over > 1.0)
  {
    for (auto& point : out.points)
      point.time *= over;
    addVelocities(out);
  }
  endAtRest(out, goal);
  return out;
}

void SkillPlanner::checkPiece(const std::string& instruction, const vrrw_trajectory::JointTrajectory& motion)
{
  const std::vector<double>& start = motion.points.front().positions;
  const std::vector<double>& goal = motion.points.back().positions;
  // The states kCheckStep apart (and the last), checked in one call
  std::vector<std::size_t> sampled;
  std::vector<std::vector<double>> states;
  for (std::size_t k = 0; k < motion.points.size(); ++k)
  {
    const auto& q = motion.points[k].positions;
    if (!states.empty() && k + 1 < motion.points.size() && largestDifference(q, states.back()) < kCheckStep)
      continue;
    sampled.push_back(k);
    states.push_back(q);
  }
  const std::vector<ContactPair> pairs = arm_.checkPath(states);
  for (std::size_t i = 0; i < sampled.size(); ++i)
  {
    const ContactPair& pair = pairs.at(i);
    if (!pair.touching())
      continue;
    const auto& q = states[i];
    const bool object = pair.a == skill_.object || pair.b == skill_.object;
    const std::string& other = pair.a == skill_.object ? pair.b : pair.a;
    if (object && instruction == "pick" && isFingerLink(other) && largestDifference(q, goal) < kGraspZone)
      continue;
    if (object && instruction == "back_to_near_pick" && largestDifference(q, start) < kSupportZone)
      continue;
    if (object && instruction == "final" && largestDifference(q, goal) < kSupportZone)
      continue;
    throw SkillRefusal(instruction + ": collision on the way: " + pair.a + " would touch " + pair.b + " at " +
                       seconds(motion.points[sampled[i]].time));
  }
}

PlannedStep SkillPlanner::armStep(const std::string& name, const SkillScene& scene, const std::vector<double>& from)
{
  const SkillInstruction& instruction = *skill_.instruction(name);
  const std::vector<double>& goal = goals_.at(name);
  PlannedStep step;
  step.instruction = name;
  step.cartesian = !taughtArm(scene);
  if (name == "final")
    step.goal_tolerance = kSetDownTolerance;
  step.trajectory = motion(instruction, scene, from, goal);
  try
  {
    checkPiece(name, step.trajectory);
    return step;
  }
  catch (const SkillRefusal& joint_refusal)
  {
    if (step.cartesian)
      throw;
    try
    {
      step.trajectory = cartesianMotion(instruction, scene, from, goal);
      step.cartesian = true;
      checkPiece(name, step.trajectory);
      return step;
    }
    catch (const SkillRefusal& cartesian_refusal)
    {
      const std::string why = cartesian_refusal.what();
      throw SkillRefusal(std::string(joint_refusal.what()) + " (along the Cartesian DMP too: " +
                         why.substr(why.find(": ") + 2) + ")");
    }
  }
}

PlannedStep SkillPlanner::gripperStep(const std::string& name) const
{
  PlannedStep step;
  step.instruction = name;
  step.gripper = true;
  const SkillInstruction* instruction = skill_.instruction(name);
  step.gripper_position = instruction->gripper_position;
  step.gripper_effort = instruction->gripper_effort;
  return step;
}

std::vector<PlannedStep> SkillPlanner::approach(const SkillScene& scene)
{
  goals_.clear();
  poses_.clear();
  std::vector<std::string> names;
  for (const SkillInstruction* instruction : skill_.armInstructions())
    names.push_back(instruction->name);
  solveGoals(scene, skill_.object_in_hand, names);
  std::vector<PlannedStep> steps;
  std::vector<double> from = scene.joints;
  for (const char* name : { "near_pick", "pick" })
  {
    steps.push_back(armStep(name, scene, from));
    from = goals_.at(name);
  }
  steps.push_back(gripperStep("close_gripper"));
  return steps;
}

std::vector<PlannedStep> SkillPlanner::carry(const SkillScene& scene, const CartesianPose& object_in_hand)
{
  // the place's goal again, from how the object is held now; the retreat's stays (it belongs to where the
  // object stood)
  const std::vector<double> planned = goals_.at("final");
  const CartesianPose place = goalPoses(skill_, scene, object_in_hand).at("final");
  const IkAnswer answer = arm_.ik(place, planned, false);
  if (answer.joints && largestDifference(*answer.joints, planned) < kMaxRetarget)
  {
    goals_["final"] = *answer.joints;
    poses_["final"] = place;
  }
  std::vector<PlannedStep> steps;
  std::vector<double> from = scene.joints;
  for (const char* name : { "back_to_near_pick", "final" })
  {
    if (!skill_.instruction(name))
      continue;
    steps.push_back(armStep(name, scene, from));
    from = goals_.at(name);
  }
  steps.push_back(gripperStep("open_gripper"));
  return steps;
}
}  // namespace vrrw_skills

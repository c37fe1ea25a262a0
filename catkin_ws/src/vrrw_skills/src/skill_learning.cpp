// learnSkill: per demonstration the robot's track, the object, the instructions and the TCP (taught()), then
// keyframes, DMPs and gripper actions per instruction, then the mean over the demonstrations.
#include <vrrw_skills/skill_learning.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>

#include <vrrw_demos/demo_error.h>
#include <vrrw_demos/tcp_kinematics.h>
#include <vrrw_dmp/dmp.h>
#include <vrrw_dmp/dmp_error.h>
#include <vrrw_skills/poses.h>
#include <vrrw_skills/skill_error.h>

namespace vrrw_skills
{
namespace
{
using vrrw_demos::Demonstration;
using vrrw_demos::RobotTrack;
using vrrw_demos::Segment;

/// s: a pause longer than this is cut to this much of a straight bridge (the arm drifts a little while it rests:
/// a hold, the payload's sag, so the learned path has no step); shorter stops are kept as shown. A person's
/// hesitation goes, a stop that belongs to the motion stays: the drill, held by friction, stops swinging in the
/// half second above the place the demo's carry rests there (cut to 0.1 s, one of 20 trials toppled it).
constexpr double kBridge = 0.5;
/// m: an object that moved less than this between the start and the end of a recording never moved.
constexpr double kObjectMoved = 0.005;
/// s: an instruction moving longer than this (its pauses cut) is refused: a DMP of it would need more basis
/// functions than a skill has, and its samples (at the sample period) more memory than a skill is worth.
constexpr double kLongestMotion = 600.0;

/// What one demonstration shows.
struct Taught
{
  const Demonstration* demo = nullptr;
  const RobotTrack* track = nullptr;
  std::map<std::string, Segment> segments;
  CartesianPose object_start, object_end, place_start;
  std::vector<double> home;
  std::shared_ptr<const vrrw_demos::TcpKinematics> tcp;  ///< by the bag's own URDF
};

std::string where(const Demonstration& demo)
{
  return demo.source.empty() ? std::string("demonstration") : demo.source;
}

std::string names(const std::vector<std::string>& list)
{
  std::string out;
  for (const std::string& name : list)
    out += (out.empty() ? "" : ", ") + name;
  return out.empty() ? "none" : out;
}

const RobotTrack& taughtTrack(const Demonstration& demo, const std::string& robot)
{
  std::vector<std::string> found;
  for (const RobotTrack& track : demo.robots)
    found.push_back(track.robot);
  if (demo.robots.empty())
    throw SkillError(where(demo) + ": joint_states: no robot's joint states recorded (a bag of `./vrrw record` "
                     "or /demos/start has them)");
  if (robot.empty())
  {
    if (demo.robots.size() != 1)
      throw SkillError(where(demo) + ": robots: " + std::to_string(demo.robots.size()) + " recorded (" + names(found) +
                       "): choose one with --robot");
    return demo.robots.front();
  }
  const RobotTrack* track = demo.robot(robot);
  if (!track)
    throw SkillError(where(demo) + ": --robot " + robot + ": no joint_states of that robot (the bag has: " +
                     names(found) + ")");
  return *track;
}

CartesianPose objectPose(const Demonstration& demo, const std::string& object, double t)
{
  const vrrw_demos::Pose* pose = vrrw_demos::objectPoseAt(demo, object, t);
  if (!pose)
  {
    std::vector<std::string> found;
    for (const auto& entry : demo.objects)
      found.push_back(entry.first);
    throw SkillError(where(demo) + ": /tf: no pose of object '" + object + "' (objects in the bag: " + names(found) +
                     ")");
  }
  return toPose(vrrw_demos::toIsometry(*pose));
}

std::map<std::string, Segment> instructions(const Demonstration& demo, const RobotTrack& track,
                                            const LearnOptions& options)
{
  const vrrw_demos::Segmentation segmentation = vrrw_demos::segmentPickPlace(track, demo, options.segmentation);
  std::map<std::string, Segment> found;
  for (const Segment& segment : segmentation.segments)
    found[segment.name] = segment;
  const std::string robot = where(demo) + ": robot '" + track.robot + "': ";
  const std::string why = segmentation.warnings.empty() ? "" : " (" + names(segmentation.warnings) + ")";
  if (!found.count("close_gripper"))
    throw SkillError(robot + "the gripper never closed after the arm moved: no close_gripper" + why);
  if (!found.count("open_gripper"))
    throw SkillError(robot + "the gripper never opened after it closed: no open_gripper" + why);
  for (const char* name : { "near_pick", "pick", "final" })
    if (!found.count(name))
      throw SkillError(robot + "no " + name + " instruction" + why);
  const std::string& held = found["close_gripper"].object;
  if (held.empty())
    throw SkillError(robot + "no object moved while the gripper was closed (more than " +
                     std::to_string(int(options.segmentation.object_moved * 1000)) + " mm)");
  if (held != options.object)
    throw SkillError(robot + "the gripper held '" + held + "' (it moved most while closed), not --object " +
                     options.object);
  return found;
}

Taught taught(const Demonstration& demo, const LearnOptions& options)
{
  Taught out;
  out.demo = &demo;
  out.track = &taughtTrack(demo, options.robot);
  if (out.track->states.size() < 3)
    throw SkillError(where(demo) + ": /" + out.track->robot + "/joint_states: " +
                     std::to_string(out.track->states.size()) + " states, too few to learn from");
  const double end = out.track->states.back().time;
  out.object_start = objectPose(demo, options.object, 0.0);
  out.object_end = objectPose(demo, options.object, end);
  const double moved = positionDistance(out.object_start, out.object_end);
  if (moved < kObjectMoved)
    throw SkillError(where(demo) + ": /tf: object '" + options.object + "' never moved (" +
                     std::to_string(moved * 1000).substr(0, 4) + " mm from the start to the end of the recording)");
  if (!options.place_on.empty())
    out.place_start = objectPose(demo, options.place_on, 0.0);
  out.segments = instructions(demo, *out.track, options);
  out.home = out.track->states.front().positions;
  out.tcp = std::make_shared<const vrrw_demos::TcpKinematics>(demo, *out.track);
  return out;
}

double jointFitRmse(const vrrw_dmp::Dmp& dmp, const vrrw_trajectory::JointTrajectory& motion)
{
  vrrw_dmp::RolloutRequest request;
  request.dt = std::min(0.002, dmp.demoDuration() / 100.0);
  const auto rollout = dmp.rollout(request);
  double sum = 0.0;
  std::size_t count = 0;
  for (const auto& point : motion.points)
  {
    const auto k = std::min(static_cast<std::size_t>(point.time / request.dt), rollout.points.size() - 2);
    const double u = std::min(1.0, (point.time - rollout.points[k].time) / request.dt);
    for (std::size_t j = 0; j < point.positions.size(); ++j, ++count)
    {
      const double q = (1.0 - u) * rollout.points[k].positions[j] + u * rollout.points[k + 1].positions[j];
      sum += (q - point.positions[j]) * (q - point.positions[j]);
    }
  }
  return std::sqrt(sum / static_cast<double>(std::max<std::size_t>(count, 1)));
}

/// The frame a keyframe of \a instruction's end belongs to.
Frame endFrame(const std::string& instruction, const LearnOptions& options)
{
  if (instruction == "final")
    return options.place_on.empty() ? Frame::world : Frame::place;
  return Frame::object;
}

Keyframe keyframe(Frame frame, const CartesianPose& tcp, const Taught& demo)
{
  switch (frame)
  {
    case Frame::object:
      return { frame, relativeTo(demo.object_start, tcp) };
    case Frame::place:
      return { frame, relativeTo(demo.place_start, tcp) };
    case Frame::world:
      break;
  }
  return { Frame::world, tcp };
}

SkillInstruction armInstruction(const Taught& demo, const Segment& segment, Frame start_frame,
                                const LearnOptions& options)
{
  const RobotTrack& track = *demo.track;
  const vrrw_demos::TcpKinematics& tcp = *demo.tcp;
  SkillInstruction out;
  out.name = segment.name;
  out.duration = segment.end - segment.start;
  out.joints_start = vrrw_demos::stateAt(track, segment.start).positions;
  out.joints_end = vrrw_demos::stateAt(track, segment.end).positions;
  out.start = keyframe(start_frame, toPose(tcp.at(out.joints_start)), demo);
  out.end = keyframe(endFrame(segment.name, options), toPose(tcp.at(out.joints_end)), demo);
  if (segment.end - segment.start > 6.0 * kLongestMotion)  // before resampling it: pauses and all
    throw SkillError(where(*demo.demo) + ": " + segment.name + ": " + std::to_string(int(segment.end - segment.start)) +
                     " s long, more than the " + std::to_string(int(6.0 * kLongestMotion)) +
                     " s a skill learns an instruction from");
  const auto motion = motionWithoutPauses(track, segment.start, segment.end, options.sample_period,
                                          options.segmentation);
  if (motion.duration() > kLongestMotion)
    throw SkillError(where(*demo.demo) + ": " + segment.name + ": " + std::to_string(int(motion.duration())) +
                     " s of motion, more than the " + std::to_string(int(kLongestMotion)) +
                     " s a skill learns an instruction from");
  std::vector<vrrw_dmp::CartesianSample> path;
  for (const auto& point : motion.points)
  {
    vrrw_dmp::CartesianSample sample;
    sample.time = point.time;
    sample.pose = toPose(tcp.at(point.positions));
    path.push_back(sample);
  }
  vrrw_dmp::DmpProvenance provenance;
  provenance.source = where(*demo.demo) + " robot " + track.robot + " segment " + segment.name;
  try
  {
    out.joint_dmp = vrrw_dmp::Dmp::learn(motion, options.parameters, provenance);
    out.cartesian_dmp = vrrw_dmp::CartesianDmp::learn(path, options.parameters, provenance);
  }
  catch (const vrrw_dmp::DmpError& e)
  {
    throw SkillError(where(*demo.demo) + ": " + segment.name + ": " + e.what());
  }
  out.joint_fit_rmse = jointFitRmse(*out.joint_dmp, motion);
  const vrrw_dmp::CartesianFit fit = vrrw_dmp::reproductionError(*out.cartesian_dmp, path);
  out.cartesian_fit_rmse = fit.position_rmse;
  out.cartesian_fit_rmse_deg = fit.angle_rmse * 180.0 / M_PI;
  return out;
}

SkillInstruction gripperInstruction(const Taught& demo, const Segment& segment)
{
  SkillInstruction out;
  out.name = segment.name;
  out.gripper = true;
  out.duration = segment.end - segment.start;
  out.gripper_position = segment.gripper_target;
  // the goal that started it: the last one sent before its end
  for (const vrrw_demos::GripperGoal& goal : demo.track->gripper_goals)
    if (goal.time <= segment.end + 1e-9)
    {
      out.gripper_position = goal.position;
      out.gripper_effort = goal.max_effort;
    }
  out.gripper_reached = vrrw_demos::stateAt(*demo.track, segment.end).gripper;
  return out;
}

/// The instructions of one demonstration, in the paper's order.
std::vector<SkillInstruction> instructionsOf(const Taught& demo, const LearnOptions& options)
{
  std::vector<SkillInstruction> out;
  Frame previous_end = Frame::world;
  for (const char* name : vrrw_demos::kSegmentNames)
  {
    const auto found = demo.segments.find(name);
    if (found == demo.segments.end())
      continue;
    if (found->second.gripper)
    {
      out.push_back(gripperInstruction(demo, found->second));
      continue;
    }
    out.push_back(armInstruction(demo, found->second, previous_end, options));
    previous_end = out.back().end.frame;
  }
  return out;
}

/// The mean over the demonstrations of what \a all[0] shows of each instruction (keyframes, durations, gripper).
std::vector<SkillInstruction> mean(const std::vector<std::vector<SkillInstruction>>& all)
{
  std::vector<SkillInstruction> out = all.front();
  for (std::size_t i = 0; i < out.size(); ++i)
  {
    std::vector<CartesianPose> starts, ends;
    double duration = 0.0, position = 0.0, reached = 0.0, effort = 0.0;
    std::size_t count = 0;
    for (const auto& instructions : all)
      for (const SkillInstruction& other : instructions)
        if (other.name == out[i].name)
        {
          starts.push_back(other.start.pose);
          ends.push_back(other.end.pose);
          duration += other.duration;
          position += other.gripper_position;
          reached += other.gripper_reached;
          effort += other.gripper_effort;
          ++count;
        }
    out[i].duration = duration / count;
    if (out[i].gripper)
    {
      out[i].gripper_position = position / count;
      out[i].gripper_reached = reached / count;
      out[i].gripper_effort = effort / count;
      continue;
    }
    out[i].start.pose = averagePose(starts);
    out[i].end.pose = averagePose(ends);
  }
  return out;
}

void checkSameTask(const Taught& first, const Taught& other)
{
  if (other.track->robot != first.track->robot || other.track->joint_names != first.track->joint_names)
    throw SkillError(where(*other.demo) + ": robot '" + other.track->robot + "' (joints " +
                     names(other.track->joint_names) + ") is not the robot of " + where(*first.demo) + " ('" +
                     first.track->robot + "', joints " + names(first.track->joint_names) +
                     "): a skill is learned from demonstrations of one robot");
}
}  // namespace

vrrw_dmp::DmpParameters skillDmpParameters()
{
  vrrw_dmp::DmpParameters parameters;
  parameters.basis_count = 30;
  parameters.scaling = vrrw_dmp::AmplitudeScaling::automatic;
  parameters.still_range = 0.02;
  return parameters;
}

vrrw_trajectory::JointTrajectory motionWithoutPauses(const RobotTrack& track, double start, double end,
                                                     double period, const vrrw_demos::SegmentationOptions& options)
{
  // the motions, those less than a bridge apart kept as one
  std::vector<std::pair<double, double>> motions;
  for (const auto& motion : vrrw_demos::armMotions(vrrw_demos::slice(track, start, end), options))
  {
    if (!(motion.second > motion.first))
      continue;
    if (!motions.empty() && motion.first - motions.back().second < kBridge)
      motions.back().second = std::min(motion.second, end);
    else
      motions.push_back({ std::max(motion.first, start), std::min(motion.second, end) });
  }
  if (motions.empty())
    motions.push_back({ start, end });
  motions.front().first = start;
  motions.back().second = end;
  // the kept stretches end to end on one clock: [t0, t1] of the recording runs at offset + (t - t0)
  struct Stretch
  {
    double from, to, offset;
  };
  std::vector<Stretch> stretches;
  double offset = 0.0;
  for (const auto& motion : motions)
  {
    stretches.push_back({ motion.first, motion.second, offset });
    offset += motion.second - motion.first + kBridge;
  }
  const double total = offset - kBridge;
  vrrw_trajectory::JointTrajectory out;
  out.joint_names = track.joint_names;
  const auto count = static_cast<std::size_t>(std::ceil(total / period - 1e-9));
  std::size_t s = 0;
  for (std::size_t k = 0; k <= count; ++k)
  {
    const double t = std::min(static_cast<double>(k) * period, total);
    while (s + 1 < stretches.size() && t > stretches[s].offset + (stretches[s].to - stretches[s].from))
      ++s;
    const Stretch& here = stretches[s];
    const double into = t - here.offset;
    std::vector<double> q;
    if (into <= here.to - here.from || s + 1 == stretches.size())
      q = vrrw_demos::stateAt(track, here.from + std::min(into, here.to - here.from)).positions;
    else
    {
      // in the bridge to the next stretch: straight from this one's end to its start
      const double u = (into - (here.to - here.from)) / kBridge;
      const auto a = vrrw_demos::stateAt(track, here.to).positions;
      const auto b = vrrw_demos::stateAt(track, stretches[s + 1].from).positions;
      q.resize(a.size());
      for (std::size_t j = 0; j < a.size(); ++j)
        q[j] = a[j] + u * (b[j] - a[j]);
    }
    out.points.push_back({ t, q, {}, {} });
    if (t >= total)
      break;
  }
  return out;
}

Skill learnSkill(const std::vector<Demonstration>& demos, const LearnOptions& options)
{
  if (demos.empty())
    throw SkillError("skill learn: no demonstration given");
  if (options.object.empty())
    throw SkillError("skill learn: --object: required (the object the demonstration picks)");
  std::vector<Taught> shown;
  for (const Demonstration& demo : demos)
  {
    shown.push_back(taught(demo, options));
    checkSameTask(shown.front(), shown.back());
  }
  std::vector<std::vector<SkillInstruction>> all;
  std::vector<CartesianPose> starts, ends, in_hand, places;
  Skill skill;
  for (const Taught& demo : shown)
  {
    all.push_back(instructionsOf(demo, options));
    starts.push_back(demo.object_start);
    ends.push_back(demo.object_end);
    places.push_back(demo.place_start);
    // where the object came to rest, in the frame of the TCP that let it go: a drill that swung in the grip
    // during a quick carry was released tilted 7 deg on one edge and fell flat (its pose when the gripper
    // opened made every run tilt the drill as much, and it toppled)
    const Segment& open = demo.segments.at("open_gripper");
    const CartesianPose releasing = toPose(demo.tcp->at(vrrw_demos::stateAt(*demo.track, open.start)));
    in_hand.push_back(relativeTo(releasing, demo.object_end));
    SkillSource source;
    source.bag = demo.demo->source;
    source.scene = demo.demo->metadata.scene;
    source.vrrw_version = demo.demo->metadata.vrrw_version;
    source.start_stamp = demo.demo->start_stamp;
    for (const char* name : vrrw_demos::kSegmentNames)
      if (demo.segments.count(name))
        source.segments.push_back({ name, demo.segments.at(name).start, demo.segments.at(name).end });
    skill.sources.push_back(source);
  }
  const Taught& first = shown.front();
  skill.robot = first.track->robot;
  skill.arm_joints = first.track->joint_names;
  skill.gripper_joint = first.track->gripper_joint;
  const auto robot = first.demo->metadata.robots.find(skill.robot);
  skill.tcp_link = robot == first.demo->metadata.robots.end() ? "" : robot->second.tcp_link;
  skill.joints_home = first.home;
  skill.object = options.object;
  skill.place_on = options.place_on;
  skill.object_start = averagePose(starts);
  skill.object_end = averagePose(ends);
  if (!options.place_on.empty())
    skill.place_start = averagePose(places);
  skill.object_in_hand = averagePose(in_hand);
  skill.instructions = mean(all);
  skill.created = vrrw_dmp::utcNow();
  skill.tool = "vrrw_skills 0.1.0";
  return skill;
}
}  // namespace vrrw_skills

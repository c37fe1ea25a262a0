#include <vrrw_evaluation/instruction_dmps.h>
#include <vrrw_evaluation/pick_place_task.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace vrrw_evaluation
{
namespace
{
/// The largest |velocity| / limit over the trajectory's points and joints; 0 without limits.
double peakVelocityRatio(const vrrw_trajectory::JointTrajectory& motion, const std::vector<double>& max_velocity)
{
  double ratio = 0.0;
  for (const auto& point : motion.points)
    for (std::size_t j = 0; j < max_velocity.size() && j < point.velocities.size(); ++j)
      if (max_velocity[j] > 0.0)
        ratio = std::max(ratio, std::abs(point.velocities[j]) / max_velocity[j]);
  return ratio;
}
}  // namespace

InstructionDmps::InstructionDmps(const Demonstration& demo, const vrrw_dmp::DmpParameters& parameters)
{
  for (const Segment& segment : demo.segments)
  {
    if (isGripperInstruction(segment.name))
      continue;
    const vrrw_trajectory::JointTrajectory motion = slice(demo.arm, segment.start, segment.end);
    vrrw_dmp::DmpProvenance provenance;
    provenance.source = "demonstration#" + segment.name;
    vrrw_dmp::Dmp dmp = vrrw_dmp::Dmp::learn(motion, parameters, provenance);
    vrrw_dmp::RolloutRequest request;
    request.dt = 0.01;
    fit_rmse_[segment.name] = jointRms(motion, dmp.rollout(request));
    dmps_.emplace(segment.name, std::move(dmp));
    names_.push_back(segment.name);
  }
}

const vrrw_dmp::Dmp& InstructionDmps::dmp(const std::string& instruction) const
{
  const auto found = dmps_.find(instruction);
  if (found == dmps_.end())
    throw std::invalid_argument("no DMP learned for instruction '" + instruction + "'");
  return found->second;
}

vrrw_trajectory::JointTrajectory InstructionDmps::rollout(const std::string& instruction,
                                                          const std::vector<double>& start,
                                                          const std::vector<double>& goal, double dt,
                                                          const std::vector<double>& max_velocity) const
{
  vrrw_dmp::RolloutRequest request;
  request.start = start;
  request.goal = goal;
  request.dt = dt;
  request.tau = dmp(instruction).demoDuration();
  vrrw_trajectory::JointTrajectory motion = dmp(instruction).rollout(request);
  // A DMP's speed is 1/tau: a rollout over the limits runs again, exactly as much slower as it needs.
  const double over = peakVelocityRatio(motion, max_velocity) / kVelocityMargin;
  if (over > 1.0)
  {
    request.tau *= over;
    motion = dmp(instruction).rollout(request);
  }
  // The spring's tail creeps over the last millirad for up to 3 tau: end at the goal, at rest, once within
  // kSettledWithin of it after tau (the controller's last segment covers the rest).
  const double tau = request.tau;
  for (std::size_t k = 0; k < motion.points.size(); ++k)
  {
    double off = 0.0;
    for (std::size_t j = 0; j < goal.size(); ++j)
      off = std::max(off, std::abs(motion.points[k].positions[j] - goal[j]));
    if (motion.points[k].time >= tau && off < kSettledWithin)
    {
      const double end = motion.points[k].time + 0.2;
      motion.points.resize(k + 1);
      motion.points.push_back({ end, goal, std::vector<double>(goal.size(), 0.0), std::vector<double>(goal.size(), 0.0) });
      break;
    }
  }
  return motion;
}
}  // namespace vrrw_evaluation

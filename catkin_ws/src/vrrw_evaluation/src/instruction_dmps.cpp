#include <vrrw_evaluation/instruction_dmps.h>
#include <vrrw_evaluation/pick_place_task.h>

#include <stdexcept>

namespace vrrw_evaluation
{
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
                                                          const std::vector<double>& goal, double dt) const
{
  vrrw_dmp::RolloutRequest request;
  request.start = start;
  request.goal = goal;
  request.dt = dt;
  request.goal_tolerance = 1e-3;
  request.rest_tolerance = 1e-2;
  return dmp(instruction).rollout(request);
}
}  // namespace vrrw_evaluation

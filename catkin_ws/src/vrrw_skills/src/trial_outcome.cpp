#include <vrrw_skills/trial_poses.h>
#include <vrrw_skills/trial_outcome.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace vrrw_skills
{
double planarDistance(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b)
{
  return (a.translation() - b.translation()).head<2>().norm();
}

double yawDifferenceDeg(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b)
{
  return std::abs(std::remainder(planarPose(a).yaw - planarPose(b).yaw, 2 * M_PI)) * 180.0 / M_PI;
}

TrialOutcome judgeTrial(const TrialObservation& seen, const Eigen::Isometry3d& demonstrated_end,
                        const SuccessCriteria& criteria)
{
  TrialOutcome outcome;
  outcome.final_error_m = planarDistance(seen.object_end, demonstrated_end);
  outcome.final_angle_deg = yawDifferenceDeg(seen.object_end, demonstrated_end);
  std::ostringstream why;
  if (!seen.failed_instruction.empty())
    why << seen.failed_instruction;
  else if (!seen.arm_contacts.empty())
    why << "arm collision: " << *seen.arm_contacts.begin();
  else if (seen.max_lift < criteria.min_lift)
    why << "not lifted: rose " << seen.max_lift * 100 << " cm (< " << criteria.min_lift * 100 << " cm)";
  else if (!seen.gripper_open_at_end)
    why << "not released";
  else if (std::acos(std::min(1.0, seen.object_end.rotation()(2, 2))) * 180.0 / M_PI > criteria.max_tilt_deg)
    why << "toppled: tilted " << std::acos(std::min(1.0, seen.object_end.rotation()(2, 2))) * 180.0 / M_PI
        << " deg at the end";
  else if (outcome.final_error_m > criteria.final_radius)
    why << "released " << outcome.final_error_m * 100 << " cm from the demonstrated final position (> "
        << criteria.final_radius * 100 << " cm)";
  outcome.reason = why.str();
  outcome.success = outcome.reason.empty();
  return outcome;
}

bool isFingerLink(const std::string& link)
{
  return link.find("finger") != std::string::npos || link.find("knuckle") != std::string::npos;
}

bool isArmCollision(const std::string& body_a, const std::string& body_b, const std::string& robot,
                    const std::set<std::string>& obstacles)
{
  const std::string prefix = robot + "_";
  auto ofRobot = [&](const std::string& body) { return body.rfind(prefix, 0) == 0 && !isFingerLink(body); };
  return (ofRobot(body_a) && obstacles.count(body_b)) || (ofRobot(body_b) && obstacles.count(body_a));
}
}  // namespace vrrw_skills

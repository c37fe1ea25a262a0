#include <vrrw_skills/ros/arm_services.h>

#include <vrrw_msgs/AttachObject.h>
#include <vrrw_msgs/CheckPath.h>
#include <vrrw_msgs/ComputeFK.h>
#include <vrrw_msgs/ComputeIK.h>
#include <vrrw_skills/skill_error.h>

namespace vrrw_skills
{
namespace
{
/// vrrw_kinematics::ErrorCode values as the services answer them.
enum Code
{
  kNoSolution = 5,
  kOutsideLimits = 6,
  kInCollision = 7,
  kJointJump = 10,
};

std::string ikReason(int code, const std::string& message)
{
  switch (code)
  {
    case kNoSolution:
      return "out of reach (" + message + ")";
    case kOutsideLimits:
      return "joint limits (" + message + ")";
    case kInCollision:
      return "collision (" + message + ")";
    case kJointJump:
      return "the arm would turn over (" + message + ")";
    default:
      return message;
  }
}
}  // namespace

ArmServices::ArmServices(vrrw_common::PersistentServices& services, std::string robot,
                         std::vector<std::string> arm_joints)
  : services_(services), robot_(std::move(robot)), arm_joints_(std::move(arm_joints))
{
}

IkAnswer ArmServices::ik(const CartesianPose& tcp, const std::vector<double>& seed, bool avoid_collisions)
{
  vrrw_msgs::ComputeIK srv;
  srv.request.pose.header.frame_id = "world";
  srv.request.pose.pose.position.x = tcp.position.x();
  srv.request.pose.pose.position.y = tcp.position.y();
  srv.request.pose.pose.position.z = tcp.position.z();
  srv.request.pose.pose.orientation.x = tcp.orientation.x();
  srv.request.pose.pose.orientation.y = tcp.orientation.y();
  srv.request.pose.pose.orientation.z = tcp.orientation.z();
  srv.request.pose.pose.orientation.w = tcp.orientation.w();
  srv.request.seed.name = arm_joints_;
  srv.request.seed.position = seed;
  srv.request.avoid_collisions = avoid_collisions;
  srv.request.timeout = 0.02;
  services_.call("/" + robot_ + "/compute_ik", srv);
  IkAnswer answer;
  if (srv.response.error_code == 0)
    answer.joints = srv.response.solution.position;
  else
    answer.reason = ikReason(srv.response.error_code, srv.response.message);
  return answer;
}

std::vector<ContactPair> ArmServices::checkPath(const std::vector<std::vector<double>>& path)
{
  std::vector<ContactPair> pairs;
  const std::size_t chunk = vrrw_msgs::CheckPath::Request::MAX_POINTS;
  for (std::size_t first = 0; first < path.size(); first += chunk)
  {
    vrrw_msgs::CheckPath srv;
    srv.request.path.joint_names = arm_joints_;
    for (std::size_t k = first; k < path.size() && k < first + chunk; ++k)
    {
      srv.request.path.points.emplace_back();
      srv.request.path.points.back().positions = path[k];
    }
    services_.call("/" + robot_ + "/check_path", srv);
    const std::size_t n = srv.request.path.points.size();
    if (srv.response.error_code != 0 || srv.response.link_a.size() != n || srv.response.link_b.size() != n ||
        srv.response.limit_violation.size() != n)
      throw SkillRefusal("/" + robot_ + "/check_path: " + srv.response.message);
    for (std::size_t k = 0; k < n; ++k)
      if (!srv.response.limit_violation[k].empty())
        pairs.push_back({ "joint limits", srv.response.limit_violation[k] });
      else
        pairs.push_back({ srv.response.link_a[k], srv.response.link_b[k] });
  }
  return pairs;
}

CartesianPose ArmServices::tcp(const std::vector<double>& joints)
{
  vrrw_msgs::ComputeFK srv;
  srv.request.joint_state.name = arm_joints_;
  srv.request.joint_state.position = joints;
  services_.call("/" + robot_ + "/compute_fk", srv);
  if (srv.response.error_code != 0)
    throw SkillRefusal("/" + robot_ + "/compute_fk: " + srv.response.message);
  const auto& p = srv.response.pose.pose;
  CartesianPose pose;
  pose.position = Eigen::Vector3d(p.position.x, p.position.y, p.position.z);
  pose.orientation = Eigen::Quaterniond(p.orientation.w, p.orientation.x, p.orientation.y, p.orientation.z).normalized();
  return pose;
}

void ArmServices::attach(const std::string& object, bool attach)
{
  vrrw_msgs::AttachObject srv;
  srv.request.object = object;
  srv.request.attach = attach;
  services_.call("/" + robot_ + "/attach_object", srv);
  if (srv.response.error_code != 0)
    throw SkillRefusal("/" + robot_ + "/attach_object: " + srv.response.message);
}
}  // namespace vrrw_skills

#include <vrrw_interaction/grab_target.h>

#include <algorithm>
#include <vector>

namespace vrrw_interaction
{
using Type = vrrw_scene::Shape::Type;

double elementDistance(const vrrw_kinematics::CollisionElement& element, const Eigen::Isometry3d& element_pose,
                       const Eigen::Vector3d& point, Eigen::Vector3d& closest)
{
  const Eigen::Vector3d local = element_pose.inverse() * point;
  Eigen::Vector3d nearest = local;
  if (element.type == Type::Box)
    nearest = local.cwiseMax(-element.half_extents).cwiseMin(element.half_extents);
  else if (element.type == Type::Cylinder)
  {
    const double radius = element.half_extents.x();
    const Eigen::Vector2d radial = local.head<2>();
    if (radial.norm() > radius)
      nearest.head<2>() = radial.normalized() * radius;
    nearest.z() = std::clamp(local.z(), -element.half_extents.z(), element.half_extents.z());
  }
  else  // sphere, and a mesh by its bounding sphere
  {
    const double radius = element.type == Type::Sphere ? element.half_extents.x() : element.bounding_radius;
    if (radius > 0.0 && local.norm() > radius)
      nearest = local.normalized() * radius;
  }
  closest = element_pose * nearest;
  return (local - nearest).norm();
}

std::optional<GrabTarget> nearestBody(const vrrw_kinematics::CollisionWorld& world, const Eigen::VectorXd& state,
                                      const Eigen::Vector3d& point, double max_distance, const Grabbable& grabbable)
{
  std::vector<Eigen::Isometry3d> bodies;
  world.bodyTransforms(state, bodies);
  std::optional<GrabTarget> best;
  for (std::size_t b = 0; b < world.bodies().size(); ++b)
  {
    const vrrw_kinematics::CollisionBody& body = world.bodies()[b];
    if (!grabbable(body))
      continue;
    for (const int e : body.elements)
    {
      const vrrw_kinematics::CollisionElement& element = world.elements()[static_cast<std::size_t>(e)];
      Eigen::Vector3d closest;
      const double distance = elementDistance(element, bodies[b] * element.local, point, closest);
      if (distance > max_distance || (best && distance >= best->distance))
        continue;
      // Springs hold a point of the URDF link (or the object): the body frame may sit at an offset to it.
      const Eigen::Isometry3d frame = bodies[b] * body.offset.inverse();
      best = GrabTarget{ body.name, body.robot, body.object, !body.object ? frame.inverse() * closest
                                                                               : bodies[b].inverse() * closest,
                         closest, distance };
    }
  }
  return best;
}
}  // namespace vrrw_interaction

namespace vrrw_interaction
{
std::string heldLink(const vrrw_kinematics::RobotModel& model, const std::string& link,
                     const std::vector<std::string>& arm_joints)
{
  int held = model.linkIndex(link);
  for (int l = held; model.links()[l].parent_joint >= 0;)
  {
    const vrrw_kinematics::JointModel& joint = model.joints()[model.links()[l].parent_joint];
    if (joint.moves() && std::find(arm_joints.begin(), arm_joints.end(), joint.name) != arm_joints.end())
      break;  // reached the arm: the links below it, up to here, are rigid with the arm's last link
    if (joint.moves())
      held = joint.parent_link;  // a gripper joint: hold what it hangs on
    l = joint.parent_link;
  }
  return model.links()[held].name;
}

std::optional<GrabTarget> handGrab(const vrrw_kinematics::CollisionWorld& world, const vrrw_scene::Scene& scene,
                                   const Eigen::VectorXd& state, const Eigen::Vector3d& point, const GrabRule& rule)
{
  const auto grabbable = [&](const vrrw_kinematics::CollisionBody& body) {
    if (body.object)
      return rule.movable_objects && body.link < 0 && !scene.object(body.name)->fixed;
    return rule.robots.count(body.robot) > 0;
  };
  std::optional<GrabTarget> target = nearestBody(world, state, point, rule.max_distance, grabbable);
  if (!target || target->object)
    return target;
  const vrrw_kinematics::RobotModel& model = world.model();
  target->body = heldLink(model, target->body, scene.robot(target->robot)->arm_joints);
  target->point_in_body = model.relativeTransform(state, model.links()[0].name, target->body).inverse() *
                          target->point_in_world;
  return target;
}

bool clearOfMovingBodies(const vrrw_kinematics::CollisionWorld& world, const vrrw_scene::Scene& scene,
                         const Eigen::VectorXd& state, const Eigen::Vector3d& point, double radius)
{
  return !nearestBody(world, state, point, radius, [&](const vrrw_kinematics::CollisionBody& body) {
    return !body.object || !scene.object(body.name)->fixed;
  });
}
}  // namespace vrrw_interaction

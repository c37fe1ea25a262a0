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

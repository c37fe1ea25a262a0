#include "vrrw_kinematics/collision_world.h"

#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/distance.h>

#include <algorithm>
#include <cmath>

#include "vrrw_kinematics/kinematics_error.h"
#include "world_box.h"

namespace vrrw_kinematics
{
void elementAabb(const CollisionElement& element, const Eigen::Isometry3d& pose, Eigen::Vector3d& center,
                 Eigen::Vector3d& half)
{
  center = pose.translation();
  const Eigen::Matrix3d& r = pose.linear();
  switch (element.type)
  {
    case vrrw_scene::Shape::Type::Box:
      half = r.cwiseAbs() * element.half_extents;
      return;
    case vrrw_scene::Shape::Type::Cylinder:
    {
      const Eigen::Vector3d axis = r.col(2);
      for (int i = 0; i < 3; ++i)
        half[i] = std::abs(axis[i]) * element.half_extents.z() +
                  element.half_extents.x() * std::sqrt(std::max(0.0, 1.0 - axis[i] * axis[i]));
      return;
    }
    default:
      half.setConstant(element.bounding_radius);
  }
}

bool elementsCollide(const CollisionElement& a, const Eigen::Isometry3d& pose_a, const CollisionElement& b,
                     const Eigen::Isometry3d& pose_b)
{
  static const fcl::CollisionRequestd request;
  fcl::CollisionResultd result;
  fcl::collide(a.geometry.get(), pose_a, b.geometry.get(), pose_b, request, result);
  return result.isCollision();
}

CollisionWorld::CollisionWorld(const std::string& urdf, const std::vector<vrrw_scene::Object>& objects,
                               const std::vector<std::string>& robot_names)
  : model_(RobotModel::fromUrdf(urdf)), robot_names_(robot_names), urdf_(urdf)
{
  for (std::size_t l = 0; l < model_.links().size(); ++l)
  {
    const LinkModel& link = model_.links()[l];
    if (link.collision.empty())
      continue;
    CollisionBody body;
    body.name = link.name;
    body.robot = robotOf(link.name);
    body.link = static_cast<int>(l);
    addBody(body, link.collision);
  }
  for (const vrrw_scene::Object& object : objects)
  {
    if (bodyIndex(object.name) >= 0)
      throw KinematicsError(ErrorCode::InvalidArgument, "object " + object.name + ": name already used by a link");
    CollisionBody body;
    body.name = object.name;
    body.offset = object.pose;
    body.object = true;
    addBody(body, object.collision);
  }
  rebuildPairs();
}

CollisionWorld CollisionWorld::fromScene(const vrrw_scene::Scene& scene)
{
  std::vector<std::string> names;
  for (const vrrw_scene::Robot& robot : scene.robots)
    names.push_back(robot.name);
  return CollisionWorld(scene.urdf, scene.objects, names);
}

std::string CollisionWorld::robotOf(const std::string& link) const
{
  if (robot_names_.empty())
    return model_.name().empty() ? "robot" : model_.name();
  std::string best;
  for (const std::string& name : robot_names_)
    if (link.compare(0, name.size() + 1, name + "_") == 0 && name.size() > best.size())
      best = name;
  return best;
}

void CollisionWorld::addBody(CollisionBody body, const std::vector<vrrw_scene::Shape>& shapes)
{
  const int body_index = static_cast<int>(bodies_.size());
  for (const vrrw_scene::Shape& shape : shapes)
  {
    CollisionElement element;
    element.body = body_index;
    element.local = shape.origin;
    element.type = shape.type;
    switch (shape.type)
    {
      case vrrw_scene::Shape::Type::Box:
        element.geometry = std::make_shared<fcl::Boxd>(shape.box_size.x(), shape.box_size.y(), shape.box_size.z());
        element.half_extents = 0.5 * shape.box_size;
        element.bounding_radius = element.half_extents.norm();
        break;
      case vrrw_scene::Shape::Type::Cylinder:
        element.geometry = std::make_shared<fcl::Cylinderd>(shape.radius, shape.length);
        element.half_extents = Eigen::Vector3d(shape.radius, shape.radius, 0.5 * shape.length);
        element.bounding_radius = std::hypot(shape.radius, 0.5 * shape.length);
        break;
      case vrrw_scene::Shape::Type::Sphere:
        element.geometry = std::make_shared<fcl::Sphered>(shape.radius);
        element.half_extents.setConstant(shape.radius);
        element.bounding_radius = shape.radius;
        break;
      case vrrw_scene::Shape::Type::Mesh:
        throw KinematicsError(ErrorCode::InvalidArgument,
                              "body " + body.name + ": mesh collision geometry " + shape.mesh_path +
                                  " is not supported; use primitives");
    }
    body.elements.push_back(static_cast<int>(elements_.size()));
    elements_.push_back(element);
  }
  bodies_.push_back(body);
}

int CollisionWorld::bodyIndex(const std::string& name) const
{
  for (std::size_t b = 0; b < bodies_.size(); ++b)
    if (bodies_[b].name == name)
      return static_cast<int>(b);
  return -1;
}

void CollisionWorld::rebuildPairs()
{
  ++revision_;
  pairs_.clear();
  for (std::size_t i = 0; i < elements_.size(); ++i)
    for (std::size_t j = i + 1; j < elements_.size(); ++j)
    {
      const int bi = elements_[i].body, bj = elements_[j].body;
      if (bi != bj && !acm_.allowed(bodies_[bi].name, bodies_[bj].name))
        pairs_.emplace_back(static_cast<int>(i), static_cast<int>(j));
    }
}

void CollisionWorld::setAllowed(const std::string& a, const std::string& b, bool allowed)
{
  for (const std::string& name : { a, b })
    if (bodyIndex(name) < 0)
      throw KinematicsError(ErrorCode::UnknownLink, "body " + name + ": no link or object with collision geometry");
  if (allowed)
    acm_.allow(a, b, "user");
  else
    acm_.forbid(a, b);
  rebuildPairs();
}

void CollisionWorld::bodyTransforms(const Eigen::VectorXd& variables, std::vector<Eigen::Isometry3d>& out) const
{
  std::vector<Eigen::Isometry3d> links;
  model_.linkTransforms(variables, links);
  out.resize(bodies_.size());
  for (std::size_t b = 0; b < bodies_.size(); ++b)
    out[b] = bodies_[b].link >= 0 ? links[bodies_[b].link] * bodies_[b].offset : bodies_[b].offset;
}

bool CollisionWorld::fixedInWorld(const CollisionBody& body) const
{
  for (int l = body.link; l > 0; l = model_.links()[l].parent_link)
    if (model_.joints()[model_.links()[l].parent_joint].moves())
      return false;
  return true;
}

Contact CollisionWorld::check(const Eigen::VectorXd& variables, const std::string& robot) const
{
  std::vector<Eigen::Isometry3d> body_poses;
  bodyTransforms(variables, body_poses);
  Contact contact;
  for (const auto& pair : pairs_)
  {
    const CollisionElement& a = elements_[pair.first];
    const CollisionElement& b = elements_[pair.second];
    if (!robot.empty() && bodies_[a.body].robot != robot && bodies_[b.body].robot != robot)
      continue;
    const Eigen::Isometry3d pa = body_poses[a.body] * a.local, pb = body_poses[b.body] * b.local;
    Eigen::Vector3d ca, ha, cb, hb;
    elementAabb(a, pa, ca, ha);
    elementAabb(b, pb, cb, hb);
    if (aabbOverlap(ca, ha, cb, hb) && elementsCollide(a, pa, b, pb))
    {
      contact.collision = true;
      contact.body_a = bodies_[a.body].name;
      contact.body_b = bodies_[b.body].name;
      return contact;
    }
  }
  return contact;
}

DistanceReport CollisionWorld::distance(const Eigen::VectorXd& variables, const std::string& owner) const
{
  const auto owned = [&](const CollisionBody& body) { return body.name == owner || body.robot == owner; };
  if (!owner.empty() && std::none_of(bodies_.begin(), bodies_.end(), owned))
    throw KinematicsError(ErrorCode::UnknownLink, "body or robot " + owner + ": has no collision geometry");
  std::vector<Eigen::Isometry3d> body_poses;
  bodyTransforms(variables, body_poses);
  DistanceReport report;
  fcl::DistanceRequestd request;
  request.gjk_solver_type = fcl::GST_INDEP;
  for (const auto& pair : pairs_)
  {
    const CollisionElement& a = elements_[pair.first];
    const CollisionElement& b = elements_[pair.second];
    if ((!owner.empty() && !owned(bodies_[a.body]) && !owned(bodies_[b.body])) ||
        (fixedInWorld(bodies_[a.body]) && fixedInWorld(bodies_[b.body])))
      continue;
    fcl::DistanceResultd result;
    const double d = fcl::distance(a.geometry.get(), body_poses[a.body] * a.local, b.geometry.get(),
                                   body_poses[b.body] * b.local, request, result);
    if (d < report.distance)
    {
      report.distance = d;
      report.body_a = bodies_[a.body].name;
      report.body_b = bodies_[b.body].name;
    }
  }
  return report;
}

void CollisionWorld::setObjectPose(const std::string& object, const Eigen::Isometry3d& pose)
{
  const int b = bodyIndex(object);
  if (b < 0 || !bodies_[b].object)
    throw KinematicsError(ErrorCode::InvalidArgument, "object " + object + ": not a scene object");
  if (bodies_[b].link >= 0)
    throw KinematicsError(ErrorCode::InvalidArgument, "object " + object + ": attached; detach it first");
  if (bodies_[b].offset.matrix() != pose.matrix())
    ++revision_;
  bodies_[b].offset = pose;
}

void CollisionWorld::attachObject(const std::string& object, const std::string& link,
                                  const Eigen::VectorXd& variables, const std::vector<std::string>& touch_links)
{
  const int b = bodyIndex(object);
  if (b < 0 || !bodies_[b].object)
    throw KinematicsError(ErrorCode::InvalidArgument, "object " + object + ": not a scene object");
  const int l = model_.linkIndex(link);
  std::vector<Eigen::Isometry3d> body_poses, links;
  bodyTransforms(variables, body_poses);
  model_.linkTransforms(variables, links);
  bodies_[b].offset = links[l].inverse() * body_poses[b];
  bodies_[b].link = l;
  bodies_[b].robot = robotOf(link);
  acm_.allow(object, link, "attached");
  for (const std::string& touch : touch_links)
    if (touch != object)
      acm_.allow(object, touch, "attached");
  rebuildPairs();
}

void CollisionWorld::detachObject(const std::string& object, const Eigen::VectorXd& variables)
{
  const int b = bodyIndex(object);
  if (b < 0 || !bodies_[b].object || bodies_[b].link < 0)
    throw KinematicsError(ErrorCode::InvalidArgument, "object " + object + ": not attached");
  std::vector<Eigen::Isometry3d> body_poses;
  bodyTransforms(variables, body_poses);
  bodies_[b].offset = body_poses[b];
  bodies_[b].link = -1;
  bodies_[b].robot.clear();
  std::vector<std::pair<std::string, std::string>> attached;
  for (const auto& entry : acm_.entries())
    if (entry.second == "attached" && (entry.first.first == object || entry.first.second == object))
      attached.push_back(entry.first);
  for (const auto& pair : attached)
    acm_.forbid(pair.first, pair.second);
  rebuildPairs();
}
}  // namespace vrrw_kinematics

#pragma once
#include <vrrw_scene/scene.h>

inline vrrw_scene::Object ball(const std::string& name, const Eigen::Vector3d& position, double radius)
{
  vrrw_scene::Object object;
  object.name = name;
  object.kind = "sphere";
  vrrw_scene::Shape shape;
  shape.type = vrrw_scene::Shape::Type::Sphere;
  shape.radius = radius;
  object.collision.push_back(shape);
  object.pose.translation() = position;
  return object;
}

inline vrrw_scene::Object slab(const std::string& name, const Eigen::Vector3d& center, const Eigen::Vector3d& size)
{
  vrrw_scene::Object object;
  object.name = name;
  object.kind = "box";
  vrrw_scene::Shape shape;
  shape.type = vrrw_scene::Shape::Type::Box;
  shape.box_size = size;
  object.collision.push_back(shape);
  object.pose.translation() = center;
  object.fixed = true;
  return object;
}

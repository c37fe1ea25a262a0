#include "object_geometry.h"

#include "vrrw_scene/urdf_geometry.h"

namespace vrrw_scene
{
namespace
{
/// Inertia of a link about its own centre of mass, accumulated about a common point.
struct MassProperties
{
  double mass = 0.0;
  Eigen::Vector3d first_moment = Eigen::Vector3d::Zero();
  Eigen::Matrix3d inertia_about_origin = Eigen::Matrix3d::Zero();

  void add(double m, const Eigen::Vector3d& com, const Eigen::Matrix3d& inertia_at_com)
  {
    mass += m;
    first_moment += m * com;
    inertia_about_origin += inertia_at_com + m * (com.squaredNorm() * Eigen::Matrix3d::Identity() - com * com.transpose());
  }

  Eigen::Vector3d com() const { return mass > 0.0 ? Eigen::Vector3d(first_moment / mass) : Eigen::Vector3d::Zero(); }

  Eigen::Matrix3d inertiaAtCom() const
  {
    const Eigen::Vector3d c = com();
    return inertia_about_origin - mass * (c.squaredNorm() * Eigen::Matrix3d::Identity() - c * c.transpose());
  }
};

void gatherLink(const urdf::ModelInterface& model, const urdf::Link& link, const Eigen::Isometry3d& link_in_root,
                const ObjectSpec& spec, Object& object, MassProperties& mass)
{
  for (const auto& collision : link.collision_array)
    if (collision && collision->geometry)
      object.collision.push_back(shapeFromUrdf(*collision->geometry, link_in_root * toIsometry(collision->origin), ""));
  for (const auto& visual : link.visual_array)
    if (visual && visual->geometry)
    {
      object.visual.push_back(shapeFromUrdf(*visual->geometry, link_in_root * toIsometry(visual->origin), ""));
      if (visual->material && visual->material->color.a > 0.0f)
      {
        const auto& c = visual->material->color;
        object.color = { c.r, c.g, c.b, c.a };
      }
    }
  if (link.inertial)
  {
    const auto& i = *link.inertial;
    const Eigen::Isometry3d frame = link_in_root * toIsometry(i.origin);
    Eigen::Matrix3d inertia;
    inertia << i.ixx, i.ixy, i.ixz, i.ixy, i.iyy, i.iyz, i.ixz, i.iyz, i.izz;
    mass.add(i.mass, frame.translation(), frame.linear() * inertia * frame.linear().transpose());
  }
  for (const auto& joint : link.child_joints)
  {
    if (joint->type != urdf::Joint::FIXED)
      throw SceneError(spec.field + ": object joint '" + joint->name + "' must be fixed");
    gatherLink(model, *model.getLink(joint->child_link_name), link_in_root * toIsometry(joint->parent_to_joint_origin_transform), spec, object, mass);
  }
}

void applyOverrides(const ObjectSpec& spec, Object& object)
{
  if (spec.mass && object.mass > 0.0)
    object.inertia *= *spec.mass / object.mass;
  if (spec.mass)
    object.mass = *spec.mass;
  if (spec.friction)
    object.friction = *spec.friction;
  if (spec.restitution)
    object.restitution = *spec.restitution;
  if (spec.fixed)
    object.fixed = *spec.fixed;
  if (spec.color)
    object.color = *spec.color;
  if (!object.fixed && object.mass <= 0.0)
    throw SceneError(spec.field + ": object '" + spec.name + "' moves but has no mass");
}
}  // namespace

Object objectFromUrdf(const urdf::ModelInterface& model, const ObjectSpec& spec, bool fixed_by_kind)
{
  const std::string prefix = spec.name + "_";
  for (const auto& [name, joint] : model.joints_)
  {
    if (joint->parent_link_name != "world" || joint->child_link_name.rfind(prefix, 0) != 0)
      continue;
    Object object;
    object.name = spec.name;
    object.kind = spec.kind;
    object.fixed = fixed_by_kind;
    object.pose = toIsometry(joint->parent_to_joint_origin_transform);
    MassProperties mass;
    gatherLink(model, *model.getLink(joint->child_link_name), Eigen::Isometry3d::Identity(), spec, object, mass);
    object.mass = mass.mass;
    object.center_of_mass = mass.com();
    object.inertia = mass.inertiaAtCom();
    applyOverrides(spec, object);
    return object;
  }
  throw SceneError(spec.field + ": the '" + spec.kind + "' macro made no link named '" + prefix + "...' fixed to world");
}

Object primitiveObject(const ObjectSpec& spec)
{
  Object object;
  object.name = spec.name;
  object.kind = spec.kind;
  object.pose = spec.pose;
  Shape shape;
  const double m = spec.mass.value_or(0.0);
  Eigen::Vector3d diagonal;
  if (spec.kind == "cylinder")
  {
    shape.type = Shape::Type::Cylinder;
    shape.radius = spec.radius;
    shape.length = spec.length;
    const double side = m * (3 * spec.radius * spec.radius + spec.length * spec.length) / 12.0;
    diagonal = Eigen::Vector3d(side, side, m * spec.radius * spec.radius / 2.0);
  }
  else if (spec.kind == "sphere")
  {
    shape.type = Shape::Type::Sphere;
    shape.radius = spec.radius;
    diagonal = Eigen::Vector3d::Constant(0.4 * m * spec.radius * spec.radius);
  }
  else
  {
    // A mesh object takes the inertia of its bounding box, given as `size`.
    shape.type = spec.kind == "mesh" ? Shape::Type::Mesh : Shape::Type::Box;
    shape.box_size = spec.size;
    shape.mesh_path = spec.mesh;
    shape.mesh_scale = spec.scale;
    const Eigen::Vector3d s2 = spec.size.cwiseProduct(spec.size);
    diagonal = m / 12.0 * Eigen::Vector3d(s2.y() + s2.z(), s2.x() + s2.z(), s2.x() + s2.y());
  }
  object.collision = { shape };
  object.visual = { shape };
  object.mass = m;
  object.inertia = diagonal.asDiagonal();
  applyOverrides(spec, object);
  return object;
}
}  // namespace vrrw_scene

#include "vrrw_scene/urdf_geometry.h"

#include "vrrw_scene/mesh_path.h"

namespace vrrw_scene
{
Eigen::Isometry3d toIsometry(const urdf::Pose& pose)
{
  Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
  out.translation() = Eigen::Vector3d(pose.position.x, pose.position.y, pose.position.z);
  out.linear() = Eigen::Quaterniond(pose.rotation.w, pose.rotation.x, pose.rotation.y, pose.rotation.z).toRotationMatrix();
  return out;
}

Shape shapeFromUrdf(const urdf::Geometry& geometry, const Eigen::Isometry3d& origin, const std::string& base_dir)
{
  Shape shape;
  shape.origin = origin;
  switch (geometry.type)
  {
    case urdf::Geometry::BOX: {
      const auto& box = static_cast<const urdf::Box&>(geometry);
      shape.type = Shape::Type::Box;
      shape.box_size = Eigen::Vector3d(box.dim.x, box.dim.y, box.dim.z);
      break;
    }
    case urdf::Geometry::CYLINDER: {
      const auto& cylinder = static_cast<const urdf::Cylinder&>(geometry);
      shape.type = Shape::Type::Cylinder;
      shape.radius = cylinder.radius;
      shape.length = cylinder.length;
      break;
    }
    case urdf::Geometry::SPHERE:
      shape.type = Shape::Type::Sphere;
      shape.radius = static_cast<const urdf::Sphere&>(geometry).radius;
      break;
    case urdf::Geometry::MESH: {
      const auto& mesh = static_cast<const urdf::Mesh&>(geometry);
      shape.type = Shape::Type::Mesh;
      shape.mesh_path = resolveMeshPath(mesh.filename, base_dir);
      if (shape.mesh_path.empty())
        throw SceneError("mesh '" + mesh.filename + "': no such file");
      shape.mesh_scale = Eigen::Vector3d(mesh.scale.x, mesh.scale.y, mesh.scale.z);
      break;
    }
  }
  return shape;
}
}  // namespace vrrw_scene

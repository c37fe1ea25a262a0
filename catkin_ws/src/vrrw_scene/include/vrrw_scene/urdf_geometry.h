#pragma once
#include <urdf_model/model.h>

#include <Eigen/Geometry>
#include <string>

#include "vrrw_scene/scene.h"

namespace vrrw_scene
{
/// \brief A URDF pose as an isometry.
Eigen::Isometry3d toIsometry(const urdf::Pose& pose);

/// \brief A URDF geometry as a Shape placed at `origin`; a mesh's URI becomes its file (resolveMeshPath,
/// relative to `base_dir`). Throws SceneError "mesh 'URI': no such file" for a mesh that names none.
Shape shapeFromUrdf(const urdf::Geometry& geometry, const Eigen::Isometry3d& origin, const std::string& base_dir = "");
}  // namespace vrrw_scene

#pragma once
#include <set>
#include <string>

#include "catalog.h"
#include "scene_spec.h"

namespace vrrw_scene
{
/// \brief The xacro document that instantiates every catalogue robot, gripper and object of a scene.
std::string xacroDocument(const SceneSpec& scene, const Catalog& catalog, const std::string& urdf_dir);

/// \brief Runs xacro on a document; throws SceneError with xacro's own first error line.
std::string runXacro(const std::string& xacro, const std::string& document_path);

/// \brief Adds a custom robot's URDF (or xacro) to a document, every name prefixed, fixed to world.
std::string addCustomRobot(const std::string& urdf, const RobotSpec& robot, const std::string& xacro);

/// \brief Checks what urdfdom would let pass or report badly: every joint's parent and child link
/// exist, names are unique, every mesh file exists, joint limits and axes and link inertias are physical
/// (urdf_physics_check.h). Throws SceneError naming source, element and reason.
void checkUrdf(const std::string& urdf, const std::string& source);

/// \brief The document without the given links and the joints that lead to them.
/// \brief The bytes of a file (binary); empty when it cannot be read: the scene library's one file reader.
std::string readWholeFile(const std::string& path);

std::string withoutLinks(const std::string& urdf, const std::set<std::string>& links);
}  // namespace vrrw_scene

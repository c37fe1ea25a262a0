#pragma once
#include <Eigen/Geometry>
#include <array>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace vrrw_scene
{
/// \brief A bad scene, robot or object description; what() is one line: "file: field: reason".
class SceneError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

/// \brief One collision or visual primitive, placed in its owner's frame.
struct Shape
{
  enum class Type { Box, Cylinder, Sphere, Mesh };
  Type type = Type::Box;
  Eigen::Vector3d box_size = Eigen::Vector3d::Zero();  ///< full extents (m)
  double radius = 0.0;                                 ///< cylinder, sphere (m)
  double length = 0.0;                                 ///< cylinder, along its z (m)
  std::string mesh_path;                               ///< absolute file path
  Eigen::Vector3d mesh_scale = Eigen::Vector3d::Ones();
  Eigen::Isometry3d origin = Eigen::Isometry3d::Identity();
};

/// \brief A rigid object of the cell (table, cube, drill, bin, primitive, mesh).
struct Object
{
  std::string name;  ///< also its tf frame
  std::string kind;  ///< table, cube, drill, bin, box, cylinder, sphere, mesh
  std::vector<Shape> collision;
  std::vector<Shape> visual;
  std::array<float, 4> color{ { 0.6f, 0.6f, 0.6f, 1.0f } };
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  ///< in the world frame
  double mass = 0.0;                                        ///< kg; 0 for fixed objects
  Eigen::Vector3d center_of_mass = Eigen::Vector3d::Zero();
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();  ///< about the centre of mass, object axes
  double friction = 0.8;
  double restitution = 0.0;
  bool fixed = false;  ///< a table does not move
};

/// \brief Gains of one joint drive: effort = stiffness (q* - q) - damping (qd - qd*), |effort| <= max_force.
struct DriveGains
{
  double stiffness = 0.0;  ///< N m/rad (N/m prismatic)
  double damping = 0.0;    ///< N m s/rad (N s/m prismatic)
  double max_force = 0.0;  ///< N m (N prismatic); 0: the joint's URDF effort limit
};

/// \brief A joint's drive gains in its two modes (`drives:` of urdf/config/<model>.yaml).
struct JointGains
{
  DriveGains rigid{ 1e5, 8e4, 0.0 };       ///< holds the target; defaults: the paper's seed values
  DriveGains compliant{ 0.0, 30.0, 0.0 };  ///< yields to pushes (free-drive)
};

/// \brief One robot of the cell; every link and joint name starts with `name + "_"`.
struct Robot
{
  std::string name;     ///< namespace and prefix
  std::string model;    ///< ur3e, ur5e, ur10e, fetch
  std::string gripper;  ///< robotiq_2f_85, robotiq_2f_140, fetch_gripper, or empty
  Eigen::Isometry3d base_pose = Eigen::Isometry3d::Identity();
  std::string base_link;      ///< root of the robot, fixed to world
  std::string arm_base_link;  ///< first link of the arm chain (base_link for a UR, torso for Fetch)
  std::string tool_link;      ///< the flange, tool0
  std::string tcp_link;       ///< fingertip centre (tool0 when there is no gripper)
  std::vector<std::string> arm_joints;      ///< the planning group, base to tip
  std::vector<std::string> gripper_joints;  ///< actuated gripper joints (mimic joints follow them)
  std::map<std::string, double> initial_positions;  ///< every movable joint
  std::string config_file;  ///< urdf/config/<model>.yaml: acceleration limits and drive gains
  std::string gripper_config_file;  ///< urdf/config/<gripper>.yaml, or empty
  /// \brief rad/s^2 (m/s^2 prismatic) of every movable joint, from config_file and the gripper's config
  /// (a robot with its own description brings its `config:`, required at scene load).
  std::map<std::string, double> acceleration_limits;
  /// \brief Drive gains of every movable joint that is not a mimic joint, from config_file (gripper joints
  /// from gripper_config_file); JointGains' defaults where a config has no `drives` (or the robot no config).
  std::map<std::string, JointGains> drive_gains;
  /// \brief `fingertip_lever_arm` of gripper_config_file (m): a pad force F (GripperCommand max_effort, N)
  /// is the actuated joint's drive force limit F x this. 0 when the gripper's config does not give it.
  double fingertip_lever_arm = 0.0;
  /// \brief `max_grip_force` of gripper_config_file: the rated pad force (N); 0 when not given.
  double max_grip_force = 0.0;
};

/// \brief A cell expanded from its YAML: one combined URDF of all robots plus the object list.
struct Scene
{
  std::string name;
  std::string source_file;  ///< the scene YAML
  std::string urdf;         ///< combined URDF XML of every robot, root link "world"
  std::string cache_dir;    ///< where the expanded scene is stored
  std::vector<Robot> robots;
  std::vector<Object> objects;
  double load_seconds = 0.0;
  bool from_cache = false;

  const Robot* robot(const std::string& name) const;
  const Object* object(const std::string& name) const;
};
}  // namespace vrrw_scene

#include "vrrw_scene/scene_loader.h"

#include <urdf_parser/urdf_parser.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <unistd.h>

#include "vrrw_scene/robot_config.h"

#include "catalog.h"
#include "object_geometry.h"
#include "scene_spec.h"
#include "urdf_document.h"

namespace fs = std::filesystem;

namespace vrrw_scene
{
namespace
{
constexpr const char* kCacheVersion = "vrrw-scene-2";

/// FNV-1a, 64 bit: a stable content key (std::hash is not stable across builds).
struct ContentKey
{
  std::uint64_t value = 1469598103934665603ull;
  void add(const std::string& text)
  {
    for (unsigned char c : text)
      value = (value ^ c) * 1099511628211ull;
    value = (value ^ 0xff) * 1099511628211ull;
  }
  std::string hex() const
  {
    std::ostringstream out;
    out << std::hex << value;
    return out.str();
  }
};

std::string cacheDir(const LoadOptions& options)
{
  if (!options.cache_dir.empty())
    return options.cache_dir;
  if (const char* dir = std::getenv("VRRW_CACHE_DIR"))
    return dir;
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"))
    return std::string(xdg) + "/vrrw";
  const char* home = std::getenv("HOME");
  return std::string(home ? home : "/tmp") + "/.cache/vrrw";
}

std::string contentKey(const SceneSpec& spec, const std::string& urdf_dir)
{
  std::vector<fs::path> inputs;
  for (const auto& entry : fs::recursive_directory_iterator(urdf_dir))
    if (entry.is_regular_file() && entry.path().parent_path().filename() != "scenes")
      inputs.push_back(entry.path());
  std::sort(inputs.begin(), inputs.end());
  ContentKey key;
  key.add(kCacheVersion);
  key.add(readWholeFile(spec.file));
  for (const auto& path : inputs)
  {
    key.add(fs::relative(path, urdf_dir).string());
    key.add(readWholeFile(path.string()));
  }
  for (const auto& robot : spec.robots)
    if (!robot.description.empty())
      key.add(readWholeFile(robot.description));
  return key.hex();
}

void writeAtomically(const std::string& path, const std::string& text)
{
  const std::string temporary = path + ".tmp" + std::to_string(getpid());
  std::ofstream(temporary) << text;
  fs::rename(temporary, path);
}

std::string expand(const SceneSpec& spec, const Catalog& catalog, const std::string& root, const std::string& dir)
{
  fs::create_directories(dir);
  const std::string document = dir + "/" + spec.name + ".xacro.tmp" + std::to_string(getpid());
  std::ofstream(document) << xacroDocument(spec, catalog, root + "/urdf");
  std::string urdf;
  try
  {
    urdf = runXacro(root + "/.venv/bin/xacro", document);
  }
  catch (const SceneError&)
  {
    fs::remove(document);
    throw;
  }
  fs::remove(document);
  for (const auto& robot : spec.robots)
    if (!robot.description.empty())
      urdf = addCustomRobot(urdf, robot, root + "/.venv/bin/xacro");
  checkUrdf(urdf, spec.file);
  return urdf;
}

std::string chainEnd(const urdf::ModelInterface& model, const std::string& prefix, const std::string& tip,
                     const std::string& field)
{
  if (!model.getLink(prefix + tip))
    throw SceneError(field + ": link '" + tip + "' does not exist in the robot");
  return prefix + tip;
}

std::vector<std::string> movableJointsBetween(const urdf::ModelInterface& model, const std::string& base,
                                              const std::string& tip, const std::string& field)
{
  std::vector<std::string> joints;
  auto link = model.getLink(tip);
  while (link && link->name != base)
  {
    const auto& joint = link->parent_joint;
    if (!joint)
      throw SceneError(field + ": link '" + tip + "' does not lie below '" + base + "'");
    if (joint->type != urdf::Joint::FIXED && !joint->mimic)
      joints.push_back(joint->name);
    link = model.getLink(joint->parent_link_name);
  }
  std::reverse(joints.begin(), joints.end());
  return joints;
}

double clampToLimits(const urdf::Joint& joint, double value)
{
  if (!joint.limits || joint.type == urdf::Joint::CONTINUOUS)
    return value;
  return std::min(std::max(value, joint.limits->lower), joint.limits->upper);
}

void setInitial(const urdf::ModelInterface& model, const std::string& prefix, const std::map<std::string, double>& values,
                const std::string& field, Robot& robot)
{
  for (const auto& [name, value] : values)
  {
    const auto joint = model.getJoint(prefix + name);
    if (!joint || joint->type == urdf::Joint::FIXED || joint->mimic)
      throw SceneError(field + ".initial." + name + ": not a movable joint of robot '" + robot.name + "'");
    if (clampToLimits(*joint, value) != value)
    {
      std::ostringstream reason;
      reason << field << ".initial." << name << ": " << value << " is outside the joint limits [" << joint->limits->lower
             << ", " << joint->limits->upper << "]";
      throw SceneError(reason.str());
    }
    robot.initial_positions[joint->name] = value;
  }
}

Robot makeRobot(const urdf::ModelInterface& model, const RobotSpec& spec, const Catalog& catalog, const std::string& root)
{
  Robot robot;
  const std::string prefix = spec.name + "_";
  robot.name = spec.name;
  robot.model = spec.model;
  robot.gripper = spec.gripper;
  robot.base_pose = spec.base;
  const auto model_entry = catalog.robots.find(spec.model);
  if (model_entry != catalog.robots.end())
  {
    const RobotModel& entry = model_entry->second;
    robot.base_link = chainEnd(model, prefix, entry.base_link, spec.field);
    robot.arm_base_link = chainEnd(model, prefix, entry.arm_base_link, spec.field);
    robot.tool_link = chainEnd(model, prefix, entry.tool_link, spec.field);
    robot.tcp_link = model.getLink(prefix + "tcp") ? prefix + "tcp" : robot.tool_link;
    for (const auto& joint : entry.arm_joints)
      robot.arm_joints.push_back(prefix + joint);
    auto gripper_joints = entry.gripper_joints;
    if (catalog.grippers.count(spec.gripper))
      gripper_joints = catalog.grippers.at(spec.gripper).joints;
    for (const auto& joint : gripper_joints)
      robot.gripper_joints.push_back(prefix + joint);
    robot.config_file = root + "/urdf/" + entry.config;
  }
  else
  {
    robot.base_link = model.getJoint(prefix + "base_joint")->child_link_name;
    robot.arm_base_link = robot.base_link;
    robot.tcp_link = chainEnd(model, prefix, spec.tip_link, spec.field + ".tip_link");
    robot.tool_link = robot.tcp_link;
    robot.arm_joints = movableJointsBetween(model, robot.arm_base_link, robot.tcp_link, spec.field + ".tip_link");
  }
  for (const auto& joint : robot.arm_joints)
    if (!model.getJoint(joint))
      throw SceneError(spec.field + ": arm joint '" + joint + "' does not exist in the robot");
  for (const auto& [name, joint] : model.joints_)
    if (name.rfind(prefix, 0) == 0 && joint->type != urdf::Joint::FIXED && !joint->mimic)
      robot.initial_positions[name] = clampToLimits(*joint, 0.0);
  if (model_entry != catalog.robots.end())
    setInitial(model, prefix, model_entry->second.initial, spec.field + "(catalogue)", robot);
  setInitial(model, prefix, spec.initial, spec.field, robot);
  if (!spec.config.empty())
    robot.config_file = spec.config;
  const auto gripper = catalog.grippers.find(spec.gripper);
  if (gripper != catalog.grippers.end() && !gripper->second.config.empty())
    robot.gripper_config_file = root + "/urdf/" + gripper->second.config;
  readRobotConfig(robot);
  return robot;
}
}  // namespace

const Robot* Scene::robot(const std::string& name) const
{
  for (const auto& r : robots)
    if (r.name == name)
      return &r;
  return nullptr;
}

const Object* Scene::object(const std::string& name) const
{
  for (const auto& o : objects)
    if (o.name == name)
      return &o;
  return nullptr;
}

std::string vrrwRoot(const LoadOptions& options)
{
  if (!options.root.empty())
    return options.root;
  if (const char* root = std::getenv("VRRW_ROOT"))
    return root;
  return VRRW_DEFAULT_ROOT;
}

std::vector<std::string> shippedScenes(const LoadOptions& options)
{
  std::vector<std::string> names;
  const fs::path dir = vrrwRoot(options) + "/urdf/scenes";
  if (fs::is_directory(dir))
    for (const auto& entry : fs::directory_iterator(dir))
      if (entry.path().extension() == ".yaml")
        names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

std::string resolveScenePath(const std::string& name_or_path, const LoadOptions& options)
{
  const fs::path shipped = vrrwRoot(options) + "/urdf/scenes/" + name_or_path + ".yaml";
  if (name_or_path.find('/') == std::string::npos && fs::is_regular_file(shipped))
    return shipped.string();
  if (fs::is_regular_file(name_or_path))
    return fs::canonical(name_or_path).string();
  std::string known;
  for (const auto& name : shippedScenes(options))
    known += (known.empty() ? "" : ", ") + name;
  throw SceneError(name_or_path + ": no such scene file or shipped scene (shipped: " + known + ")");
}

Scene loadScene(const std::string& name_or_path, const LoadOptions& options)
{
  const auto start = std::chrono::steady_clock::now();
  const std::string root = vrrwRoot(options);
  const std::string file = resolveScenePath(name_or_path, options);
  const Catalog catalog = Catalog::load(root + "/urdf");
  const SceneSpec spec = parseSceneFile(file, catalog);

  Scene scene;
  scene.name = spec.name;
  scene.source_file = file;
  scene.cache_dir = cacheDir(options);
  const std::string cached = scene.cache_dir + "/" + spec.name + "-" + contentKey(spec, root + "/urdf") + ".urdf";
  std::string urdf;
  if (options.use_cache && fs::is_regular_file(cached))
  {
    urdf = readWholeFile(cached);
    scene.from_cache = true;
  }
  else
  {
    urdf = expand(spec, catalog, root, scene.cache_dir);
    writeAtomically(cached, urdf);
  }

  const auto model = urdf::parseURDF(urdf);
  if (!model)
    throw SceneError(file + ": the expanded URDF does not parse (urdfdom rejected it; see " + cached + ")");
  std::set<std::string> object_links;
  for (const auto& object : spec.objects)
  {
    const auto kind = catalog.objects.find(object.kind);
    scene.objects.push_back(kind == catalog.objects.end() ? primitiveObject(object) :
                                                            objectFromUrdf(*model, object, kind->second.fixed));
    for (const auto& [name, link] : model->links_)
      if (name.rfind(object.name + "_", 0) == 0)
        object_links.insert(name);
  }
  for (const auto& robot : spec.robots)
    scene.robots.push_back(makeRobot(*model, robot, catalog, root));
  scene.urdf = withoutLinks(urdf, object_links);
  scene.load_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return scene;
}
}  // namespace vrrw_scene

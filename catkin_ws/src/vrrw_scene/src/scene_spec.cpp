#include "scene_spec.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>
#include <set>
#include <sstream>

#include "physical_ranges.h"
#include "yaml_field.h"

namespace fs = std::filesystem;

namespace vrrw_scene
{
namespace
{
std::string fieldName(const YamlField& field)
{
  return field.file() + ":" + std::to_string(field.node().Mark().line + 1) + ": " + field.path();
}

/// A letter, then letters, digits or _ (checked by hand: <regex> alone took seconds of this file's compile).
bool validName(const std::string& name)
{
  const auto letter = [](char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); };
  if (name.empty() || !letter(name[0]))
    return false;
  return std::all_of(name.begin(), name.end(), [&](char c) { return letter(c) || (c >= '0' && c <= '9') || c == '_'; });
}

void checkName(const YamlField& field, std::set<std::string>& taken)
{
  const std::string name = field.asString();
  if (!validName(name))
    field.fail("'" + name + "' is not a valid name (a letter, then letters, digits or _)");
  if (name == "world")
    field.fail("'world' is the root frame of every scene");
  if (!taken.insert(name).second)
    field.fail("the name '" + name + "' is used twice; robot and object names must be unique");
  for (const auto& other : taken)
    if (other != name && (other.rfind(name + "_", 0) == 0 || name.rfind(other + "_", 0) == 0))
      field.fail("'" + name + "' and '" + other + "' would share the link prefix '" +
                 std::min(name, other, [](auto& a, auto& b) { return a.size() < b.size(); }) + "_'");
}

std::string resolveFile(const YamlField& field, const std::string& scene_file)
{
  fs::path path = field.asString();
  if (path.is_relative())
    path = fs::path(scene_file).parent_path() / path;
  if (!fs::is_regular_file(path))
    field.fail("file '" + path.string() + "' does not exist");
  return fs::canonical(path).string();
}

/// A number as a person reads it (1e+30, 0.5).
std::string number(double value)
{
  std::ostringstream out;
  out << value;
  return out.str();
}

/// A pose in the cell: every coordinate within ranges::kMaxCoordinate.
Eigen::Isometry3d placedPose(const YamlField& field)
{
  const Eigen::Isometry3d pose = field.asPose();
  for (int axis = 0; axis < 3; ++axis)
    if (std::abs(pose.translation()[axis]) > ranges::kMaxCoordinate)
      field["xyz"].fail(number(pose.translation()[axis]) + " outside [-" + number(ranges::kMaxCoordinate) + ", " +
                        number(ranges::kMaxCoordinate) + "] m (a cell's coordinates)");
  return pose;
}

/// A number within [lo, hi], or the field's one-line error naming the range.
double within(const YamlField& field, double lo, double hi, const std::string& unit)
{
  const double value = field.asDouble();
  if (value < lo || value > hi)
    field.fail(number(value) + " outside [" + number(lo) + ", " + number(hi) + "]" + (unit.empty() ? "" : " " + unit));
  return value;
}

/// A length of an object: in (0, ranges::kMaxExtent] m.
double extent(const YamlField& field)
{
  const double value = within(field, 0.0, ranges::kMaxExtent, "m");
  if (value == 0.0)
    field.fail("must be greater than zero, got 0");
  return value;
}

RobotSpec parseRobot(const YamlField& entry, const Catalog& catalog, const std::string& scene_file)
{
  entry.allowKeys({ "name", "model", "gripper", "description", "tip_link", "config", "base", "initial" });
  RobotSpec robot;
  robot.field = fieldName(entry);
  robot.name = entry["name"].asString();
  if (entry.has("description"))
  {
    if (entry.has("model") || entry.has("gripper"))
      entry["description"].fail("a robot takes either a catalogue model (with a gripper) or its own description");
    robot.model = "custom";
    robot.description = resolveFile(entry["description"], scene_file);
    robot.tip_link = entry["tip_link"].asString();
    if (!entry.has("config"))  // planning and the controllers need an acceleration limit for every joint
      throw SceneError(robot.field + ".config: missing; a robot with its own description needs a config file "
                       "(acceleration_limits per joint, as urdf/config/*.yaml)");
  }
  else
  {
    robot.model = entry["model"].asString();
    const auto model = catalog.robots.find(robot.model);
    if (model == catalog.robots.end())
      entry["model"].fail("unknown robot model '" + robot.model + "' (known: " + keyList(catalog.robots) + ")");
    robot.gripper = entry.stringOr("gripper", "");
    if (!robot.gripper.empty() && !model->second.builtin_gripper.empty())
      entry["gripper"].fail("model '" + robot.model + "' has its own gripper '" + model->second.builtin_gripper + "'");
    if (!robot.gripper.empty() && !catalog.grippers.count(robot.gripper))
      entry["gripper"].fail("unknown gripper '" + robot.gripper + "' (known: " + keyList(catalog.grippers) + ")");
    if (robot.gripper.empty())
      robot.gripper = model->second.builtin_gripper;
  }
  if (entry.has("config"))
    robot.config = resolveFile(entry["config"], scene_file);
  if (entry.has("base"))
    robot.base = placedPose(entry["base"]);
  if (entry.has("initial"))
    for (const auto& joint : entry["initial"].keys())
      robot.initial[joint] = entry["initial"][joint].asDouble();
  return robot;
}

void drawRandomPlacement(const YamlField& random, std::mt19937& rng, Eigen::Isometry3d& pose)
{
  random.allowKeys({ "x", "y", "z", "yaw" });
  auto draw = [&](const char* axis) {
    if (!random.has(axis))
      return 0.0;
    const auto range = random[axis].asDoubles(2);
    if (std::string(axis) != "yaw" && std::max(std::abs(range[0]), std::abs(range[1])) > ranges::kMaxCoordinate)
      random[axis].fail("outside [-" + number(ranges::kMaxCoordinate) + ", " + number(ranges::kMaxCoordinate) +
                        "] m (a cell's coordinates)");
    if (range[1] < range[0])
      random[axis].fail("the range [min, max] has min > max");
    return std::uniform_real_distribution<double>(range[0], range[1])(rng);
  };
  const double dx = draw("x"), dy = draw("y"), dz = draw("z"), yaw = draw("yaw");
  pose.translation() += Eigen::Vector3d(dx, dy, dz);
  pose.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix() * pose.linear();
}

double positive(const YamlField& field, bool allow_zero)
{
  const double value = field.asDouble();
  if (value < 0.0 || (!allow_zero && value == 0.0))
    field.fail("must be " + std::string(allow_zero ? "zero or more" : "greater than zero") + ", got " +
               field.asString());
  return value;
}

ObjectSpec parseObject(const YamlField& entry, const Catalog& catalog, const std::string& scene_file,
                       std::mt19937& rng)
{
  entry.allowKeys({ "name", "kind", "pose", "random", "mass", "friction", "restitution", "fixed", "size", "radius",
                    "length", "mesh", "scale", "color" });
  ObjectSpec object;
  object.field = fieldName(entry);
  object.name = entry["name"].asString();
  object.kind = entry["kind"].asString();
  const std::set<std::string> primitives{ "box", "cylinder", "sphere", "mesh" };
  if (!catalog.objects.count(object.kind) && !primitives.count(object.kind))
    entry["kind"].fail("unknown object kind '" + object.kind + "' (known: " + keyList(catalog.objects) +
                       ", box, cylinder, sphere, mesh)");
  if (entry.has("pose"))
    object.pose = placedPose(entry["pose"]);
  if (entry.has("random"))
    drawRandomPlacement(entry["random"], rng, object.pose);
  if (entry.has("mass"))
    object.mass = within(entry["mass"], 0.0, ranges::kMaxMass, "kg");
  if (entry.has("friction"))
    object.friction = within(entry["friction"], 0.0, ranges::kMaxFriction, "");
  if (entry.has("restitution"))
    object.restitution = within(entry["restitution"], 0.0, 1.0, "");
  if (entry.has("fixed"))
    object.fixed = entry["fixed"].asBool();
  if (entry.has("size"))
  {
    const auto size = entry["size"].asDoubles(3);
    object.size = Eigen::Vector3d(size[0], size[1], size[2]);
    if (object.size.minCoeff() <= 0.0)
      entry["size"].fail("every extent must be greater than zero");
    if (object.size.maxCoeff() > ranges::kMaxExtent)
      entry["size"].fail(number(object.size.maxCoeff()) + " outside (0, " + number(ranges::kMaxExtent) + "] m");
  }
  if (entry.has("radius"))
    object.radius = extent(entry["radius"]);
  if (entry.has("length"))
    object.length = extent(entry["length"]);
  if (object.kind == "mesh")
    object.mesh = resolveFile(entry["mesh"], scene_file);
  if (entry.has("scale"))
  {
    const auto scale = entry["scale"].asDoubles(3);
    object.scale = Eigen::Vector3d(scale[0], scale[1], scale[2]);
  }
  if (entry.has("color"))
  {
    const auto rgba = entry["color"].asDoubles(4);
    object.color = std::array<float, 4>{ float(rgba[0]), float(rgba[1]), float(rgba[2]), float(rgba[3]) };
  }
  if (primitives.count(object.kind) && !object.mass && !(object.fixed && *object.fixed))
    entry.fail("a " + object.kind + " that is not fixed needs a mass");
  return object;
}
}  // namespace

SceneSpec parseSceneFile(const std::string& file, const Catalog& catalog)
{
  const auto root = YamlField::loadFile(file);
  if (!root.node().IsMap())
    root.fail("a scene is a mapping with 'robots' and 'objects'");
  root.allowKeys({ "name", "seed", "robots", "objects", "presets" });  // presets: vrrw_interaction
  SceneSpec scene;
  scene.file = file;
  scene.name = root.stringOr("name", fs::path(file).stem().string());
  scene.seed = root.has("seed") ? unsigned(positive(root["seed"], true)) : 0u;
  std::set<std::string> names;
  if (root.has("robots"))
  {
    const auto robots = root["robots"];
    robots.requireSequence();
    for (std::size_t i = 0; i < robots.size(); ++i)
    {
      checkName(robots[i]["name"], names);
      scene.robots.push_back(parseRobot(robots[i], catalog, file));
    }
  }
  if (root.has("objects"))
  {
    std::mt19937 rng(scene.seed);
    const auto objects = root["objects"];
    objects.requireSequence();
    for (std::size_t i = 0; i < objects.size(); ++i)
    {
      checkName(objects[i]["name"], names);
      scene.objects.push_back(parseObject(objects[i], catalog, file, rng));
    }
  }
  if (scene.robots.empty() && scene.objects.empty())
    root.fail("the scene has no robots and no objects");
  return scene;
}
}  // namespace vrrw_scene

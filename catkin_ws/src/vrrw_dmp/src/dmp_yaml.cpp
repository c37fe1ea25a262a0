#include <vrrw_dmp/dmp_yaml.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include <vrrw_dmp/dmp_error.h>
#include <vrrw_dmp/yaml_fields.h>
#include <vrrw_trajectory/trajectory_error.h>
#include <vrrw_trajectory/whole_file.h>

#include "format_number.h"

namespace vrrw_dmp
{
namespace
{
const char* const kFormat = "vrrw_dmp/1";

/// The model file's fields (its top level named "model" in errors).
class Reader : public YamlFields
{
public:
  explicit Reader(std::string source) : YamlFields(std::move(source), "model") {}
};
}  // namespace

YAML::Node loadYamlMapping(const std::string& text, const std::string& source, const std::string& what)
{
  YAML::Node root;
  try
  {
    root = YAML::Load(text);
  }
  catch (const YAML::Exception& e)
  {
    throw DmpError(source + ":" + std::to_string(e.mark.line + 1) + ": not YAML (cut short?): " + e.msg);
  }
  if (!root.IsMap())
    throw DmpError(source + ": " + what + ": expected a YAML mapping (an empty or cut-short file?)");
  return root;
}

void emitNumbers(YAML::Emitter& out, const std::vector<double>& values)
{
  out << YAML::Flow << YAML::BeginSeq;
  for (double v : values)
    out << v;
  out << YAML::EndSeq;
}

void emitDmpFields(YAML::Emitter& out, const Dmp& dmp)
{
  const DmpParameters& p = dmp.parameters();
  out << YAML::Key << "parameters" << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "basis_count" << YAML::Value << p.basis_count;
  out << YAML::Key << "alpha" << YAML::Value << p.alpha;
  out << YAML::Key << "K" << YAML::Value << p.K;
  out << YAML::Key << "D" << YAML::Value << p.damping();
  out << YAML::Key << "scaling" << YAML::Value << toString(p.scaling);
  out << YAML::Key << "degenerate_ratio" << YAML::Value << p.degenerate_ratio;
  out << YAML::Key << "still_range" << YAML::Value << p.still_range;
  out << YAML::Key << "derivative_half_window" << YAML::Value << p.derivative_half_window;
  out << YAML::EndMap;
  out << YAML::Key << "demo_duration" << YAML::Value << dmp.demoDuration();
  out << YAML::Key << "basis" << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "centers" << YAML::Value;
  emitNumbers(out, dmp.basis().centers());
  out << YAML::Key << "widths" << YAML::Value;
  emitNumbers(out, dmp.basis().widths());
  out << YAML::EndMap;
  out << YAML::Key << "joints" << YAML::Value << YAML::BeginSeq;
  for (std::size_t j = 0; j < dmp.dofs(); ++j)
  {
    out << YAML::BeginMap;
    out << YAML::Key << "name" << YAML::Value << dmp.jointNames()[j];
    out << YAML::Key << "scaling" << YAML::Value << toString(dmp.jointScaling()[j]);
    out << YAML::Key << "start" << YAML::Value << dmp.demoStart()[j];
    out << YAML::Key << "goal" << YAML::Value << dmp.demoGoal()[j];
    out << YAML::Key << "amplitude" << YAML::Value << dmp.demoAmplitude()[j];
    out << YAML::Key << "weights" << YAML::Value;
    emitNumbers(out, dmp.weights()[j]);
    out << YAML::EndMap;
  }
  out << YAML::EndSeq;
  out << YAML::Key << "warnings" << YAML::Value << YAML::BeginSeq;
  for (const auto& warning : dmp.warnings())
    out << warning;
  out << YAML::EndSeq;
  const DmpProvenance& origin = dmp.provenance();
  out << YAML::Key << "provenance" << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "source" << YAML::Value << origin.source;
  out << YAML::Key << "created" << YAML::Value << origin.created;
  out << YAML::Key << "samples" << YAML::Value << origin.samples;
  out << YAML::Key << "demo_checksum" << YAML::Value << origin.demo_checksum;
  out << YAML::Key << "tool" << YAML::Value << "vrrw_dmp 0.1.0";
  out << YAML::EndMap;
}

std::string toYaml(const Dmp& dmp)
{
  YAML::Emitter out;
  out.SetDoublePrecision(17);
  out << YAML::BeginMap;
  out << YAML::Key << "format" << YAML::Value << kFormat;
  emitDmpFields(out, dmp);
  out << YAML::EndMap;
  return std::string(out.c_str()) + "\n";
}

void emitCartesianDmpFields(YAML::Emitter& out, const CartesianDmp& dmp)
{
  const OrientationDmp& o = dmp.orientation();
  auto quaternion = [&out](const Eigen::Quaterniond& q) {
    emitNumbers(out, { q.x(), q.y(), q.z(), q.w() });
  };
  out << YAML::Key << "position" << YAML::Value << YAML::BeginMap;
  emitDmpFields(out, dmp.position());
  out << YAML::EndMap;
  out << YAML::Key << "orientation" << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "start" << YAML::Value;
  quaternion(o.demoStart());
  out << YAML::Key << "goal" << YAML::Value;
  quaternion(o.demoGoal());
  out << YAML::Key << "amplitude" << YAML::Value;
  emitNumbers(out, { o.demoAmplitude().x(), o.demoAmplitude().y(), o.demoAmplitude().z() });
  out << YAML::Key << "axes" << YAML::Value << YAML::BeginSeq;
  for (std::size_t a = 0; a < 3; ++a)
  {
    out << YAML::BeginMap;
    out << YAML::Key << "name" << YAML::Value << std::string(1, "xyz"[a]);
    out << YAML::Key << "scaling" << YAML::Value << toString(o.axisScaling()[a]);
    out << YAML::Key << "weights" << YAML::Value;
    emitNumbers(out, o.weights()[a]);
    out << YAML::EndMap;
  }
  out << YAML::EndSeq;
  out << YAML::Key << "warnings" << YAML::Value << YAML::BeginSeq;
  for (const auto& warning : o.warnings())
    out << warning;
  out << YAML::EndSeq;
  out << YAML::EndMap;
}

namespace
{
Dmp parseFields(const YAML::Node& root, const Reader& read, const std::string& at)
{
  if (!root.IsMap())
    read.fail(at.empty() ? "model" : at.substr(0, at.size() - 1), "expected a YAML mapping");
  const YAML::Node p = read.child(root, "parameters", at);
  DmpParameters parameters;
  const std::string pp = at + "parameters.";
  const auto count = read.scalar<long long>(p, "basis_count", pp);
  if (count <= 0 || count > static_cast<long long>(DmpParameters::kMaxBasisCount))
    read.fail(pp + "basis_count", std::to_string(count) + " must be > 0 and at most the limit of " +
                                            std::to_string(DmpParameters::kMaxBasisCount));
  parameters.basis_count = static_cast<std::size_t>(count);
  parameters.alpha = read.scalar<double>(p, "alpha", pp);
  parameters.K = read.scalar<double>(p, "K", pp);
  parameters.D = read.scalar<double>(p, "D", pp);
  parameters.degenerate_ratio = read.scalar<double>(p, "degenerate_ratio", pp);
  if (p["still_range"])  // models written before it have none: off
    parameters.still_range = read.scalar<double>(p, "still_range", pp);
  const auto window = read.scalar<long long>(p, "derivative_half_window", pp);
  if (window <= 0)
    read.fail(pp + "derivative_half_window", std::to_string(window) + " must be > 0");
  parameters.derivative_half_window = static_cast<std::size_t>(window);
  try
  {
    parameters.scaling = amplitudeScalingFromString(read.scalar<std::string>(p, "scaling", pp));
  }
  catch (const DmpError& e)
  {
    read.fail(pp + "scaling", e.what());
  }

  const YAML::Node b = read.child(root, "basis", at);
  GaussianBasis basis(read.numbers(b, "centers", at + "basis."), read.numbers(b, "widths", at + "basis."));

  const YAML::Node joints = read.child(root, "joints", at);
  if (!joints.IsSequence() || joints.size() == 0)
    read.fail(at + "joints", "expected a non-empty list");
  std::vector<std::string> names;
  std::vector<std::vector<double>> weights;
  std::vector<double> start, goal, amplitude;
  std::vector<AmplitudeScaling> scaling;
  for (std::size_t j = 0; j < joints.size(); ++j)
  {
    const std::string path = at + "joints[" + std::to_string(j) + "].";
    const YAML::Node joint = joints[j];
    names.push_back(read.scalar<std::string>(joint, "name", path));
    const auto mode = read.scalar<std::string>(joint, "scaling", path);
    if (mode != "goal" && mode != "amplitude")
      read.fail(path + "scaling", "'" + mode + "' is not goal or amplitude");
    scaling.push_back(amplitudeScalingFromString(mode));
    start.push_back(read.scalar<double>(joint, "start", path));
    goal.push_back(read.scalar<double>(joint, "goal", path));
    amplitude.push_back(read.scalar<double>(joint, "amplitude", path));
    weights.push_back(read.numbers(joint, "weights", path));
  }

  std::vector<std::string> warnings;
  if (const YAML::Node list = root["warnings"])
    for (const auto& item : list)
      warnings.push_back(item.as<std::string>());
  DmpProvenance origin;
  if (const YAML::Node prov = root["provenance"])
  {
    origin.source = prov["source"] ? prov["source"].as<std::string>() : "";
    origin.created = prov["created"] ? prov["created"].as<std::string>() : "";
    origin.samples = prov["samples"] ? prov["samples"].as<std::size_t>() : 0;
    origin.demo_checksum = prov["demo_checksum"] ? prov["demo_checksum"].as<std::string>() : "";
  }
  const double duration = read.scalar<double>(root, "demo_duration", at);
  try
  {
    return Dmp(std::move(names), parameters, std::move(basis), std::move(weights), std::move(start), std::move(goal),
               std::move(amplitude), std::move(scaling), duration, std::move(origin), std::move(warnings));
  }
  catch (const DmpError& e)
  {
    if (at.empty())
      throw DmpError(read.source() + ": " + e.what());
    read.fail(at.substr(0, at.size() - 1), e.what());
  }
}

Eigen::Quaterniond quaternion(const YAML::Node& node, const std::string& key, const Reader& read, const std::string& at)
{
  const std::vector<double> v = read.numbers(node, key, at);
  if (v.size() != 4)
    read.fail(at + key, std::to_string(v.size()) + " numbers, a quaternion is x, y, z, w");
  const Eigen::Quaterniond q(v[3], v[0], v[1], v[2]);
  if (std::abs(q.norm() - 1.0) > 1e-9)
    read.fail(at + key, "norm " + format(q.norm()) + " is not 1 (a unit quaternion is needed)");
  return q;
}

Dmp parseModel(const std::string& text, const std::string& source)
{
  const Reader read(source);
  const YAML::Node root = loadYamlMapping(text, source, "model");
  const auto format = read.scalar<std::string>(root, "format", "");
  if (format != kFormat)
    read.fail("format", "'" + format + "' is not '" + kFormat + "'");
  return parseFields(root, read, "");
}
}  // namespace

Dmp parseDmpFields(const YAML::Node& node, const std::string& source, const std::string& path)
{
  return parseFields(node, Reader(source), path);
}

CartesianDmp parseCartesianDmpFields(const YAML::Node& node, const std::string& source, const std::string& path)
{
  const Reader read(source);
  const Dmp position = parseFields(read.child(node, "position", path), read, path + "position.");
  const std::string at = path + "orientation.";
  const YAML::Node o = read.child(node, "orientation", path);
  const std::vector<double> range = read.numbers(o, "amplitude", at);
  if (range.size() != 3)
    read.fail(at + "amplitude", std::to_string(range.size()) + " numbers for 3 axes");
  const YAML::Node axes = read.child(o, "axes", at);
  if (!axes.IsSequence() || axes.size() != 3)
    read.fail(at + "axes", "expected a list of the 3 axes x, y, z");
  std::vector<std::vector<double>> weights;
  std::vector<AmplitudeScaling> scaling;
  for (std::size_t a = 0; a < 3; ++a)
  {
    const std::string axis = at + "axes[" + std::to_string(a) + "].";
    const auto mode = read.scalar<std::string>(axes[a], "scaling", axis);
    if (mode != "goal" && mode != "amplitude")
      read.fail(axis + "scaling", "'" + mode + "' is not goal or amplitude");
    scaling.push_back(amplitudeScalingFromString(mode));
    weights.push_back(read.numbers(axes[a], "weights", axis));
  }
  std::vector<std::string> warnings;
  if (const YAML::Node list = o["warnings"])
    for (const auto& item : list)
      warnings.push_back(item.as<std::string>());
  const Eigen::Quaterniond start = quaternion(o, "start", read, at), goal = quaternion(o, "goal", read, at);
  try
  {
    OrientationDmp orientation(position.parameters(), position.basis(), std::move(weights), start, goal,
                               Eigen::Vector3d(range[0], range[1], range[2]), std::move(scaling),
                               position.demoDuration(), std::move(warnings));
    return CartesianDmp(position, std::move(orientation));
  }
  catch (const DmpError& e)
  {
    read.fail(at.substr(0, at.size() - 1), e.what());
  }
}

Dmp fromYaml(const std::string& text, const std::string& source)
{
  try
  {
    return parseModel(text, source);
  }
  catch (const YAML::Exception& e)
  {
    throw DmpError(source + ":" + std::to_string(e.mark.line + 1) + ": " + e.msg);
  }
}

void saveDmp(const Dmp& dmp, const std::string& path)
{
  try
  {
    vrrw_trajectory::writeWholeFile(path, toYaml(dmp));
  }
  catch (const vrrw_trajectory::TrajectoryError& e)
  {
    throw DmpError(e.what());
  }
}

Dmp loadDmp(const std::string& path)
{
  std::ifstream in(path);
  if (!in)
    throw DmpError(path + ": cannot open for reading");
  std::stringstream text;
  text << in.rdbuf();
  return fromYaml(text.str(), path);
}
}  // namespace vrrw_dmp

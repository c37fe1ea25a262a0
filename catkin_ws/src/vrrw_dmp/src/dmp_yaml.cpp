#include <vrrw_dmp/dmp_yaml.h>

#include <fstream>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include <vrrw_dmp/dmp_error.h>
#include <vrrw_trajectory/trajectory_error.h>
#include <vrrw_trajectory/whole_file.h>

namespace vrrw_dmp
{
namespace
{
const char* const kFormat = "vrrw_dmp/1";

YAML::Emitter& flowSequence(YAML::Emitter& out, const std::vector<double>& values)
{
  out << YAML::Flow << YAML::BeginSeq;
  for (double v : values)
    out << v;
  return out << YAML::EndSeq;
}

class Reader
{
public:
  explicit Reader(std::string source) : source_(std::move(source)) {}

  YAML::Node child(const YAML::Node& node, const std::string& key, const std::string& path) const
  {
    const YAML::Node value = node[key];
    if (!value)
      fail(path + key, "missing");
    return value;
  }

  template <typename T>
  T scalar(const YAML::Node& node, const std::string& key, const std::string& path) const
  {
    const YAML::Node value = child(node, key, path);
    try
    {
      return value.as<T>();
    }
    catch (const YAML::Exception&)
    {
      fail(path + key, "is not a " + std::string(std::is_same<T, std::string>::value ? "string" : "number"));
    }
  }

  std::vector<double> numbers(const YAML::Node& node, const std::string& key, const std::string& path) const
  {
    const YAML::Node value = child(node, key, path);
    if (!value.IsSequence())
      fail(path + key, "is not a list of numbers");
    try
    {
      return value.as<std::vector<double>>();
    }
    catch (const YAML::Exception&)
    {
      fail(path + key, "is not a list of numbers");
    }
  }

  [[noreturn]] void fail(const std::string& field, const std::string& reason) const
  {
    throw DmpError(source_ + ": " + field + ": " + reason);
  }

private:
  std::string source_;
};
}  // namespace

std::string toYaml(const Dmp& dmp)
{
  const DmpParameters& p = dmp.parameters();
  YAML::Emitter out;
  out.SetDoublePrecision(17);
  out << YAML::BeginMap;
  out << YAML::Key << "format" << YAML::Value << kFormat;
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
  flowSequence(out, dmp.basis().centers());
  out << YAML::Key << "widths" << YAML::Value;
  flowSequence(out, dmp.basis().widths());
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
    flowSequence(out, dmp.weights()[j]);
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
  out << YAML::EndMap;
  return std::string(out.c_str()) + "\n";
}

namespace
{
Dmp parseModel(const std::string& text, const std::string& source)
{
  const Reader read(source);
  YAML::Node root;
  try
  {
    root = YAML::Load(text);
  }
  catch (const YAML::Exception& e)
  {
    throw DmpError(source + ":" + std::to_string(e.mark.line + 1) + ": not YAML: " + e.msg);
  }
  if (!root.IsMap())
    read.fail("model", "expected a YAML mapping");
  const auto format = read.scalar<std::string>(root, "format", "");
  if (format != kFormat)
    read.fail("format", "'" + format + "' is not '" + kFormat + "'");

  const YAML::Node p = read.child(root, "parameters", "");
  DmpParameters parameters;
  const auto count = read.scalar<long long>(p, "basis_count", "parameters.");
  if (count <= 0 || count > static_cast<long long>(DmpParameters::kMaxBasisCount))
    read.fail("parameters.basis_count", std::to_string(count) + " must be > 0 and at most the limit of " +
                                            std::to_string(DmpParameters::kMaxBasisCount));
  parameters.basis_count = static_cast<std::size_t>(count);
  parameters.alpha = read.scalar<double>(p, "alpha", "parameters.");
  parameters.K = read.scalar<double>(p, "K", "parameters.");
  parameters.D = read.scalar<double>(p, "D", "parameters.");
  parameters.degenerate_ratio = read.scalar<double>(p, "degenerate_ratio", "parameters.");
  if (p["still_range"])  // models written before it have none: off
    parameters.still_range = read.scalar<double>(p, "still_range", "parameters.");
  const auto window = read.scalar<long long>(p, "derivative_half_window", "parameters.");
  if (window <= 0)
    read.fail("parameters.derivative_half_window", std::to_string(window) + " must be > 0");
  parameters.derivative_half_window = static_cast<std::size_t>(window);
  try
  {
    parameters.scaling = amplitudeScalingFromString(read.scalar<std::string>(p, "scaling", "parameters."));
  }
  catch (const DmpError& e)
  {
    read.fail("parameters.scaling", e.what());
  }

  const YAML::Node b = read.child(root, "basis", "");
  GaussianBasis basis(read.numbers(b, "centers", "basis."), read.numbers(b, "widths", "basis."));

  const YAML::Node joints = read.child(root, "joints", "");
  if (!joints.IsSequence() || joints.size() == 0)
    read.fail("joints", "expected a non-empty list");
  std::vector<std::string> names;
  std::vector<std::vector<double>> weights;
  std::vector<double> start, goal, amplitude;
  std::vector<AmplitudeScaling> scaling;
  for (std::size_t j = 0; j < joints.size(); ++j)
  {
    const std::string path = "joints[" + std::to_string(j) + "].";
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
  const double duration = read.scalar<double>(root, "demo_duration", "");
  try
  {
    return Dmp(std::move(names), parameters, std::move(basis), std::move(weights), std::move(start), std::move(goal),
               std::move(amplitude), std::move(scaling), duration, std::move(origin), std::move(warnings));
  }
  catch (const DmpError& e)
  {
    throw DmpError(source + ": " + e.what());
  }
}
}  // namespace

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

#include "yaml_field.h"

#include <cmath>
#include <fstream>
#include <sstream>

namespace vrrw_scene
{
YamlField::YamlField(YAML::Node node, std::string file, std::string path)
  : node_(std::move(node)), file_(std::move(file)), path_(std::move(path))
{
}

YamlField YamlField::loadFile(const std::string& file)
{
  std::ifstream in(file);
  if (!in)
    throw SceneError(file + ": cannot read the file");
  try
  {
    return YamlField(YAML::Load(in), file, "");
  }
  catch (const YAML::Exception& e)
  {
    throw SceneError(file + ":" + std::to_string(e.mark.line + 1) + ": malformed YAML: " + e.msg);
  }
}

void YamlField::fail(const std::string& reason) const
{
  std::string where = file_;
  if (node_.IsDefined() && node_.Mark().line >= 0)
    where += ":" + std::to_string(node_.Mark().line + 1);
  throw SceneError(where + ": " + (path_.empty() ? "" : path_ + ": ") + reason);
}

bool YamlField::has(const std::string& key) const
{
  return node_.IsMap() && node_[key].IsDefined() && !node_[key].IsNull();
}

YamlField YamlField::operator[](const std::string& key) const
{
  requireMap();
  std::string child = path_.empty() ? key : path_ + "." + key;
  if (!has(key))
    fail("missing field '" + key + "'");
  return YamlField(node_[key], file_, child);
}

YamlField YamlField::operator[](std::size_t index) const
{
  return YamlField(node_[index], file_, path_ + "[" + std::to_string(index) + "]");
}

std::size_t YamlField::size() const
{
  return node_.size();
}

std::vector<std::string> YamlField::keys() const
{
  std::vector<std::string> out;
  for (const auto& item : node_)
    out.push_back(item.first.as<std::string>());
  return out;
}

void YamlField::requireMap() const
{
  if (!node_.IsMap())
    fail("expected a mapping of fields");
}

void YamlField::requireSequence() const
{
  if (!node_.IsSequence())
    fail("expected a list");
}

void YamlField::allowKeys(const std::vector<std::string>& allowed) const
{
  requireMap();
  for (const auto& item : node_)
  {
    const auto key = item.first.as<std::string>();
    bool known = false;
    std::string list;
    for (const auto& a : allowed)
    {
      known = known || a == key;
      list += (list.empty() ? "" : ", ") + a;
    }
    if (!known)
      YamlField(item.first, file_, path_.empty() ? key : path_ + "." + key)
          .fail("unknown field (allowed: " + list + ")");
  }
}

double YamlField::asDouble() const
{
  if (!node_.IsScalar())
    fail("expected a number");
  const std::string text = node_.Scalar();
  std::istringstream in(text);
  double value = 0.0;
  in >> value;
  if (in.fail() || !in.eof())
  {
    // YAML spells pi as a number only; accept the common "pi" forms people write by hand.
    if (text == "pi" || text == "-pi")
      return text[0] == '-' ? -M_PI : M_PI;
    fail("expected a number, got '" + text + "'");
  }
  if (!std::isfinite(value))
    fail("expected a finite number, got '" + text + "'");
  return value;
}

std::string YamlField::asString() const
{
  if (!node_.IsScalar())
    fail("expected a text value");
  return node_.Scalar();
}

bool YamlField::asBool() const
{
  const std::string text = asString();
  if (text == "true" || text == "yes")
    return true;
  if (text == "false" || text == "no")
    return false;
  fail("expected true or false, got '" + text + "'");
}

std::vector<double> YamlField::asDoubles(std::size_t expected_size) const
{
  requireSequence();
  if (expected_size && size() != expected_size)
    fail("expected " + std::to_string(expected_size) + " numbers, got " + std::to_string(size()));
  std::vector<double> out;
  for (std::size_t i = 0; i < size(); ++i)
    out.push_back((*this)[i].asDouble());
  return out;
}

std::vector<std::string> YamlField::asStrings() const
{
  requireSequence();
  std::vector<std::string> out;
  for (std::size_t i = 0; i < size(); ++i)
    out.push_back((*this)[i].asString());
  return out;
}

double YamlField::doubleOr(const std::string& key, double fallback) const
{
  return has(key) ? (*this)[key].asDouble() : fallback;
}

std::string YamlField::stringOr(const std::string& key, const std::string& fallback) const
{
  return has(key) ? (*this)[key].asString() : fallback;
}

Eigen::Isometry3d YamlField::asPose() const
{
  allowKeys({ "xyz", "rpy" });
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  if (has("xyz"))
  {
    const auto xyz = (*this)["xyz"].asDoubles(3);
    pose.translation() = Eigen::Vector3d(xyz[0], xyz[1], xyz[2]);
  }
  if (has("rpy"))
  {
    const auto rpy = (*this)["rpy"].asDoubles(3);
    pose.linear() = rpyToMatrix(rpy[0], rpy[1], rpy[2]);
  }
  return pose;
}

Eigen::Matrix3d rpyToMatrix(double roll, double pitch, double yaw)
{
  return (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}
}  // namespace vrrw_scene

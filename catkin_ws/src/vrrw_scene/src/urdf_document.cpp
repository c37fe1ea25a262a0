#include "urdf_document.h"

#include <tinyxml2.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <unistd.h>

#include <vrrw_common/run_program.h>

#include "vrrw_scene/mesh_path.h"
#include "vrrw_scene/scene.h"

#include "urdf_physics_check.h"

namespace fs = std::filesystem;
using tinyxml2::XMLDocument;
using tinyxml2::XMLElement;

namespace vrrw_scene
{
namespace
{
std::string originXml(const Eigen::Isometry3d& pose)
{
  const Eigen::Vector3d xyz = pose.translation();
  const Eigen::Vector3d ypr = pose.linear().eulerAngles(2, 1, 0);
  std::ostringstream out;
  out.precision(17);
  out << "<origin xyz=\"" << xyz.x() << " " << xyz.y() << " " << xyz.z() << "\" rpy=\"" << ypr[2] << " " << ypr[1]
      << " " << ypr[0] << "\"/>";
  return out.str();
}

std::string argsXml(const std::map<std::string, std::string>& args)
{
  std::string out;
  for (const auto& [key, value] : args)
    out += " " + key + "=\"" + value + "\"";
  return out;
}

void parse(XMLDocument& doc, const std::string& urdf, const std::string& source)
{
  if (doc.Parse(urdf.c_str()) != tinyxml2::XML_SUCCESS)
    throw SceneError(source + ":" + std::to_string(doc.ErrorLineNum()) + ": malformed XML: " + doc.ErrorStr());
  if (!doc.RootElement() || std::string(doc.RootElement()->Name()) != "robot")
    throw SceneError(source + ": the root element must be <robot>");
}

std::string print(const XMLDocument& doc)
{
  tinyxml2::XMLPrinter printer;
  doc.Print(&printer);
  return printer.CStr();
}

std::string attribute(const XMLElement* element, const char* name)
{
  const char* value = element ? element->Attribute(name) : nullptr;
  return value ? value : "";
}

}  // namespace

std::string readWholeFile(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string xacroDocument(const SceneSpec& scene, const Catalog& catalog, const std::string& urdf_dir)
{
  std::set<std::string> includes;
  std::ostringstream body;
  for (const auto& robot : scene.robots)
  {
    if (robot.model == "custom")
      continue;
    const RobotModel& model = catalog.robots.at(robot.model);
    includes.insert(model.xacro);
    const std::string prefix = robot.name + "_";
    body << "  <xacro:" << model.macro << " prefix=\"" << prefix << "\" parent=\"world\"" << argsXml(model.args)
         << ">\n    " << originXml(robot.base) << "\n  </xacro:" << model.macro << ">\n";
    if (catalog.grippers.count(robot.gripper))
    {
      const GripperModel& gripper = catalog.grippers.at(robot.gripper);
      includes.insert(gripper.xacro);
      body << "  <xacro:" << gripper.macro << " prefix=\"" << prefix << "\" parent=\"" << prefix << model.tool_link
           << "\"" << argsXml(gripper.args) << "/>\n";
    }
  }
  for (const auto& object : scene.objects)
  {
    const auto kind = catalog.objects.find(object.kind);
    if (kind == catalog.objects.end())
      continue;  // primitives are built without xacro
    includes.insert(kind->second.xacro);
    body << "  <xacro:" << kind->second.macro << " prefix=\"" << object.name << "_\" parent=\"world\">\n    "
         << originXml(object.pose) << "\n  </xacro:" << kind->second.macro << ">\n";
  }
  std::ostringstream doc;
  doc << "<?xml version=\"1.0\"?>\n<robot name=\"" << scene.name << "\" xmlns:xacro=\"http://www.ros.org/wiki/xacro\">\n";
  for (const auto& include : includes)
    doc << "  <xacro:include filename=\"" << urdf_dir << "/" << include << "\"/>\n";
  doc << "  <link name=\"world\"/>\n" << body.str() << "</robot>\n";
  return doc.str();
}

std::string runXacro(const std::string& xacro, const std::string& document_path)
{
  if (access(xacro.c_str(), X_OK) != 0)
    throw SceneError(xacro + ": xacro is not installed; run ./vrrw setup");
  // By argv, never a shell: the document's path is the scene author's (a custom robot's description).
  std::string output, message;
  vrrw_common::ProgramStreams streams;
  streams.output = &output;
  streams.errors = &message;
  const int status = vrrw_common::runProgram({ xacro, document_path }, streams);
  if (status != 0 || output.empty())
  {
    std::string first;
    std::istringstream lines(message);
    for (std::string line; std::getline(lines, line);)
      if (!line.empty())
        first = line;  // xacro prints its reason last
    if (status < 0 && first.empty())
      first = "cannot start " + xacro;
    throw SceneError(document_path + ": xacro failed: " + (first.empty() ? "no output" : first));
  }
  return output;
}

std::string addCustomRobot(const std::string& urdf, const RobotSpec& robot, const std::string& xacro)
{
  const bool is_xacro = fs::path(robot.description).extension() == ".xacro";
  const std::string text = is_xacro ? runXacro(xacro, robot.description) : readWholeFile(robot.description);
  checkUrdf(text, robot.description);
  XMLDocument custom;
  parse(custom, text, robot.description);
  XMLDocument scene;
  parse(scene, urdf, "scene");
  const std::string prefix = robot.name + "_";
  std::set<std::string> children;
  for (auto* joint = custom.RootElement()->FirstChildElement("joint"); joint; joint = joint->NextSiblingElement("joint"))
    children.insert(attribute(joint->FirstChildElement("child"), "link"));
  std::string root_link;
  for (auto* element = custom.RootElement()->FirstChildElement(); element; element = element->NextSiblingElement())
  {
    const std::string tag = element->Name();
    if (tag == "link" && !children.count(attribute(element, "name")))
      root_link = attribute(element, "name");
    if (tag == "link" || tag == "joint")
      element->SetAttribute("name", (prefix + attribute(element, "name")).c_str());
    for (const char* ref : { "parent", "child" })
      if (auto* e = element->FirstChildElement(ref))
        e->SetAttribute("link", (prefix + attribute(e, "link")).c_str());
    if (auto* mimic = element->FirstChildElement("mimic"))
      mimic->SetAttribute("joint", (prefix + attribute(mimic, "joint")).c_str());
    for (auto* part = element->FirstChildElement(); part; part = part->NextSiblingElement())
      if (auto* mesh = part->FirstChildElement("geometry") ? part->FirstChildElement("geometry")->FirstChildElement("mesh") : nullptr)
      {
        const std::string path = resolveMeshPath(attribute(mesh, "filename"), fs::path(robot.description).parent_path());
        mesh->SetAttribute("filename", ("file://" + path).c_str());
      }
    if (tag == "link" || tag == "joint" || tag == "material")
      scene.RootElement()->InsertEndChild(element->DeepClone(&scene));
  }
  XMLElement* joint = scene.NewElement("joint");
  joint->SetAttribute("name", (prefix + "base_joint").c_str());
  joint->SetAttribute("type", "fixed");
  XMLDocument origin;
  origin.Parse(originXml(robot.base).c_str());
  joint->InsertEndChild(origin.RootElement()->DeepClone(&scene));
  joint->InsertNewChildElement("parent")->SetAttribute("link", "world");
  joint->InsertNewChildElement("child")->SetAttribute("link", (prefix + root_link).c_str());
  scene.RootElement()->InsertEndChild(joint);
  return print(scene);
}

void checkUrdf(const std::string& urdf, const std::string& source)
{
  XMLDocument doc;
  parse(doc, urdf, source);
  std::set<std::string> links, joints;
  std::map<std::string, std::string> parent_of;
  for (auto* link = doc.RootElement()->FirstChildElement("link"); link; link = link->NextSiblingElement("link"))
  {
    const std::string name = attribute(link, "name");
    if (name.empty())
      throw SceneError(source + ":" + std::to_string(link->GetLineNum()) + ": link: has no name");
    if (!links.insert(name).second)
      throw SceneError(source + ": link '" + name + "': defined twice");
    checkLinkInertia(*link, source);
    for (auto* part = link->FirstChildElement(); part; part = part->NextSiblingElement())
    {
      auto* geometry = part->FirstChildElement("geometry");
      auto* mesh = geometry ? geometry->FirstChildElement("mesh") : nullptr;
      if (!mesh)
        continue;
      const std::string uri = attribute(mesh, "filename");
      if (resolveMeshPath(uri, fs::path(source).parent_path()).empty())
        throw SceneError(source + ": link '" + name + "': " + part->Name() + " mesh '" + uri + "' does not exist");
    }
  }
  for (auto* joint = doc.RootElement()->FirstChildElement("joint"); joint; joint = joint->NextSiblingElement("joint"))
  {
    const std::string name = attribute(joint, "name");
    const std::string where = source + ":" + std::to_string(joint->GetLineNum()) + ": joint '" + name + "'";
    if (!joints.insert(name).second)
      throw SceneError(where + ": defined twice");
    const std::string parent = attribute(joint->FirstChildElement("parent"), "link");
    const std::string child = attribute(joint->FirstChildElement("child"), "link");
    if (!links.count(parent))
      throw SceneError(where + ": parent link '" + parent + "' does not exist");
    if (!links.count(child))
      throw SceneError(where + ": child link '" + child + "' does not exist");
    if (!parent_of.emplace(child, name).second)
      throw SceneError(where + ": link '" + child + "' already has parent joint '" + parent_of[child] + "'");
    checkJointMotion(*joint, source);
  }
}

std::string withoutLinks(const std::string& urdf, const std::set<std::string>& links)
{
  XMLDocument doc;
  parse(doc, urdf, "scene");
  for (auto* element = doc.RootElement()->FirstChildElement(); element;)
  {
    auto* next = element->NextSiblingElement();
    const std::string tag = element->Name();
    const bool drop = (tag == "link" && links.count(attribute(element, "name"))) ||
                      (tag == "joint" && links.count(attribute(element->FirstChildElement("child"), "link")));
    if (drop)
      doc.RootElement()->DeleteChild(element);
    element = next;
  }
  return print(doc);
}
}  // namespace vrrw_scene

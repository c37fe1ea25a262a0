#include <vrrw_interaction/ghost_description.h>

#include <array>
#include <cstdio>
#include <tinyxml2.h>
#include <vrrw_interaction/interaction_error.h>

namespace vrrw_interaction
{
Tint ghostTint(std::size_t index)
{
  static const std::array<Tint, 4> palette{ { { 1.0, 0.55, 0.05 }, { 0.0, 0.75, 0.75 }, { 0.9, 0.2, 0.8 }, { 0.55, 0.9, 0.1 } } };
  return palette[index % palette.size()];
}

std::string ghostDescription(const vrrw_scene::Scene& scene)
{
  tinyxml2::XMLDocument doc;
  if (doc.Parse(scene.urdf.c_str()) != tinyxml2::XML_SUCCESS || !doc.FirstChildElement("robot"))
    throw InteractionError("ghost description: scene " + scene.name + ": urdf: not a URDF (" +
                           std::string(doc.ErrorStr() ? doc.ErrorStr() : "no <robot>") + ")");
  tinyxml2::XMLElement* robot = doc.FirstChildElement("robot");
  for (tinyxml2::XMLElement* link = robot->FirstChildElement("link"); link; link = link->NextSiblingElement("link"))
  {
    const std::string name = link->Attribute("name") ? link->Attribute("name") : "";
    for (std::size_t r = 0; r < scene.robots.size(); ++r)
    {
      if (name.rfind(scene.robots[r].name + "_", 0) != 0)
        continue;
      const Tint tint = ghostTint(r);
      char rgba[64];
      std::snprintf(rgba, sizeof(rgba), "%.3f %.3f %.3f 1", tint.r, tint.g, tint.b);
      for (tinyxml2::XMLElement* visual = link->FirstChildElement("visual"); visual;
           visual = visual->NextSiblingElement("visual"))
      {
        while (tinyxml2::XMLElement* material = visual->FirstChildElement("material"))
          visual->DeleteChild(material);
        tinyxml2::XMLElement* material = visual->InsertNewChildElement("material");
        material->SetAttribute("name", ("ghost_" + scene.robots[r].name).c_str());
        material->InsertNewChildElement("color")->SetAttribute("rgba", rgba);
      }
      break;
    }
  }
  tinyxml2::XMLPrinter printer;
  doc.Print(&printer);
  return printer.CStr();
}
}  // namespace vrrw_interaction

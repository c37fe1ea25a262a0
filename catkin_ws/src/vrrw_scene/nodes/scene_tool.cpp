// vrrw_scene SCENE [--urdf-out FILE|-] [--timing] [--no-cache]: expands a scene and reports it.
#include <cstring>
#include <fstream>
#include <iostream>

#include "vrrw_scene/scene_loader.h"

namespace
{
int usage()
{
  std::cerr << "usage: vrrw_scene SCENE [--urdf-out FILE|-] [--robots] [--timing] [--no-cache]\n"
               "  SCENE is a shipped scene name or a scene YAML path; --robots prints the robot names\n";
  return 2;
}

void summarize(const vrrw_scene::Scene& scene)
{
  std::cerr << "scene " << scene.name << ": " << scene.robots.size() << " robots, " << scene.objects.size()
            << " objects, loaded in " << scene.load_seconds << " s (" << (scene.from_cache ? "cache" : "xacro") << ")\n";
  for (const auto& robot : scene.robots)
    std::cerr << "  robot " << robot.name << " (" << robot.model << (robot.gripper.empty() ? "" : " + " + robot.gripper)
              << "): " << robot.arm_joints.size() << " arm joints, tcp " << robot.tcp_link << "\n";
  for (const auto& object : scene.objects)
    std::cerr << "  object " << object.name << " (" << object.kind << "): " << object.mass << " kg"
              << (object.fixed ? ", fixed" : "") << "\n";
}
}  // namespace

int main(int argc, char** argv)
{
  if (argc < 2 || argv[1][0] == '-')
    return usage();
  std::string scene_name = argv[1], urdf_out;
  bool timing = false, list_robots = false;
  vrrw_scene::LoadOptions options;
  for (int i = 2; i < argc; ++i)
  {
    if (!std::strcmp(argv[i], "--urdf-out") && i + 1 < argc)
      urdf_out = argv[++i];
    else if (!std::strcmp(argv[i], "--robots"))
      list_robots = true;
    else if (!std::strcmp(argv[i], "--timing"))
      timing = true;
    else if (!std::strcmp(argv[i], "--no-cache"))
      options.use_cache = false;
    else
      return usage();
  }
  try
  {
    if (timing)
    {
      vrrw_scene::LoadOptions cold = options;
      cold.use_cache = false;
      const auto first = vrrw_scene::loadScene(scene_name, cold);
      const auto second = vrrw_scene::loadScene(scene_name, options);
      summarize(second);
      std::cout << "{\"scene\": \"" << second.name << "\", \"cold_s\": " << first.load_seconds
                << ", \"cached_s\": " << second.load_seconds << "}" << std::endl;
      return 0;
    }
    const auto scene = vrrw_scene::loadScene(scene_name, options);
    if (list_robots)
    {
      for (const auto& robot : scene.robots)
        std::cout << robot.name << "\n";
      return 0;
    }
    summarize(scene);
    if (urdf_out == "-")
      std::cout << scene.urdf;
    else if (!urdf_out.empty())
    {
      std::ofstream out(urdf_out);
      out << scene.urdf;
      if (!out)
        throw vrrw_scene::SceneError(urdf_out + ": cannot write the URDF");
      std::cerr << "wrote " << urdf_out << "\n";
    }
  }
  catch (const std::exception& e)
  {
    std::cerr << "vrrw_scene: " << e.what() << std::endl;
    return 1;
  }
  return 0;
}

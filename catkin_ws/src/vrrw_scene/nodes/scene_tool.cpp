// vrrw_scene SCENE [--urdf-out FILE|-] [--robots] [--timing] [--no-cache]: expands a scene and reports it;
// --urdf-out writes the URDF with any of the others.
#include <fstream>
#include <iostream>

#include "vrrw_scene/scene_loader.h"
#include <vrrw_common/options.h>

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

/// Writes the URDF to \a path ("-": stdout).
void writeUrdf(const vrrw_scene::Scene& scene, const std::string& path)
{
  if (path == "-")
  {
    std::cout << scene.urdf;
    return;
  }
  std::ofstream out(path);
  out << scene.urdf;
  if (!out)
    throw vrrw_scene::SceneError(path + ": cannot write the URDF");
  std::cerr << "wrote " << path << "\n";
}

int run(const vrrw_common::Options& options)
{
  options.expectPositional({ "SCENE" });
  const std::string scene_name = options.positional()[0], urdf_out = options.text("urdf-out", "");
  vrrw_scene::LoadOptions load;
  load.use_cache = !options.flag("no-cache");
  if (options.flag("timing"))
  {
    vrrw_scene::LoadOptions cold = load;
    cold.use_cache = false;
    const auto first = vrrw_scene::loadScene(scene_name, cold);
    const auto second = vrrw_scene::loadScene(scene_name, load);
    summarize(second);
    if (!urdf_out.empty())
      writeUrdf(second, urdf_out);
    std::cout << "{\"scene\": \"" << second.name << "\", \"cold_s\": " << first.load_seconds
              << ", \"cached_s\": " << second.load_seconds << "}" << std::endl;
    return 0;
  }
  const auto scene = vrrw_scene::loadScene(scene_name, load);
  if (!options.flag("robots"))
    summarize(scene);
  if (!urdf_out.empty())
    writeUrdf(scene, urdf_out);
  if (options.flag("robots"))
    for (const auto& robot : scene.robots)
      std::cout << robot.name << "\n";
  return 0;
}
}  // namespace

int main(int argc, char** argv)
{
  try
  {
    return run(vrrw_common::Options(argc, argv, 1, { "urdf-out" }, { "robots", "timing", "no-cache" }));
  }
  catch (const vrrw_common::OptionError& e)
  {
    std::cerr << "vrrw_scene: " << e.what() << "\n";
    return usage();
  }
  catch (const vrrw_scene::SceneError& e)  // a scene it cannot load, a URDF it cannot write: bad input
  {
    std::cerr << "vrrw_scene: " << e.what() << std::endl;
    return 2;
  }
  catch (const std::exception& e)  // a failure while running (the cache folder, xacro's process)
  {
    std::cerr << "vrrw_scene: " << e.what() << std::endl;
    return 1;
  }
}

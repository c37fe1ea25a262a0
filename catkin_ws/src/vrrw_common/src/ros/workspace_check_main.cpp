// vrrw_workspace_check [--robot R] [--action NS]... [--service NAME]...: exits 0 when the running workspace
// has them, else prints the one line of what is missing and exits 1 (for ./vrrw's shell commands).
#include <iostream>
#include <ros/ros.h>
#include <vrrw_common/options.h>
#include <vrrw_common/ros/workspace_check.h>

int main(int argc, char** argv)
{
  ros::init(argc, argv, "vrrw_workspace_check", ros::init_options::AnonymousName | ros::init_options::NoRosout);
  try
  {
    const vrrw_common::Options options(argc, argv, 1, { "robot", "action", "service" });
    options.expectPositional({});
    vrrw_common::checkWorkspace({ options.text("robot", ""), options.all("action"), options.all("service") });
    return 0;
  }
  catch (const vrrw_common::OptionError& e)
  {
    std::cerr << "vrrw_workspace_check: " << e.what() << "\n";
    return 2;
  }
  catch (const std::exception& e)
  {
    std::cerr << e.what() << "\n";
    return 1;
  }
}

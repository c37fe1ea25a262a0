#pragma once
// The test pendulum (test/data/pendulum.urdf), shared by the physics tests.
#include <urdf_parser/urdf_parser.h>

#include <fstream>
#include <sstream>
#include <string>

namespace vrrw_physics_test
{
inline std::string pendulumUrdf()
{
  std::ifstream in(std::string(TEST_DATA) + "/pendulum.urdf");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

inline urdf::ModelInterfaceSharedPtr pendulumModel()
{
  return urdf::parseURDF(pendulumUrdf());
}
}  // namespace vrrw_physics_test

#pragma once
#include <fstream>
#include <sstream>
#include <string>

inline std::string fixture(const std::string& name)
{
  std::ifstream in(std::string(TEST_DATA) + "/" + name);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

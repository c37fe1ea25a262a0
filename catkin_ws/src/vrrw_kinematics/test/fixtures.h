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

#include <Eigen/Dense>
#include <initializer_list>

inline Eigen::VectorXd vec(std::initializer_list<double> values)
{
  Eigen::VectorXd v(static_cast<Eigen::Index>(values.size()));
  int i = 0;
  for (const double x : values)
    v[i++] = x;
  return v;
}

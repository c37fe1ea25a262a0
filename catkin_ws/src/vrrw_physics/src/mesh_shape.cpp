#include "mesh_shape.h"

#include <BulletCollision/CollisionShapes/btConvexHullShape.h>
#include <BulletCollision/CollisionShapes/btShapeHull.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace vrrw_physics
{
namespace
{
std::vector<btVector3> readStl(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw std::runtime_error(path + ": cannot open mesh");
  std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::vector<btVector3> points;
  if (data.size() >= 84)
  {
    std::uint32_t count = 0;
    std::memcpy(&count, data.data() + 80, 4);
    if (84 + std::size_t(count) * 50 == data.size())
    {
      for (std::uint32_t t = 0; t < count; ++t)
        for (int v = 0; v < 3; ++v)
        {
          float xyz[3];
          std::memcpy(xyz, data.data() + 84 + t * 50 + 12 + v * 12, 12);
          points.emplace_back(xyz[0], xyz[1], xyz[2]);
        }
      return points;
    }
  }
  std::istringstream text(data);
  std::string word;
  while (text >> word)
    if (word == "vertex")
    {
      double x, y, z;
      text >> x >> y >> z;
      points.emplace_back(btScalar(x), btScalar(y), btScalar(z));
    }
  return points;
}

std::vector<btVector3> readObj(const std::string& path)
{
  std::ifstream in(path);
  if (!in)
    throw std::runtime_error(path + ": cannot open mesh");
  std::vector<btVector3> points;
  std::string line;
  while (std::getline(in, line))
    if (line.size() > 2 && line[0] == 'v' && line[1] == ' ')
    {
      std::istringstream fields(line.substr(2));
      double x, y, z;
      if (fields >> x >> y >> z)
        points.emplace_back(btScalar(x), btScalar(y), btScalar(z));
    }
  return points;
}

std::string lowerExtension(const std::string& path)
{
  const auto dot = path.rfind('.');
  std::string ext = dot == std::string::npos ? "" : path.substr(dot + 1);
  for (char& c : ext)
    c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}
}  // namespace

std::unique_ptr<btConvexHullShape> loadConvexHull(const std::string& path, const Eigen::Vector3d& scale)
{
  const std::string ext = lowerExtension(path);
  std::vector<btVector3> points;
  if (ext == "stl")
    points = readStl(path);
  else if (ext == "obj")
    points = readObj(path);
  else
    throw std::runtime_error(path + ": mesh format '" + ext + "' not supported for collision (use STL or OBJ)");
  if (points.size() < 4)
    throw std::runtime_error(path + ": mesh has fewer than 4 vertices");
  const btVector3 s(btScalar(scale.x()), btScalar(scale.y()), btScalar(scale.z()));
  btConvexHullShape full;
  for (const btVector3& p : points)
    full.addPoint(p * s, false);
  full.recalcLocalAabb();
  full.setMargin(0);
  btShapeHull reducer(&full);
  reducer.buildHull(0);
  auto hull = std::make_unique<btConvexHullShape>();
  for (int i = 0; i < reducer.numVertices(); ++i)
    hull->addPoint(reducer.getVertexPointer()[i], false);
  hull->recalcLocalAabb();
  hull->setMargin(btScalar(0.001));
  return hull;
}
}  // namespace vrrw_physics

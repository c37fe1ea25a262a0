#include <gtest/gtest.h>

#include <cstdio>

#include "vrrw_kinematics/allowed_collision_matrix.h"

using vrrw_kinematics::AllowedCollisionMatrix;

TEST(AllowedCollisionMatrix, SymmetricWithReasons)
{
  AllowedCollisionMatrix acm;
  acm.allow("b", "a", "adjacent");
  acm.allow("c", "d", "never");
  EXPECT_TRUE(acm.allowed("a", "b"));
  EXPECT_TRUE(acm.allowed("b", "a"));
  EXPECT_FALSE(acm.allowed("a", "c"));
  EXPECT_EQ(acm.reason("d", "c"), "never");
  EXPECT_EQ(acm.count("adjacent"), 1u);
  acm.forbid("a", "b");
  EXPECT_FALSE(acm.allowed("a", "b"));
  EXPECT_EQ(acm.size(), 1u);
}

TEST(AllowedCollisionMatrix, SavesAndLoadsByKey)
{
  AllowedCollisionMatrix acm;
  acm.allow("x", "y", "always");
  acm.allow("p", "q", "never");
  const std::string path = "/tmp/vrrw_acm_test_" + std::to_string(::getpid()) + ".txt";
  acm.save(path, "key1");
  AllowedCollisionMatrix loaded;
  EXPECT_FALSE(loaded.load(path, "key2"));
  ASSERT_TRUE(loaded.load(path, "key1"));
  EXPECT_EQ(loaded.entries(), acm.entries());
  EXPECT_FALSE(loaded.load("/nonexistent/acm.txt", "key1"));
  std::remove(path.c_str());
}

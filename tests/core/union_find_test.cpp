// Disjoint sets: every element of a component has one representative, and separate components
// keep separate ones.
#include "mocap/math/union_find.h"

#include <gtest/gtest.h>

namespace mocap {
namespace {

TEST(UnionFind, ComponentsOfAGraphGivenEdgeByEdge)
{
  UnionFind sets(7);
  for (Eigen::Index i = 0; i < 7; ++i)
    EXPECT_EQ(sets.find(i), i);  // alone at first
  sets.unite(0, 1);
  sets.unite(2, 1);
  sets.unite(4, 5);
  sets.unite(5, 6);
  sets.unite(6, 4);  // a cycle changes nothing
  EXPECT_EQ(sets.find(0), sets.find(2));
  EXPECT_EQ(sets.find(1), sets.find(2));
  EXPECT_EQ(sets.find(4), sets.find(6));
  EXPECT_NE(sets.find(0), sets.find(4));
  EXPECT_EQ(sets.find(3), 3);
  sets.unite(3, 0);
  EXPECT_EQ(sets.find(3), sets.find(1));
  EXPECT_NE(sets.find(3), sets.find(5));
}

TEST(UnionFind, ALongChainStaysCorrect)
{
  const Eigen::Index n = 100000;
  UnionFind sets(n);
  for (Eigen::Index i = 1; i < n; ++i)
    sets.unite(i - 1, i);
  const Eigen::Index root = sets.find(0);
  for (Eigen::Index i = 0; i < n; i += 997)
    EXPECT_EQ(sets.find(i), root);
}

} // namespace
} // namespace mocap

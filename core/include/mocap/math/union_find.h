#pragma once

#include <Eigen/Core>

#include <vector>

namespace mocap {

/// Disjoint sets over the elements 0 … size−1 (union-find with path halving): connected
/// components of a graph given edge by edge. find and unite cost near-constant amortised time.
class UnionFind
{
public:
  explicit UnionFind(Eigen::Index size);

  /// The representative of the set holding `element` (the same for every element of a set).
  [[nodiscard]] Eigen::Index find(Eigen::Index element);
  /// Joins the sets holding `a` and `b`.
  void unite(Eigen::Index a, Eigen::Index b);

private:
  Eigen::Index& parent(Eigen::Index element) { return m_parent[static_cast<std::size_t>(element)]; }

  std::vector<Eigen::Index> m_parent;
};

} // namespace mocap

#include "mocap/math/union_find.h"

#include <numeric>

namespace mocap {

UnionFind::UnionFind(Eigen::Index size) : m_parent(static_cast<std::size_t>(size))
{
  std::iota(m_parent.begin(), m_parent.end(), Eigen::Index{0});
}

Eigen::Index UnionFind::find(Eigen::Index element)
{
  while (parent(element) != element) {
    parent(element) = parent(parent(element));  // path halving
    element = parent(element);
  }
  return element;
}

void UnionFind::unite(Eigen::Index a, Eigen::Index b)
{
  parent(find(a)) = find(b);
}

} // namespace mocap

#pragma once
// Weights handed in from Python must be numbers: a NaN or inf would be written as text no tool
// reads back, or pose a mesh with NaN vertices.

#include <Eigen/Core>

namespace mocap::python {

/// Throws InvalidArgument naming the first weight that is NaN or inf ("weights[f, s] is not
/// finite"). O(#frames · #shapes).
void checkFiniteWeights(const Eigen::Ref<const Eigen::MatrixXd>& weights);

} // namespace mocap::python

#pragma once

#include <Eigen/Core>

namespace mocap {

/// A set of 3D points, one per row (#points × 3): marker templates, neutral frames, registration input.
using PointSet = Eigen::Matrix<double, Eigen::Dynamic, 3>;

} // namespace mocap

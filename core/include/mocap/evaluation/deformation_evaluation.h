#pragma once

#include "mocap/deform/blendshape_solver.h"
#include "mocap/deform/mesh_deformer.h"
#include "mocap/deform/retarget.h"

#include <cstdint>
#include <functional>
#include <memory>

namespace mocap {


struct LeaveOutOptions
{
  double fraction = 0.2;   ///< share of the markers hidden (at least one, at least one kept)
  std::uint64_t seed = 1;  ///< which markers: the first of a seeded shuffle
  int rotations = 0;       ///< Laplacian rotation-aware iterations per frame (deformFrame)
};

struct LeaveOutResult
{
  std::vector<Eigen::Index> hidden;  ///< indices into the marker list, ascending
  Eigen::Index samples = 0;          ///< hidden-marker samples measured (valid in their frame)
  double meanError = 0.0;            ///< mean distance, take units (mm)
  double rmsError = 0.0;
  double maxError = 0.0;
  /// The same mean for a mesh left at rest (the hidden markers' mean retargeted displacement), so
  /// the error reads against how far the markers actually moved.
  double restError = 0.0;

  /// Accumulates one hidden-marker sample: its error and how far it moved from the neutral.
  void add(double error, double restDistance);
  /// Turns the sums into the means.
  void finish();

private:
  double m_sum = 0.0, m_squares = 0.0, m_restSum = 0.0;
};

/// Which markers a leave-out hides: round(fraction · count), at least one and one kept, the
/// first of a seeded shuffle, ascending. Throws InvalidArgument for fewer than 2 markers or a
/// fraction outside (0, 1). O(count).
[[nodiscard]] std::vector<Eigen::Index> chooseHiddenMarkers(std::size_t count, const LeaveOutOptions& options);

/// Leave-markers-out quality of a deformation (issue 5's measure, not a paper equation: the paper
/// compares by eye): hide a seeded share of the bound markers, deform from the rest each frame
/// (missing markers skipped), and measure the distance between each hidden marker's bound point
/// on the deformed mesh and where the retargeted marker actually is (rest point + its retargeted
/// displacement), over every frame where the hidden marker is valid; distances are divided by the
/// retarget's uniform scale to be in take units. Throws InvalidArgument for fewer than 2 markers,
/// a fraction outside (0, 1), or sizes that disagree; the factory's errors pass through.
/// O(set-up + #frames · #vertices · #kept).
[[nodiscard]] LeaveOutResult evaluateLeaveOut(const Take& take, const std::vector<Eigen::Index>& markers,
                                              const std::vector<MeshPoint>& points, Eigen::Index neutralFrame,
                                              const Retarget& retarget, const MeshVertices& rest,
                                              const DeformerFactory& factory, const LeaveOutOptions& options = {});

/// The same measure for a blendshape solve: hide a seeded share of the bound markers, solve the
/// take from the rest, and compare each hidden marker's retargeted displacement with the rig's
/// (the shapes' deltas at its bound point times the solved weights) wherever it is valid and the
/// frame was solved; take units. Throws as chooseHiddenMarkers and BlendshapeSolver::solve.
/// O(the solve + #frames · #hidden · #shapes).
[[nodiscard]] LeaveOutResult evaluateBlendshapeLeaveOut(const BlendshapeSolver& solver, const Take& take,
                                                        const LeaveOutOptions& options = {});

} // namespace mocap

#pragma once

#include "mocap/layout/blendshape_basis.h"

#include <Eigen/Core>

#include <vector>

namespace mocap {

/// How well a marker subset stands in for the full set, by two measures, from statistics computed
/// once so that each subset costs little (a layout sweep scores thousands of subsets):
///
/// - blendshapeError: Wellein et al. 2007 §3 — the mean squared difference between the blendshape
///   weights solved (0 ≤ w ≤ 1) from the subset and from the full set, over the test frames;
/// - reconstructionRmse: the other markers predicted from the subset by a linear model
///   x_U = μ_U + (x_S − μ_S)·B fitted by ridge regression on the training frames (the subset's
///   own markers are measured, error 0), scored as the RMS 3-D distance (frames' units, mm) over
///   the test frames and all markers. Not in the paper; it measures the layout directly.
///
/// Frames are rows of 3·#markers values (x, y, z of marker 0, then marker 1, …).
struct SubsetErrorOptions
{
  /// Ridge of the reconstruction model, relative to the mean variance of a coordinate: with tens
  /// of correlated input coordinates, plain least squares fits noise directions and does worse
  /// on new frames; 1e-3 ignores directions carrying less than ~0.1 % of a coordinate's variance.
  double ridge = 1e-3;
  /// Training frames (evenly spaced) whose weights trainingObjective() solves for.
  Eigen::Index objectiveFrames = 128;
  /// Weight of the blendshape term in trainingObjective() against the reconstruction term (each
  /// already divided by its no-marker value): both measures count alike. On the AnimFace and
  /// Facial-Sing takes, with greedy search also started from the PFA sets, 1.0 left 8 sizes where
  /// greedy was worse than PFA on a test measure, against 12 for 0.3 (3.0: no better, and slower
  /// searches with 512 objective frames did not help either).
  double blendshapeWeight = 1.0;
};

/// See the comment above SubsetErrorOptions. Immutable after construction: threads may share one.
class SubsetErrors
{
public:
  /// O(#frames · #coordinates² + (#test + objectiveFrames) · cost of one full-set weight solve).
  /// Throws InvalidArgument for no training or test rows, a row out of range, a basis of another
  /// width, a non-finite value, a negative ridge or blendshape weight, or objectiveFrames < 1.
  SubsetErrors(const Eigen::Ref<const Eigen::MatrixXd>& frames, const std::vector<Eigen::Index>& training,
               const std::vector<Eigen::Index>& test, BlendshapeBasis basis,
               const SubsetErrorOptions& options = {});

  [[nodiscard]] Eigen::Index markerCount() const { return m_trainingGram.rows() / 3; }
  [[nodiscard]] const BlendshapeBasis& basis() const { return m_basis; }
  /// The full set's weights on the test frames (#test × #key poses).
  [[nodiscard]] const Eigen::MatrixXd& fullWeights() const { return m_fullWeights; }
  /// RMS 3-D distance of the test frames from the training mean: the error of a layout with no
  /// markers, the scale to read reconstructionRmse against. O(1).
  [[nodiscard]] double motionRms() const;

  /// Sum of squared residuals of the linear model on the frames it was fitted on (PFA's tie-break
  /// between cluster counts giving the same size). O(|S|³ + |S|²·#coordinates) with |S| = 3·#markers
  /// in the subset.
  [[nodiscard]] double trainingResidual(const std::vector<Eigen::Index>& markers) const;
  /// See the class comment. O(|S|³ + |S|²·#coordinates).
  [[nodiscard]] double reconstructionRmse(const std::vector<Eigen::Index>& markers) const;
  /// See the class comment. O(#test · #key poses · (|S| + steps · #key poses²)).
  [[nodiscard]] double blendshapeError(const std::vector<Eigen::Index>& markers) const;
  /// What a selection should minimise, from training frames only: the reconstruction error on a
  /// held-apart quarter of the training frames (model fitted on the rest, so a selection is not
  /// rewarded for fitting noise) plus blendshapeWeight × the blendshape-weight error on
  /// objectiveFrames training frames, each divided by its value for no markers.
  /// O(trainingResidual + objectiveFrames · one weight solve).
  [[nodiscard]] double trainingObjective(const std::vector<Eigen::Index>& markers) const;

private:
  [[nodiscard]] std::vector<Eigen::Index> coordinates(const std::vector<Eigen::Index>& markers) const;
  [[nodiscard]] std::vector<Eigen::Index> complement(const std::vector<Eigen::Index>& coordinates) const;
  [[nodiscard]] double heldOutError(const Eigen::MatrixXd& fitGram, const Eigen::MatrixXd& evaluatedGram,
                                    const std::vector<Eigen::Index>& coordinates) const;
  /// `offsets`: frames minus the neutral, one frame per column (#coordinates × #frames).
  [[nodiscard]] double weightError(const std::vector<Eigen::Index>& coordinates,
                                   const Eigen::MatrixXd& offsets, const Eigen::MatrixXd& fullWeights) const;

  Eigen::MatrixXd m_trainingGram;    // centred training Gram matrix XᵀX
  Eigen::MatrixXd m_testGram;        // test frames centred on the training mean
  Eigen::MatrixXd m_fitGram;         // the objective's split of the training frames: fitted part...
  Eigen::MatrixXd m_validationGram;  // ...and held-apart part, centred on the fitted part's mean
  Eigen::MatrixXd m_testFrames;      // test rows, raw
  Eigen::Index m_testCount = 0;
  double m_ridge = 0.0;  // absolute
  double m_blendshapeWeight = 0.3;
  BlendshapeBasis m_basis;
  Eigen::MatrixXd m_fullWeights;
  Eigen::MatrixXd m_objectiveFrames;   // training rows the objective solves weights for
  Eigen::MatrixXd m_objectiveWeights;  // their full-set weights
  Eigen::MatrixXd m_testOffsets;       // test frames minus the neutral, transposed
  Eigen::MatrixXd m_objectiveOffsets;  // objective frames minus the neutral, transposed
  double m_emptyResidual = 0.0;
  double m_emptyWeightError = 0.0;
};

} // namespace mocap

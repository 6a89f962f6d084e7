#pragma once

#include "mocap/cleaning/fill/gap_prediction.h"

#include <vector>

namespace mocap {

/// Tuning of the `pca` method.
struct PcaFillOptions
{
  double varianceKept = 0.999;    ///< components kept explain this share of the variance (0, 1]
  int iterations = 8;             ///< at most this many re-estimations of the model (≥ 1)
  double minValidFraction = 0.5;  ///< markers valid in fewer frames are left out of the model
};

/// `pca`: gaps recovered from marker inter-correlations, in the spirit of Gløersen & Federolf
/// (2016). The take is a #frames × 3·#markers matrix; the principal components of the frames where
/// every modelled marker is valid (all frames, linearly interpolated, when there are too few) give
/// a low-rank model, and each frame's missing coordinates become the model's conditional mean
/// given its known ones (probabilistic PCA: coefficients c = (U_Kᵀ U_K + σ²Λ⁻¹)⁻¹ U_Kᵀ (x_K − μ_K),
/// then x_M = μ_M + U_M c); the model is then re-estimated from the completed matrix and the
/// reconstruction repeated (EM). Works when many markers are missing at once. Each gap's track is
/// finally shifted onto its border samples (border_blend.h) so the fill does not jump. Not a paper
/// equation (the paper's recovery is eqs 3-7).
class PcaFillModel
{
public:
  /// Builds the model of `take`, which must outlive it unchanged.
  /// O(iterations · (#frames · D² + D³ + #patterns · D · k²)), D = 3·#markers, k components,
  /// #patterns the distinct sets of missing markers. Throws InvalidArgument for options out of
  /// range.
  explicit PcaFillModel(const Take& take, const PcaFillOptions& options = {});

  /// The model's fill for one gap of the take it was built from: each frame's conditional mean
  /// given the markers valid in it, the marker itself hidden (so a leave-out pseudo-gap of valid
  /// samples is predicted without its own data). Not filled (reason given) when the marker or the
  /// whole take was left out of the model. Throws InvalidArgument for a gap of another take.
  /// O(length · D · k + #patterns · (D · k² + k³)).
  [[nodiscard]] GapPrediction predict(const GapQuery& gap) const;

  /// Whether a model could be built (at least two markers valid often enough, and enough frames).
  [[nodiscard]] bool usable() const { return m_components.cols() > 0; }

private:
  [[nodiscard]] Eigen::Matrix<double, Eigen::Dynamic, 3>
  reconstructSpan(Eigen::Index first, Eigen::Index last, Eigen::Index marker) const;

  const Take* m_take = nullptr;
  std::vector<Eigen::Index> m_column;   // per take marker: its block in the model, or −1
  std::vector<Eigen::Index> m_markers;  // model block → take marker
  Eigen::MatrixXd m_completed;          // #frames × D, missing entries reconstructed
  Eigen::RowVectorXd m_mean;
  Eigen::MatrixXd m_components;  // D × k
  Eigen::VectorXd m_variances;   // k
  double m_noise = 0.0;          // σ², the mean variance of the dropped components
  std::string m_unusableReason;
};

} // namespace mocap

#pragma once

#include "mocap/cleaning/fill/fill_context.h"
#include "mocap/cleaning/fill/gap_prediction.h"

#include <utility>
#include <vector>

namespace mocap {

struct RegressionFillOptions
{
  int neighbours = 10;                   ///< K predictor markers, 1..1000
  double ridge = 1e-2;                   ///< Tikhonov weight relative to the mean feature variance, ≥ 0
  Eigen::Index maxTrainingFrames = 150;  ///< frames used for fitting (evenly thinned), ≥ 10
  Eigen::Index window = 1500;            ///< training frames come from this far either side of the gap, ≥ 1
};

/// A fitted linear model of one marker on K others: P(t) = P̄ + Wᵀ(Q(t) − Q̄), Q(t) the 3K
/// coordinates of the predictors in frame t. Not a paper equation: learned weights in place of
/// eq 5's distance-based ones.
struct RegressionFit
{
  std::vector<Eigen::Index> predictors;
  Eigen::RowVectorXd featureMean;
  Eigen::RowVector3d targetMean = Eigen::RowVector3d::Zero();
  Eigen::Matrix<double, Eigen::Dynamic, 3> weights;

  /// The model's track for frames first − 1 … first + length (length + 2 rows), ready for
  /// blendBorders; rows of frames outside the take are meaningless (blendBorders ignores them).
  /// The predictors must be valid there. O(length · K).
  [[nodiscard]] Eigen::Matrix<double, Eigen::Dynamic, 3> track(const Take& take, Eigen::Index first,
                                                               Eigen::Index length) const;
  /// The model applied to predictor coordinates from predictorTrack() (extra columns, for more
  /// predictors of the same ranking, are ignored). O(rows · K).
  [[nodiscard]] Eigen::Matrix<double, Eigen::Dynamic, 3> apply(const Eigen::MatrixXd& coordinates) const;
};

/// The coordinates of `predictors` for frames first − 1 … first + length: length + 2 rows,
/// 3 · #predictors columns (x, y, z of each), rows outside the take 0. Not a paper equation.
/// O(length · #predictors).
[[nodiscard]] Eigen::MatrixXd predictorTrack(const Take& take, const std::vector<Eigen::Index>& predictors,
                                             Eigen::Index first, Eigen::Index length);

/// A frame range [first, last] kept out of a fit (a validation gap).
using FrameRange = std::pair<Eigen::Index, Eigen::Index>;

/// The least-squares sums of one marker on its ranked predictors, from which fits with the first
/// k predictors, any ridge weight, and with or without the held-out frames are cheap. Not a
/// paper equation.
struct RegressionSystem
{
  std::vector<Eigen::Index> predictors;  ///< steadiest first
  std::string reason;                    ///< why there is no system (predictors empty)

  [[nodiscard]] bool usable() const { return !predictors.empty(); }
  /// The fit on the first `count` predictors (clamped to K and to the frames available) with ridge
  /// weight `ridge` relative to their mean feature variance, on all training frames or on those
  /// outside the held-out ranges. Empty predictors when too few frames remain. O(count³).
  [[nodiscard]] RegressionFit solve(Eigen::Index count, double ridge, bool withoutHeldOut = false) const;

  // Sums over the training frames (relative to `origin`, `targetOrigin` for accuracy) and over
  // the held-out part of them.
  Eigen::RowVectorXd origin;
  Eigen::RowVector3d targetOrigin = Eigen::RowVector3d::Zero();
  struct Sums
  {
    Eigen::Index frames = 0;
    Eigen::RowVectorXd x;
    Eigen::RowVector3d y = Eigen::RowVector3d::Zero();
    Eigen::MatrixXd xx;
    Eigen::Matrix<double, Eigen::Dynamic, 3> xy;
  };
  Sums all;
  Sums heldOut;
};

/// Builds the regression of `marker` (validity `markerValid`) on the K markers that moved most
/// like it: among the markers valid in every frame from `from` to `to` and without a jump there
/// (a step over ten times their usual large step, such as a label swap), those whose offset to
/// it varied least over the frames around where both are valid (and valid in 3/4 of them), so
/// the other eyelid predicts a blink wherever it sits. Training frames: the context's grid
/// frames within options.window of [from, to] where the marker and the K are valid, thinned
/// evenly to maxTrainingFrames; those inside `heldOut` are summed apart as well. Not a paper
/// equation (eq 5's weights are fixed by distance; these are learned). O(#markers · (100 + to −
/// from) + T · K²), T = maxTrainingFrames. Throws InvalidArgument for options out of range.
[[nodiscard]] RegressionSystem buildRegression(const FillContext& context, Eigen::Index marker,
                                               const Eigen::Ref<const ValidMask>& markerValid,
                                               Eigen::Index from, Eigen::Index to,
                                               const RegressionFillOptions& options = {},
                                               const std::vector<FrameRange>& heldOut = {});

/// Regression fill: buildRegression for predictors valid through the gap and its borders, solved
/// with K = options.neighbours, evaluated through the gap and on the border frames and shifted
/// onto the border samples with blendBorders (smooth ramp), so the fill uses both ends and meets
/// them without a jump. Facial markers move together, so a linear model of the take predicts a
/// missing marker from the markers that are there far better than displacements copied from
/// neighbours frame by frame, and it does not drift. Not a paper equation (replaces eq 5's
/// distance weights by learned ones). Not filled (reason given) without a suitable predictor or
/// with fewer training frames than 3K + 1. `context` (of gap.take) saves O(#frames · #markers)
/// per call. O(#markers · (100 + length) + T · K² + K³).
[[nodiscard]] GapPrediction predictRegression(const GapQuery& gap, const RegressionFillOptions& options = {},
                                              const FillContext* context = nullptr);

} // namespace mocap

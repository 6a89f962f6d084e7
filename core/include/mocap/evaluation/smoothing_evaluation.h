#pragma once

#include "mocap/cleaning/smoothing.h"
#include "mocap/model/take.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace mocap {

/// The configurations `mocap eval-smooth` compares: the default (SmoothOptions{}) first, then
/// the paper's cubic B-spline, Butterworth at 6 Hz and by Winter's residual analysis, GCVSPL
/// cubic and quintic by GCV, and Savitzky–Golay 9/3 (entries equal to the default are left out).
/// O(1). No paper equation (the paper compares no smoothers).
[[nodiscard]] std::vector<SmoothOptions> evaluatedSmoothOptions();

/// A copy of `take` in millimetres with independent Gaussian noise of standard deviation
/// `noiseMm` added to each coordinate of each valid sample (invalid samples untouched). The
/// normal deviates come from mocap::Random (Box–Muller), so a seed gives the same noise with
/// every compiler (no paper equation). Throws InvalidArgument unless noiseMm is
/// finite and ≥ 0.
/// O(#frames · #markers).
[[nodiscard]] Take addMeasurementNoise(const Take& take, double noiseMm, std::uint64_t seed);

struct SmoothingEvaluationOptions
{
  double noiseMm = 0.5;
  std::uint64_t seed = 1;
  std::vector<SmoothOptions> methods = evaluatedSmoothOptions();
};

/// One configuration's errors against the clean take.
struct SmoothingScore
{
  SmoothOptions options;
  std::string parameters;         ///< describeSmoothOptions
  bool isDefault = false;         ///< the options equal SmoothOptions{}
  double rmse = 0.0;              ///< mm, RMS over every coordinate of every valid sample
  double accelerationRmse = 0.0;  ///< mm/s², same over interior samples of the runs
  double seconds = 0.0;           ///< wall time of smoothing the whole take
};

struct SmoothingEvaluation
{
  double noiseMm = 0.0;
  std::uint64_t seed = 0;
  Eigen::Index samples = 0;              ///< valid samples scored (positions)
  Eigen::Index accelerationSamples = 0;  ///< interior samples scored (accelerations)
  double noisyRmse = 0.0;                ///< the noisy take's own errors, for scale
  double noisyAccelerationRmse = 0.0;
  std::vector<SmoothingScore> scores;  ///< in the order of the options' methods
};

/// The eval-smooth protocol: `take` is taken as the clean truth (the bundled takes are already
/// smooth: their own high-frequency content is far below the added noise), addMeasurementNoise
/// makes the noisy input, and each configuration smooths it with smoothTake. Scores compare with
/// the clean take: position RMSE (mm) over every coordinate of every valid sample, and the RMS
/// error of the acceleration by central second differences (x_{i+1} − 2x_i + x_{i−1}) · fs² in
/// mm/s² over samples with a valid neighbour on both sides within the same run. Throws
/// InvalidArgument for a bad noise level or options. O(#configurations · smoothing cost). No paper
/// equation (the paper reports no error against truth).
[[nodiscard]] SmoothingEvaluation evaluateSmoothing(const Take& take,
                                                    const SmoothingEvaluationOptions& options = {});

/// The smoothness figure of the paper's Table 1 ("variances of the vectors grouped using two
/// neighbours"), read as: the population variance of the lengths |P_i − P_{i−1}| of the
/// displacement vectors between consecutive valid frames of one run, pooled over the marker's
/// runs (mm² when positions are in mm). Zero with fewer than two such vectors. O(#frames).
[[nodiscard]] double
displacementLengthVariance(const Eigen::Ref<const Eigen::Matrix<double, Eigen::Dynamic, 3>>& xyz,
                           const Eigen::Ref<const ValidMask>& valid);

/// The exact definition of the smoothness figure (Table 1), as text for reports. O(1).
[[nodiscard]] std::string smoothnessMeasureDefinition();

struct SmoothnessTableOptions
{
  std::vector<Eigen::Index> markers;  ///< markers to average over; empty: every marker
  int lowestDegree = 3;               ///< the paper's orders 3..7 (= spline degree, eqs 11–12)
  int highestDegree = 7;
  double knotSpacing = SmoothOptions{}.knotSpacing;
  /// Preprocessing for the extra "order 3 with preprocessing" row (e.g. spike replacement,
  /// eqs 8–10); no such row when empty. Runs on a millimetre copy of the take.
  std::function<void(Take&)> preprocess;
  std::string preprocessName = "spikes";
  int preprocessedDegree = 3;
};

struct SmoothnessRow
{
  int order = 3;                  ///< B-spline degree, the paper's order
  std::string preprocessing;      ///< empty: none
  double smoothness = 0.0;        ///< mean over the markers of displacementLengthVariance, mm²
  std::vector<double> perMarker;  ///< in the order of SmoothnessTable::markers
};

struct SmoothnessTable
{
  std::vector<Eigen::Index> markers;
  double rawSmoothness = 0.0;  ///< the same figure before any smoothing
  std::vector<SmoothnessRow> rows;
};

/// The paper's Table 1 on `take`: fits the least-squares B-spline (bspline_fit.h, knot spacing
/// from the options) of each degree to every valid run of the chosen markers (in millimetres) and
/// reports displacementLengthVariance averaged over them, plus the preprocessed row when asked.
/// Throws InvalidArgument for a marker index out of range or bad degrees/spacing.
/// O((#degrees + 1) · #markers · #frames · degree²).
[[nodiscard]] SmoothnessTable smoothnessTable(const Take& take, const SmoothnessTableOptions& options = {});

} // namespace mocap

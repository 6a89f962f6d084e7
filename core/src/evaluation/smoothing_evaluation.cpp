#include "mocap/evaluation/smoothing_evaluation.h"

#include "mocap/cleaning/bspline_fit.h"
#include "mocap/base/error.h"
#include "mocap/base/random.h"
#include "mocap/model/valid_runs.h"

#include <chrono>
#include <cmath>

namespace mocap {

namespace {

// Sum of squared position and acceleration errors of `test` against `clean` (same validity).
struct ErrorSums
{
  double position = 0.0;
  double acceleration = 0.0;
  Eigen::Index samples = 0;
  Eigen::Index interior = 0;
};

ErrorSums compare(const Take& clean, const Take& test)
{
  ErrorSums sums;
  const double rate2 = clean.frameRate() * clean.frameRate();
  for (Eigen::Index m = 0; m < clean.markerCount(); ++m) {
    const auto a = clean.trajectory(m);
    const auto b = test.trajectory(m);
    const ValidMask usable = clean.valid().col(m) && a.array().isFinite().rowwise().all();
    for (const ValidRun& run : findValidRuns(usable)) {
      const Eigen::Index end = run.first + run.length;
      sums.position +=
          (a.middleRows(run.first, run.length) - b.middleRows(run.first, run.length)).squaredNorm();
      sums.samples += run.length;
      for (Eigen::Index f = run.first + 1; f + 1 < end; ++f) {
        const Eigen::RowVector3d accA = a.row(f + 1) - 2.0 * a.row(f) + a.row(f - 1);
        const Eigen::RowVector3d accB = b.row(f + 1) - 2.0 * b.row(f) + b.row(f - 1);
        sums.acceleration += (accA - accB).squaredNorm() * rate2 * rate2;
        ++sums.interior;
      }
    }
  }
  return sums;
}

double rootMean(double sum, Eigen::Index count)
{
  return count > 0 ? std::sqrt(sum / static_cast<double>(3 * count)) : 0.0;
}

Take inMillimetres(const Take& take)
{
  Take copy = take;
  copy.convertUnits(LengthUnit::Millimetre);
  return copy;
}

struct VarianceSum
{
  double variance = 0.0;
  Eigen::Index count = 0;
};

VarianceSum lengthVariance(const Eigen::Ref<const Eigen::Matrix<double, Eigen::Dynamic, 3>>& xyz,
                           const Eigen::Ref<const ValidMask>& valid)
{
  // Two-pass over the pooled lengths: mean first, then squared deviations (no cancellation).
  const std::vector<ValidRun> runs = findValidRuns(valid);
  double sum = 0.0;
  Eigen::Index count = 0;
  for (const ValidRun& run : runs)
    for (Eigen::Index f = run.first + 1; f < run.first + run.length; ++f) {
      sum += (xyz.row(f) - xyz.row(f - 1)).norm();
      ++count;
    }
  if (count < 2)
    return {0.0, count};
  const double mean = sum / static_cast<double>(count);
  double squares = 0.0;
  for (const ValidRun& run : runs)
    for (Eigen::Index f = run.first + 1; f < run.first + run.length; ++f) {
      const double d = (xyz.row(f) - xyz.row(f - 1)).norm() - mean;
      squares += d * d;
    }
  return {squares / static_cast<double>(count), count};
}

// Mean of the per-marker figure over markers that have one, and the per-marker values.
SmoothnessRow smoothnessOf(const Take& take, const std::vector<Eigen::Index>& markers,
                           const SmoothOptions* smoothing)
{
  SmoothnessRow row;
  double sum = 0.0;
  int counted = 0;
  for (Eigen::Index m : markers) {
    const ValidMask valid = take.valid().col(m) && take.trajectory(m).array().isFinite().rowwise().all();
    VarianceSum v;
    if (smoothing) {
      const Eigen::Matrix<double, Eigen::Dynamic, 3> smoothed =
          smoothTrajectory(take.trajectory(m), valid, take.frameRate(), *smoothing);
      v = lengthVariance(smoothed, valid);
    } else {
      v = lengthVariance(take.trajectory(m), valid);
    }
    row.perMarker.push_back(v.variance);
    if (v.count >= 2) {
      sum += v.variance;
      ++counted;
    }
  }
  row.smoothness = counted > 0 ? sum / counted : 0.0;
  return row;
}

} // namespace

std::vector<SmoothOptions> evaluatedSmoothOptions()
{
  std::vector<SmoothOptions> list{SmoothOptions{}};
  const auto add = [&list](SmoothOptions o) {
    if (o != SmoothOptions{})
      list.push_back(o);
  };
  SmoothOptions o;
  o.method = SmoothMethod::BSpline;
  add(o);
  o = {};
  o.method = SmoothMethod::Butterworth;
  add(o);
  o.winterCutoff = true;
  add(o);
  o = {};
  o.method = SmoothMethod::Gcvspl;
  o.gcvsplMode = SmoothingSplineMode::Gcv;
  o.gcvsplDegree = 3;
  add(o);
  o.gcvsplDegree = 5;
  add(o);
  o = {};
  o.method = SmoothMethod::SavGol;
  add(o);
  return list;
}

Take addMeasurementNoise(const Take& take, double noiseMm, std::uint64_t seed)
{
  if (!std::isfinite(noiseMm) || noiseMm < 0.0)
    throw InvalidArgument("noise must be a finite number of millimetres ≥ 0, not " + std::to_string(noiseMm));
  Take noisy = inMillimetres(take);
  Random random(seed);
  for (Eigen::Index m = 0; m < noisy.markerCount(); ++m) {
    auto xyz = noisy.trajectory(m);
    for (Eigen::Index f = 0; f < noisy.frameCount(); ++f)
      if (noisy.isValid(f, m))
        for (Eigen::Index c = 0; c < 3; ++c)
          xyz(f, c) += noiseMm * random.normal();
  }
  return noisy;
}

SmoothingEvaluation evaluateSmoothing(const Take& take, const SmoothingEvaluationOptions& options)
{
  for (const SmoothOptions& o : options.methods)
    checkSmoothOptions(o, take.frameRate());
  const Take clean = inMillimetres(take);
  const Take noisy = addMeasurementNoise(take, options.noiseMm, options.seed);
  SmoothingEvaluation result;
  result.noiseMm = options.noiseMm;
  result.seed = options.seed;
  const ErrorSums raw = compare(clean, noisy);
  result.samples = raw.samples;
  result.accelerationSamples = raw.interior;
  result.noisyRmse = rootMean(raw.position, raw.samples);
  result.noisyAccelerationRmse = rootMean(raw.acceleration, raw.interior);
  for (const SmoothOptions& o : options.methods) {
    Take smoothed = noisy;
    const auto start = std::chrono::steady_clock::now();
    applyPatches(smoothed, smoothTake(noisy, o));
    const auto stop = std::chrono::steady_clock::now();
    const ErrorSums sums = compare(clean, smoothed);
    SmoothingScore score;
    score.options = o;
    score.parameters = describeSmoothOptions(o);
    score.isDefault = o == SmoothOptions{};
    score.rmse = rootMean(sums.position, sums.samples);
    score.accelerationRmse = rootMean(sums.acceleration, sums.interior);
    score.seconds = std::chrono::duration<double>(stop - start).count();
    result.scores.push_back(std::move(score));
  }
  return result;
}

double displacementLengthVariance(const Eigen::Ref<const Eigen::Matrix<double, Eigen::Dynamic, 3>>& xyz,
                                  const Eigen::Ref<const ValidMask>& valid)
{
  if (xyz.rows() != valid.size())
    throw InvalidArgument("smoothness: " + std::to_string(xyz.rows()) + " positions but " +
                          std::to_string(valid.size()) + " validity flags");
  return lengthVariance(xyz, valid).variance;
}

std::string smoothnessMeasureDefinition()
{
  return "population variance of the lengths |P_i - P_(i-1)| (mm) of the displacement vectors between "
         "consecutive frames of each valid run, pooled over a marker's runs (mm^2), then averaged over the "
         "markers";
}

SmoothnessTable smoothnessTable(const Take& take, const SmoothnessTableOptions& options)
{
  for (int degree : {options.lowestDegree, options.highestDegree, options.preprocessedDegree})
    checkBSplineFitOptions({degree, options.knotSpacing});
  if (options.lowestDegree > options.highestDegree)
    throw InvalidArgument("smoothness table: lowest degree above the highest");
  SmoothnessTable table;
  table.markers = options.markers;
  if (table.markers.empty())
    for (Eigen::Index m = 0; m < take.markerCount(); ++m)
      table.markers.push_back(m);
  for (Eigen::Index m : table.markers)
    if (m < 0 || m >= take.markerCount())
      throw InvalidArgument("smoothness table: marker index " + std::to_string(m) + " out of range");
  const Take mm = inMillimetres(take);
  table.rawSmoothness = smoothnessOf(mm, table.markers, nullptr).smoothness;
  SmoothOptions spline;
  spline.method = SmoothMethod::BSpline;
  spline.knotSpacing = options.knotSpacing;
  for (int degree = options.lowestDegree; degree <= options.highestDegree; ++degree) {
    spline.degree = degree;
    SmoothnessRow row = smoothnessOf(mm, table.markers, &spline);
    row.order = degree;
    table.rows.push_back(std::move(row));
  }
  if (options.preprocess) {
    Take preprocessed = mm;
    options.preprocess(preprocessed);
    spline.degree = options.preprocessedDegree;
    SmoothnessRow row = smoothnessOf(preprocessed, table.markers, &spline);
    row.order = options.preprocessedDegree;
    row.preprocessing = options.preprocessName;
    table.rows.push_back(std::move(row));
  }
  return table;
}

} // namespace mocap

#include "mocap/cleaning/smoothing.h"

#include "mocap/base/enum_table.h"
#include "mocap/cleaning/bspline_fit.h"
#include "mocap/cleaning/butterworth_filter.h"
#include "mocap/base/error.h"
#include "mocap/base/number_text.h"
#include "mocap/cleaning/savitzky_golay.h"
#include "mocap/model/marker_points.h"
#include "mocap/model/valid_runs.h"
#include "mocap/cleaning/winter_cutoff.h"

#include <cmath>
#include <map>

namespace mocap {

namespace {

using Trajectory = Eigen::Matrix<double, Eigen::Dynamic, 3>;

// Rows whose three coordinates are finite; column by column, so each test runs over contiguous memory.
ValidMask finiteRows(const Eigen::Ref<const Trajectory>& xyz)
{
  return xyz.col(0).array().isFinite() && xyz.col(1).array().isFinite() && xyz.col(2).array().isFinite();
}

SmoothingSplineOptions splineOptions(const SmoothOptions& options)
{
  return {options.gcvsplDegree, options.gcvsplMode, options.errorVariance, options.cutoffHz};
}

// Smooths trajectories with one set of options, keeping B-spline factorisations by run length so
// that a take whose markers share run lengths (the usual case) factorises once.
class TrajectorySmoother
{
public:
  TrajectorySmoother(const SmoothOptions& options, double frameRate)
      : m_options(options), m_frameRate(frameRate)
  {
    checkSmoothOptions(options, frameRate);
  }

  // The samples a filter may use: valid ones with finite coordinates (a valid sample holding a
  // NaN or infinity is treated as a gap and never enters a filter).
  static ValidMask usableSamples(const Eigen::Ref<const Trajectory>& xyz,
                                 const Eigen::Ref<const ValidMask>& valid)
  {
    if (xyz.rows() != valid.size())
      throw InvalidArgument("smoothing: " + std::to_string(xyz.rows()) + " positions but " +
                            std::to_string(valid.size()) + " validity flags");
    return valid && finiteRows(xyz);
  }

  // Rows outside `usable` come back as they are.
  Trajectory smooth(const Eigen::Ref<const Trajectory>& xyz, const ValidMask& usable)
  {
    Trajectory result = xyz;
    ValidMask changed;
    smoothRuns(xyz, usable, result, changed);
    return result;
  }

  // Writes the smoothed runs into their rows of `out` (the others untouched, so `out` needs no
  // copy of `xyz`) and sets `changed` (resized to the frames) where a smoothed position differs.
  void smoothRuns(const Eigen::Ref<const Trajectory>& xyz, const ValidMask& usable, Trajectory& out,
                  ValidMask& changed)
  {
    out.resize(xyz.rows(), 3);
    changed.setConstant(xyz.rows(), false);
    double cutoff = m_options.cutoffHz;
    if (m_options.method == SmoothMethod::Butterworth && m_options.winterCutoff)
      cutoff = winterCutoff(xyz, usable, m_frameRate).cutoffHz;
    const Eigen::Index minLength = minSmoothRunLength(m_options);
    for (const ValidRun& run : findValidRuns(usable)) {
      if (run.length < minLength)
        continue;
      const auto samples = xyz.middleRows(run.first, run.length);
      auto smoothed = out.middleRows(run.first, run.length);
      switch (m_options.method) {
      case SmoothMethod::BSpline: fitter(run.length).fit(samples, smoothed); break;
      case SmoothMethod::Butterworth: smoothed = butterworthFilter(samples, m_frameRate, cutoff); break;
      case SmoothMethod::Gcvspl:
        smoothed = smoothingSpline(samples, m_frameRate, splineOptions(m_options)).smoothed;
        break;
      case SmoothMethod::SavGol:
        smoothed = savitzkyGolay(samples, {m_options.savgolWindow, m_options.savgolDegree});
        break;
      }
      // Column-wise comparison (contiguous) rather than row by row.
      changed.segment(run.first, run.length) = (smoothed.col(0).array() != samples.col(0).array()) ||
                                               (smoothed.col(1).array() != samples.col(1).array()) ||
                                               (smoothed.col(2).array() != samples.col(2).array());
    }
  }

private:
  const BSplineFitter& fitter(Eigen::Index length)
  {
    auto it = m_fitters.find(length);
    if (it == m_fitters.end()) {
      // A take whose runs all differ in length would otherwise keep a basis table per run (40 bytes
      // a sample: tens of MB of fresh pages for a long take); the usual repeated lengths stay cached.
      if (m_fitters.size() >= kMaxFitters)
        m_fitters.clear();
      it = m_fitters.emplace(length, BSplineFitter(length, {m_options.degree, m_options.knotSpacing})).first;
    }
    return it->second;
  }

  static constexpr std::size_t kMaxFitters = 32;

  SmoothOptions m_options;
  double m_frameRate;
  std::map<Eigen::Index, BSplineFitter> m_fitters;
};

// Smooths each marker point of `take` (model outputs are left alone) in turn and calls visit(marker, smoothed, changed): `changed` the
// marker's usable samples whose position the smoothing changed, `smoothed` holding their new
// positions (its other rows are undefined). `visit` may write marker `marker` of the take (the
// smoothing has read it by then).
template <typename Visit>
void smoothMarkers(const Take& take, const SmoothOptions& options, const JobControl& job, Visit&& visit)
{
  TrajectorySmoother smoother(options, take.frameRate());
  Trajectory smoothed;  // one buffer for every marker
  ValidMask changed;
  for (Eigen::Index m = 0; m < take.markerCount(); ++m) {
    job.checkpoint(static_cast<double>(m) / static_cast<double>(take.markerCount()));
    const auto xyz = take.trajectory(m);
    if (isMarker(take, m))
      smoother.smoothRuns(xyz, TrajectorySmoother::usableSamples(xyz, take.valid().col(m)), smoothed, changed);
    else
      changed.setConstant(take.frameCount(), false);
    visit(m, static_cast<const Trajectory&>(smoothed), static_cast<const ValidMask&>(changed));
  }
}

std::string number(double value)
{
  std::string text;
  appendNumber(text, value);
  return text;
}

} // namespace

namespace {

constexpr EnumTable<SmoothMethod, 4> kSmoothMethods{{{
    {SmoothMethod::BSpline, "bspline"},
    {SmoothMethod::Butterworth, "butterworth"},
    {SmoothMethod::Gcvspl, "gcvspl"},
    {SmoothMethod::SavGol, "savgol"},
}}};

} // namespace

std::optional<SmoothMethod> parseSmoothMethod(std::string_view name)
{
  return kSmoothMethods.parse(name);
}

std::string_view smoothMethodName(SmoothMethod method)
{
  return kSmoothMethods.name(method, "bspline");
}

std::string smoothMethodNames()
{
  return kSmoothMethods.names();
}

bool operator==(const SmoothOptions& a, const SmoothOptions& b)
{
  return a.method == b.method && a.degree == b.degree && a.knotSpacing == b.knotSpacing &&
         a.cutoffHz == b.cutoffHz && a.winterCutoff == b.winterCutoff && a.gcvsplMode == b.gcvsplMode &&
         a.gcvsplDegree == b.gcvsplDegree && a.errorVariance == b.errorVariance &&
         a.savgolWindow == b.savgolWindow && a.savgolDegree == b.savgolDegree;
}

void checkSmoothOptions(const SmoothOptions& options, double frameRate)
{
  if (!std::isfinite(frameRate) || frameRate <= 0.0)
    throw InvalidArgument("smoothing: frame rate must be finite and positive, not " +
                          std::to_string(frameRate));
  switch (options.method) {
  case SmoothMethod::BSpline: checkBSplineFitOptions({options.degree, options.knotSpacing}); break;
  case SmoothMethod::Butterworth:
    if (!options.winterCutoff)
      (void)butterworthLowPass(frameRate, options.cutoffHz);
    break;
  case SmoothMethod::Gcvspl:
    checkSmoothingSplineOptions(splineOptions(options));
    if (options.gcvsplMode == SmoothingSplineMode::Cutoff)
      (void)smoothingSplineLambda(options.gcvsplDegree, frameRate, options.cutoffHz);
    break;
  case SmoothMethod::SavGol: checkSavitzkyGolayOptions({options.savgolWindow, options.savgolDegree}); break;
  }
}

std::string describeSmoothOptions(const SmoothOptions& options)
{
  switch (options.method) {
  case SmoothMethod::BSpline:
    return "degree=" + std::to_string(options.degree) + " knot_spacing=" + number(options.knotSpacing);
  case SmoothMethod::Butterworth:
    return options.winterCutoff ? std::string("cutoff=winter") : "cutoff_hz=" + number(options.cutoffHz);
  case SmoothMethod::Gcvspl: {
    std::string text = std::string(options.gcvsplDegree == 5 ? "quintic" : "cubic") +
                       " mode=" + std::string(smoothingSplineModeName(options.gcvsplMode));
    if (options.gcvsplMode == SmoothingSplineMode::ErrorVariance)
      text += " variance=" + number(options.errorVariance);
    if (options.gcvsplMode == SmoothingSplineMode::Cutoff)
      text += " cutoff_hz=" + number(options.cutoffHz);
    return text;
  }
  case SmoothMethod::SavGol:
    return "window=" + std::to_string(options.savgolWindow) +
           " degree=" + std::to_string(options.savgolDegree);
  }
  return {};
}

Eigen::Index minSmoothRunLength(const SmoothOptions& options)
{
  switch (options.method) {
  case SmoothMethod::BSpline: return minBSplineRunLength(options.degree);
  case SmoothMethod::Butterworth: return kMinButterworthRunLength;
  case SmoothMethod::Gcvspl: return minSmoothingSplineRunLength(options.gcvsplDegree);
  case SmoothMethod::SavGol: return options.savgolWindow;
  }
  return 0;
}

Eigen::Matrix<double, Eigen::Dynamic, 3>
smoothTrajectory(const Eigen::Ref<const Eigen::Matrix<double, Eigen::Dynamic, 3>>& xyz,
                 const Eigen::Ref<const ValidMask>& valid, double frameRate, const SmoothOptions& options)
{
  TrajectorySmoother smoother(options, frameRate);
  return smoother.smooth(xyz, TrajectorySmoother::usableSamples(xyz, valid));
}

std::vector<SamplePatch> smoothTake(const Take& take, const SmoothOptions& options, const JobControl& job)
{
  std::vector<SamplePatch> patches;
  patches.reserve(static_cast<std::size_t>(take.markerCount()));
  smoothMarkers(take, options, job, [&](Eigen::Index m, const Trajectory& smoothed, const ValidMask& changed) {
    std::vector<Eigen::Index> frames;
    frames.reserve(static_cast<std::size_t>(changed.count()));
    for (Eigen::Index f = 0; f < take.frameCount(); ++f)
      if (changed(f))
        frames.push_back(f);
    SamplePatch patch;
    patch.marker = m;
    patch.positions = smoothed(frames, Eigen::all);
    patch.valid = ValidMask::Constant(patch.positions.rows(), true);
    patch.residuals = take.residuals().col(m)(frames);
    patch.states.reserve(frames.size());
    for (const Eigen::Index f : frames)
      patch.states.push_back(take.state(f, m).with(SampleOperation::Smoothed));
    patch.frames = std::move(frames);
    patches.push_back(std::move(patch));
  });
  return patches;
}

Eigen::Index smoothTakeInPlace(Take& take, const SmoothOptions& options, const JobControl& job)
{
  Eigen::Index count = 0;
  smoothMarkers(take, options, job, [&](Eigen::Index m, const Trajectory& smoothed, const ValidMask& changed) {
    auto trajectory = take.trajectory(m);
    auto states = take.states().col(m);
    for (Eigen::Index f = 0; f < take.frameCount(); ++f)
      if (changed(f)) {
        trajectory.row(f) = smoothed.row(f);
        states(f) = SampleState::fromBits(states(f)).with(SampleOperation::Smoothed).bits();
        ++count;
      }
  });
  return count;
}

} // namespace mocap

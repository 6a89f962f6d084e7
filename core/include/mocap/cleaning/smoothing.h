#pragma once

#include "mocap/model/sample_patch.h"
#include "mocap/base/job_control.h"
#include "mocap/cleaning/smoothing_spline.h"
#include "mocap/model/take.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mocap {

/// The trajectory smoothers. Every one works on each valid run separately, so a gap never
/// reaches a filter and two runs are never mixed.
enum class SmoothMethod
{
  BSpline,      ///< least-squares clamped B-spline, the paper's eqs 11–12 (bspline_fit.h)
  Butterworth,  ///< zero-lag Butterworth low-pass (butterworth_filter.h)
  Gcvspl,       ///< Woltring's generalised cross-validated smoothing spline (smoothing_spline.h)
  SavGol,       ///< Savitzky–Golay (savitzky_golay.h)
};

/// "bspline", "butterworth", "gcvspl", "savgol" (exact, lower case); nullopt otherwise. O(1).
[[nodiscard]] std::optional<SmoothMethod> parseSmoothMethod(std::string_view name);
[[nodiscard]] std::string_view smoothMethodName(SmoothMethod method);
/// Every value's name, "a|b|c" (for usage texts and errors). O(#values).
[[nodiscard]] std::string smoothMethodNames();

/// Which smoother and its parameters. Only the fields of the chosen method are used (and checked).
/// The default is Woltring's cubic smoothing spline with λ chosen by GCV per run: it adapts to the
/// noise and the frame rate. On the bundled takes (0.5 and 1 mm added noise, `mocap eval-smooth`)
/// it had the lowest position or acceleration error in 9 of 12 take × noise × measure cases and
/// was within 6 % of the best (the quintic) in the other 3, while the fixed-parameter methods
/// (B-spline, 6 Hz Butterworth, Savitzky–Golay) were 15–440 % worse. It costs about 27 banded
/// solves per run; the B-spline is the fast alternative.
struct SmoothOptions
{
  SmoothMethod method = SmoothMethod::Gcvspl;
  /// bspline: degree of the spline, the paper's n in eqs 11–12 (3 = cubic = the paper's "third
  /// order"; the order-as-degree+1 convention would call it 4). 2..7.
  int degree = 3;
  double knotSpacing = 4.0;   ///< bspline: frames between interior knots, ≥ 1
  double cutoffHz = 6.0;      ///< butterworth (−3 dB of the zero-lag pair), and gcvspl in Cutoff mode
  bool winterCutoff = false;  ///< butterworth: choose the cutoff per trajectory by Winter's residual analysis
  SmoothingSplineMode gcvsplMode = SmoothingSplineMode::Gcv;
  int gcvsplDegree = 3;        ///< gcvspl: 3 (cubic) or 5 (quintic)
  double errorVariance = 0.0;  ///< gcvspl ErrorVariance mode: noise variance per coordinate, take units²
  int savgolWindow = 9;        ///< savgol: odd window, 3..1001 frames
  int savgolDegree = 3;        ///< savgol: polynomial degree, 0..min(window − 1, 10)
};

/// Field-by-field equality (every field, used or not). O(1).
[[nodiscard]] bool operator==(const SmoothOptions& a, const SmoothOptions& b);
[[nodiscard]] inline bool operator!=(const SmoothOptions& a, const SmoothOptions& b)
{
  return !(a == b);
}

/// Throws InvalidArgument when a parameter of the chosen method is out of range for `frameRate`
/// (which must be finite and positive), naming the parameter and its range. O(1).
void checkSmoothOptions(const SmoothOptions& options, double frameRate);

/// The chosen method's parameters as text, e.g. "degree=3 knot_spacing=4". O(1).
[[nodiscard]] std::string describeSmoothOptions(const SmoothOptions& options);

/// Shortest valid run the chosen method changes; shorter runs are left unchanged: bspline
/// degree + 2, butterworth 4, gcvspl 4 (cubic) / 6 (quintic), savgol the window. O(1).
[[nodiscard]] Eigen::Index minSmoothRunLength(const SmoothOptions& options);

/// Smoothed copy of one trajectory (#frames × 3). Rows where `valid` is false come back
/// unchanged, and so do valid rows holding a non-finite coordinate (treated as a gap, never fed to
/// a filter) and runs shorter than minSmoothRunLength. `frameRate` in Hz. Throws InvalidArgument
/// when the sizes disagree or checkSmoothOptions fails. Cost per run of N frames: bspline
/// O(N · degree²), butterworth O(N) (Winter: O(40 · N) per trajectory), gcvspl O(N) per λ tried
/// (27 in the GCV and variance modes), savgol O(N · window). Paper: bspline is eqs 11–12 fitted
/// by least squares; the other methods are not in the paper.
[[nodiscard]] Eigen::Matrix<double, Eigen::Dynamic, 3>
smoothTrajectory(const Eigen::Ref<const Eigen::Matrix<double, Eigen::Dynamic, 3>>& xyz,
                 const Eigen::Ref<const ValidMask>& valid, double frameRate, const SmoothOptions& options);

/// One patch per marker (index = marker, possibly empty: always for a model output, which is
/// left alone, marker_points.h) holding the samples whose position changed, each gaining
/// SampleOperation::Smoothed on top of its origin (a filled sample stays filled); validity and
/// residuals are kept (a smoothed sample is still a measured one). Applying the patches smooths the
/// take; applying their undo restores it.
/// B-spline factorisations are shared between runs of equal length. Throws InvalidArgument as
/// checkSmoothOptions with the take's frame rate. O(#markers · cost of smoothTrajectory).
[[nodiscard]] std::vector<SamplePatch> smoothTake(const Take& take, const SmoothOptions& options,
                                                const JobControl& job = {});

/// Smooths `take` in place exactly as applying smoothTake's patches would (the same positions and
/// states), without building them: for pipelines that never undo. Returns the number of samples
/// changed. Throws as smoothTake before changing anything; JobCancelled leaves the markers smoothed
/// before it smoothed. Same cost as smoothTake, without its
/// O(#samples) patch memory.
Eigen::Index smoothTakeInPlace(Take& take, const SmoothOptions& options, const JobControl& job = {});

} // namespace mocap

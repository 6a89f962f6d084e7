#pragma once

#include <Eigen/Core>

#include <optional>
#include <string_view>

namespace mocap {

/// How the smoothing spline chooses its smoothing (Woltring's GCVSPL modes).
enum class SmoothingSplineMode
{
  Gcv,            ///< minimise the generalised cross-validation score (no knowledge needed)
  ErrorVariance,  ///< minimise the predicted mean squared error for a known noise variance
  Cutoff,         ///< fixed: the equivalent zero-lag filter is −3 dB at cutoffHz
};

/// "gcv", "variance", "cutoff" (exact); nullopt otherwise. O(1).
[[nodiscard]] std::optional<SmoothingSplineMode> parseSmoothingSplineMode(std::string_view name);
[[nodiscard]] std::string_view smoothingSplineModeName(SmoothingSplineMode mode);

struct SmoothingSplineOptions
{
  int degree = 3;  ///< 3: cubic (penalises the 2nd derivative, m = 2); 5: quintic (3rd, m = 3)
  SmoothingSplineMode mode = SmoothingSplineMode::Gcv;
  double errorVariance = 0.0;  ///< ErrorVariance mode: noise variance per coordinate, data units²
  double cutoffHz = 6.0;       ///< Cutoff mode
};

/// The fit and the smoothing it used.
struct SmoothingSplineFit
{
  Eigen::MatrixXd smoothed;
  /// Penalty weight λ with time measured in frames (λ_seconds = λ / frameRate^{2m−1}); 0 when
  /// the run was too short and came back unchanged.
  double lambda = 0.0;
  double equivalentCutoffHz = 0.0;  ///< −3 dB frequency of the spline's equivalent zero-lag filter
  double degreesOfFreedom = 0.0;    ///< tr(A), the trace of the influence matrix
  double criterion = 0.0;           ///< GCV score or predicted MSE at λ (Cutoff mode: the GCV score)
};

/// Throws InvalidArgument unless the degree is 3 or 5, the variance finite and ≥ 0 and the
/// cutoff finite and positive (checked against the frame rate by the fit itself). O(1).
void checkSmoothingSplineOptions(const SmoothingSplineOptions& options);

/// Shortest run the spline changes: 2m samples (4 cubic, 6 quintic); shorter ones come back
/// unchanged, because the natural spline of order 2m then has too few degrees of freedom to judge.
/// O(1).
[[nodiscard]] Eigen::Index minSmoothingSplineRunLength(int degree);

/// λ (frame units) whose equivalent zero-lag filter has gain 1/√2 at `cutoffHz`. On an infinite
/// uniform grid the smoothing spline is the filter H(ω) = 1 / (1 + λ (2 sin ω/2)^{2m} / P̂(ω)),
/// P̂ the symbol of the order-2m B-spline Gram matrix (below); this solves H(ωc) = 1/√2.
/// (Woltring's GCVSPL uses the −6 dB point instead.) Throws InvalidArgument unless
/// 0 < cutoffHz < frameRate / 2. O(1).
[[nodiscard]] double smoothingSplineLambda(int degree, double frameRate, double cutoffHz);
/// The inverse: −3 dB frequency of the equivalent filter for a given λ (≤ 0: the Nyquist
/// frequency). O(1) (100 bisection steps).
[[nodiscard]] double smoothingSplineCutoffHz(int degree, double frameRate, double lambda);

/// Not in the paper: Woltring's generalised cross-validated smoothing spline (GCVSPL, 1986) on equally spaced
/// samples (#samples × any columns, one λ shared by the columns). Minimises
///   Σ_i |y_i − g_i|² + λ Σ gᵀ Q R⁻¹ Qᵀ g,
/// the exact natural-spline penalty ∫ (s^{(m)})² of the spline of degree 2m − 1 through g (Reinsch
/// form, Green & Silverman 1994 §2.3): Qᵀ is the m-th difference operator and R the Gram matrix of
/// the order-m B-splines on the sample grid (Toeplitz, half-bandwidth m − 1). The fit is
///   (R + λ QᵀQ) γ = Qᵀ y,   g = y − λ Q γ,
/// one banded LDLᵀ of half-bandwidth m, O(N · m²). The influence matrix A has
/// tr(I − A) = λ tr((R + λ QᵀQ)⁻¹ QᵀQ), from the band of the inverse (Hutchinson & de Hoog 1985),
/// also O(N · m²). GCV(λ) = (RSS / N) / (tr(I − A) / N)² (Craven & Wahba 1979); the known-variance
/// mode minimises RSS / N − 2σ² tr(I − A) / N + σ² (Mallows). Both search log λ over equivalent
/// cutoffs of 0.5 %–45 % of the frame rate: a 13-point scan then golden section, 27
/// evaluations, so O(27 · N · m²) per run in total.
///
/// Runs shorter than minSmoothingSplineRunLength come back unchanged (lambda = 0). Throws
/// InvalidArgument for bad options, a frame rate that is not finite and positive, or a
/// non-finite sample.
[[nodiscard]] SmoothingSplineFit smoothingSpline(const Eigen::Ref<const Eigen::MatrixXd>& samples,
                                                 double frameRate,
                                                 const SmoothingSplineOptions& options = {});

} // namespace mocap

#pragma once

#include <Eigen/Core>

namespace mocap {

/// Coefficients of a second-order low-pass Butterworth section (bilinear transform):
/// y[i] = b0 x[i] + b1 x[i−1] + b2 x[i−2] − a1 y[i−1] − a2 y[i−2].
struct Biquad
{
  double b0 = 1.0, b1 = 0.0, b2 = 0.0, a1 = 0.0, a2 = 0.0;
};

/// Winter's correction for running a second-order section forwards and backwards:
/// C = (2^{1/2} − 1)^{1/4} ≈ 0.802, so the two passes together are −3 dB at the requested cutoff.
/// O(1). Not in the paper (nor is any of this file): Winter's standard alternative to eqs 11–12.
[[nodiscard]] double butterworthPassCorrection();

/// The section whose forward–backward (zero-lag, "4th-order") combination has gain 1/√2 at
/// `cutoffHz`: Ω = tan(π fc / fs) / C, prewarped bilinear design (Winter, Biomechanics and Motor
/// Control of Human Movement, §3.4). Throws InvalidArgument unless frameRate is finite and
/// positive and 0 < cutoffHz < frameRate / 2. O(1).
[[nodiscard]] Biquad butterworthLowPass(double frameRate, double cutoffHz);

/// Amplitude gain of the zero-lag filter at `frequencyHz`: |H(e^{iω})|² of the section, i.e.
/// 1 / (1 + (tan(π f / fs) / Ω)⁴). O(1). Not in the paper.
[[nodiscard]] double butterworthGain(double frequencyHz, double frameRate, double cutoffHz);

/// Frames added at each end before filtering: enough for the impulse response to die out
/// (about 3 fs / fc, capped by the run length − 1). O(1).
[[nodiscard]] Eigen::Index butterworthPadLength(Eigen::Index sampleCount, double frameRate, double cutoffHz);

/// Zero-lag low-pass of every column of `samples` (#samples × any columns, all valid): one
/// forward and one backward pass of butterworthLowPass. Each end is extended by
/// butterworthPadLength frames reflected through the end sample (odd reflection, which keeps
/// value and slope); when that pad is at least 15 frames long, the reflection's even part is
/// corrected by the curvature of a cubic fitted to the end's pad + 1 samples, so quadratic and
/// cubic trends continue too (shorter runs are too noisy to extrapolate a curvature from). The
/// filter starts in its steady state at the first padded value. So ends neither ring nor bend:
/// constants, lines and slow sines pass unchanged. Runs of fewer than 4 samples come back unchanged. Throws
/// InvalidArgument for bad rates or a non-finite sample. O(#samples + pad) per column. Not in the
/// paper (Winter's zero-lag Butterworth).
[[nodiscard]] Eigen::MatrixXd butterworthFilter(const Eigen::Ref<const Eigen::MatrixXd>& samples,
                                                double frameRate, double cutoffHz);

/// Shortest run butterworthFilter changes.
inline constexpr Eigen::Index kMinButterworthRunLength = 4;

} // namespace mocap

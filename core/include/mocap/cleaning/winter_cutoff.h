#pragma once

#include "mocap/model/take.h"

#include <vector>

namespace mocap {

/// Result of Winter's residual analysis: the residual curve and the cutoff read from it.
struct WinterCutoff
{
  double cutoffHz = 0.0;
  double noiseRms = 0.0;              ///< intercept of the line fitted to the high-frequency tail
  std::vector<double> frequenciesHz;  ///< the cutoffs tried
  std::vector<double> residualRms;    ///< RMS of raw − filtered at each cutoff
};

/// Winter's residual analysis (Biomechanics and Motor Control of Human Movement, §3.4.4.3):
/// filters the valid runs of `xyz` (#frames × 3) with butterworthFilter at 40 cutoffs from
/// 1 % to 40 % of the frame rate, fits a straight line to the residual RMS over the upper half
/// of that range (where only noise is left), and returns the lowest cutoff whose residual has
/// dropped to the line's intercept at 0 Hz (the noise RMS), interpolating between grid points.
/// Residuals are pooled over the three axes and all runs of at least 4 frames; with no such run
/// the result is the top of the grid. Throws InvalidArgument for sizes that disagree or a frame
/// rate that is not finite and positive. O(40 · #frames). Not in the paper.
[[nodiscard]] WinterCutoff winterCutoff(const Eigen::Ref<const Eigen::Matrix<double, Eigen::Dynamic, 3>>& xyz,
                                        const Eigen::Ref<const ValidMask>& valid, double frameRate);

} // namespace mocap

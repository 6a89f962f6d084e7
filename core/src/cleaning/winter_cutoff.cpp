#include "mocap/cleaning/winter_cutoff.h"

#include "mocap/cleaning/butterworth_filter.h"
#include "mocap/base/error.h"
#include "mocap/model/valid_runs.h"

#include <cmath>
#include <string>

namespace mocap {

namespace {
constexpr int kGridSize = 40;
constexpr double kGridStep = 0.01;  // fraction of the frame rate
} // namespace

WinterCutoff winterCutoff(const Eigen::Ref<const Eigen::Matrix<double, Eigen::Dynamic, 3>>& xyz,
                          const Eigen::Ref<const ValidMask>& valid, double frameRate)
{
  if (xyz.rows() != valid.size())
    throw InvalidArgument("Winter residual analysis: " + std::to_string(xyz.rows()) + " positions but " +
                          std::to_string(valid.size()) + " validity flags");
  if (!std::isfinite(frameRate) || frameRate <= 0.0)
    throw InvalidArgument("Winter residual analysis: frame rate must be finite and positive");
  WinterCutoff result;
  std::vector<ValidRun> runs;
  Eigen::Index sampleCount = 0;
  for (const ValidRun& run : findValidRuns(valid))
    if (run.length >= kMinButterworthRunLength && xyz.middleRows(run.first, run.length).allFinite()) {
      runs.push_back(run);
      sampleCount += run.length;
    }
  for (int g = 1; g <= kGridSize; ++g) {
    const double cutoff = kGridStep * static_cast<double>(g) * frameRate;
    double sum = 0.0;
    for (const ValidRun& run : runs) {
      const auto raw = xyz.middleRows(run.first, run.length);
      sum += (butterworthFilter(raw, frameRate, cutoff) - raw).squaredNorm();
    }
    result.frequenciesHz.push_back(cutoff);
    result.residualRms.push_back(sampleCount > 0 ? std::sqrt(sum / static_cast<double>(3 * sampleCount))
                                                 : 0.0);
  }
  if (runs.empty()) {
    result.cutoffHz = result.frequenciesHz.back();
    return result;
  }
  // Least-squares line through the upper half of the residual curve; its intercept is the noise RMS.
  double sf = 0.0, sr = 0.0, sff = 0.0, sfr = 0.0, count = 0.0;
  for (std::size_t g = kGridSize / 2; g < result.frequenciesHz.size(); ++g) {
    const double f = result.frequenciesHz[g], r = result.residualRms[g];
    sf += f;
    sr += r;
    sff += f * f;
    sfr += f * r;
    count += 1.0;
  }
  const double slope = (count * sfr - sf * sr) / (count * sff - sf * sf);
  result.noiseRms = std::max(0.0, (sr - slope * sf) / count);
  result.cutoffHz = result.frequenciesHz.back();
  for (std::size_t g = 0; g < result.frequenciesHz.size(); ++g) {
    if (result.residualRms[g] > result.noiseRms)
      continue;
    if (g == 0) {
      result.cutoffHz = result.frequenciesHz[0];
    } else {
      const double r0 = result.residualRms[g - 1], r1 = result.residualRms[g];
      const double f0 = result.frequenciesHz[g - 1], f1 = result.frequenciesHz[g];
      result.cutoffHz = f0 + (f1 - f0) * (r0 - result.noiseRms) / (r0 - r1);
    }
    break;
  }
  return result;
}

} // namespace mocap

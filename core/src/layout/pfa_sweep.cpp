// Principal Feature Analysis over a sweep of k (sweepPfa, marker_selection.h).

#include "mocap/layout/marker_selection.h"

#include "mocap/base/error.h"
#include "mocap/base/parallel_for.h"
#include "mocap/base/random.h"
#include "mocap/math/pca.h"

#include "selection_units.h"

#include <atomic>
#include <string>

namespace mocap {

using layout_internal::checkSymmetry;
using layout_internal::checkTraining;
using layout_internal::markersOfUnits;

PfaSweep sweepPfa(const Eigen::Ref<const Eigen::MatrixXd>& training, const MarkerSymmetry& symmetry,
                  const PfaOptions& options, const JobControl& control)
{
  checkTraining(training);
  const Eigen::Index features = training.cols();
  const Eigen::Index markers = features / 3;
  checkSymmetry(symmetry, markers);
  if (training.rows() < features + 1)
    throw InvalidArgument("PFA: " + std::to_string(training.rows()) + " frames for " +
                          std::to_string(features) + " features; need at least " +
                          std::to_string(features + 1));
  if (options.restarts < 1)
    throw InvalidArgument("PFA: restarts must be at least 1, not " + std::to_string(options.restarts));
  const bool automatic = options.minK == 0 && options.maxK == 0;
  const Eigen::Index lowK = options.minK == 0 ? 1 : options.minK;
  const Eigen::Index highK = automatic ? markers : (options.maxK == 0 ? features : options.maxK);
  if (lowK < 1 || highK > features || lowK > highK)
    throw InvalidArgument("PFA: k must satisfy 1 ≤ min ≤ max ≤ " + std::to_string(features) +
                          " (the number of features, 3 per marker), got " + std::to_string(lowK) + ":" +
                          std::to_string(highK));

  const PrincipalComponents pca = computePca(training, options.varianceFraction);
  // Lu et al. 2007 cluster |Vᵢ|: an eigenvector's sign is arbitrary, and a coordinate moving
  // against another (a left mouth corner against the right one) is as redundant as one moving with it.
  const KMeansPoints points(pca.components.cwiseAbs());
  PfaSweep sweep;
  sweep.components = pca.count();
  sweep.explainedVariance = pca.explainedFraction();

  const auto& units = symmetry.units();
  const std::size_t unitCount = units.size();
  const auto restarts = static_cast<std::size_t>(options.restarts);
  // Work of a restart grows with k; progress counts k per restart.
  double totalWork = 0.0;
  for (Eigen::Index k = lowK; k <= highK; ++k)
    totalWork += static_cast<double>(k) * static_cast<double>(restarts);
  double doneBefore = 0.0;
  std::atomic<std::size_t> doneRestarts{0};

  std::vector<std::uint8_t> chosen;  // restarts × units, 1 when the restart selected the unit
  for (Eigen::Index k = lowK; k <= highK; ++k) {
    chosen.assign(restarts * unitCount, 0);
    doneRestarts = 0;
    const auto body = [&](std::size_t r) {
      const KMeansResult clusters =
          kMeans(points, k, mixSeed(options.seed, static_cast<std::uint64_t>(k), r), options.kMeans);
      std::uint8_t* row = chosen.data() + r * unitCount;
      for (const Eigen::Index feature : clusters.representatives)
        if (feature >= 0)
          row[static_cast<std::size_t>(symmetry.unitOf(feature / 3))] = 1;
      doneRestarts.fetch_add(1, std::memory_order_relaxed);
    };
    const auto tick = [&] {
      control.report((doneBefore + static_cast<double>(k) * static_cast<double>(doneRestarts.load())) /
                      totalWork);
    };
    if (!parallelFor(restarts, control.threads(), body, control.cancelFlag(), tick)) {
      sweep.cancelled = true;
      break;
    }
    doneBefore += static_cast<double>(k) * static_cast<double>(restarts);

    PfaSelection selection;
    selection.k = k;
    selection.unitFrequency.assign(unitCount, 0.0);
    for (std::size_t r = 0; r < restarts; ++r)
      for (std::size_t u = 0; u < unitCount; ++u)
        selection.unitFrequency[u] += chosen[r * unitCount + u];
    for (double& f : selection.unitFrequency)
      f /= static_cast<double>(restarts);
    // The most stable restart: highest Σ frequency of its units; the first one on ties.
    std::size_t best = 0;
    double bestScore = -1.0;
    for (std::size_t r = 0; r < restarts; ++r) {
      double score = 0.0;
      for (std::size_t u = 0; u < unitCount; ++u)
        if (chosen[r * unitCount + u])
          score += selection.unitFrequency[u];
      if (score > bestScore) {
        bestScore = score;
        best = r;
      }
    }
    std::vector<bool> selected(unitCount);
    for (std::size_t u = 0; u < unitCount; ++u)
      selected[u] = chosen[best * unitCount + u] != 0;
    selection.markers = markersOfUnits(symmetry, selected);
    selection.stability = bestScore;
    const bool complete = static_cast<Eigen::Index>(selection.markers.size()) == markers;
    sweep.selections.push_back(std::move(selection));
    if (automatic && complete)
      break;
  }
  if (!sweep.cancelled)
    control.reportNow(1.0);
  return sweep;
}

} // namespace mocap

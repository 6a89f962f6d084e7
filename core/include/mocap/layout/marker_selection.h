#pragma once

#include "mocap/base/job_control.h"
#include "mocap/layout/blendshape_basis.h"
#include "mocap/math/kmeans.h"
#include "mocap/layout/layout_frames.h"
#include "mocap/model/marker_pairs.h"
#include "mocap/layout/subset_error.h"

#include <Eigen/Core>

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mocap {

/// How a marker layout of a given size is chosen.
enum class SelectionMethod
{
  Pfa,     ///< Principal Feature Analysis with the most stable of many k-means restarts (the paper)
  Greedy,  ///< greedy forward selection + exchange on the reconstruction (and blend-weight) error
};

/// "pfa" or "greedy". O(1).
[[nodiscard]] std::string_view selectionMethodName(SelectionMethod method);
/// Every value's name, "a|b|c" (for usage texts and errors). O(#values).
[[nodiscard]] std::string selectionMethodNames();
/// The method named "pfa" or "greedy"; nullopt otherwise. O(1).
[[nodiscard]] std::optional<SelectionMethod> parseSelectionMethod(std::string_view name);

struct PfaOptions
{
  double varianceFraction = 0.98;  ///< PCA components kept (Wellein et al. 2007 §2: 98 %)
  int restarts = 1000;             ///< k-means initialisations per k (§2: 1000)
  /// Cluster counts to sweep; both 0: all useful values, k = 1 … #markers, stopping after the first
  /// k whose stable selection holds every marker.
  Eigen::Index minK = 0;
  Eigen::Index maxK = 0;
  std::uint64_t seed = 1;  ///< restart r of k uses seed mixSeed(seed, k, r): the same on any thread count
  KMeansOptions kMeans;
};

/// The PFA result for one k.
struct PfaSelection
{
  Eigen::Index k = 0;
  std::vector<Eigen::Index> markers;  ///< the most stable selection, symmetric, sorted
  /// Per unit of the symmetry (MarkerSymmetry::units()), the fraction of restarts selecting it.
  std::vector<double> unitFrequency;
  double stability = 0.0;  ///< Σ unitFrequency over the selection's units (§2's criterion)
};

struct PfaSweep
{
  std::vector<PfaSelection> selections;  ///< one per completed k, ascending
  Eigen::Index components = 0;           ///< PCA components kept
  double explainedVariance = 0.0;        ///< their share of the variance
  bool cancelled = false;
};

/// Principal Feature Analysis over a sweep of k (Cohen et al. 2002 / Lu et al. 2007 as adapted by
/// Wellein et al. 2007 §2): PCA of the 3·#markers coordinates keeping `varianceFraction`; each
/// coordinate is a row Vᵢ of the eigenvector matrix, clustered as |Vᵢ| (Lu et al.'s step 4: the
/// sign of an eigenvector is arbitrary, and coordinates moving against each other are as redundant
/// as coordinates moving together); per k, `restarts` k-means runs (k-means++ seeding) each select
/// the coordinate nearest every cluster mean; coordinates → markers, closed under `symmetry`; over the
/// restarts each unit's selection frequency is counted, and the selection with the highest sum of
/// unit frequencies is kept. Restarts run on JobControl::threads() threads sharing one distance
/// matrix; results do not depend on the thread count. Progress is reported on the calling thread,
/// and at the end; a cancel stops between restarts and returns the k completed, cancelled = true.
/// O(n·d² + d³ + Σ_k restarts · d·k·(1 + q·iterations)) for n training frames, d = 3·#markers,
/// q kept components.
/// Throws InvalidArgument for fewer than two markers, a symmetry of another size, fewer frames than
/// d + 1, a non-finite value, restarts < 1, or k outside 1 … d (or minK > maxK).
[[nodiscard]] PfaSweep sweepPfa(const Eigen::Ref<const Eigen::MatrixXd>& training,
                                const MarkerSymmetry& symmetry, const PfaOptions& options = {},
                                const JobControl& control = {});

/// Greedy selection of exactly `size` markers in whole units of `symmetry`, minimising
/// errors.trainingObjective() (held-out reconstruction error plus a share of the blendshape-weight
/// error, training frames only): forward steps add the unit that lowers it most (keeping the size
/// reachable), then exchange passes swap a selected unit for an unselected one of the same width
/// while that lowers it. Beyond the paper: PFA keeps mutually uncorrelated coordinates; this keeps
/// the markers that best predict the others and the blend weights. Ties go to the lower unit.
/// nullopt when no symmetric set of that size exists.
/// O((size + passes · size) · #units · cost of trainingObjective), with at most 2 exchange passes.
/// Throws InvalidArgument for a symmetry of another size or a size outside 1 … #markers.
[[nodiscard]] std::optional<std::vector<Eigen::Index>>
selectGreedy(const SubsetErrors& errors, const MarkerSymmetry& symmetry, Eigen::Index size);

/// selectGreedy for each of `sizes` (entry i for sizes[i]), in parallel on JobControl::threads(),
/// sharing the objective values of the forward steps the sizes have in common; then, in ascending
/// size, a set is replaced by the set one smaller plus a single unit (or two smaller plus a pair)
/// when that scores better, so no size is worse on the objective than a smaller one allows.
/// `starts` (by size; e.g. the PFA sets) are improved by the same exchange passes and replace the
/// greedy set of their size when they end better, so the result never scores worse on the
/// objective than a start. Returns an empty vector when cancelled. Throws as selectGreedy.
[[nodiscard]] std::vector<std::optional<std::vector<Eigen::Index>>>
selectGreedy(const SubsetErrors& errors, const MarkerSymmetry& symmetry,
             const std::vector<Eigen::Index>& sizes, const JobControl& control = {},
             const std::map<Eigen::Index, std::vector<Eigen::Index>>& starts = {});

/// A uniformly shuffled symmetric set of exactly `size` markers (units added in random order
/// while they fit), the baseline both methods must beat; nullopt when none exists. O(#markers).
[[nodiscard]] std::optional<std::vector<Eigen::Index>> selectRandom(const MarkerSymmetry& symmetry,
                                                                    Eigen::Index size, std::uint64_t seed);

/// The knee of an error curve ("low error, few markers"): both error curves are scaled by their
/// largest value and averaged, sizes scaled to [0, 1], and the knee is the point farthest below the
/// straight line from the first point to the last (Satopää et al. 2011, "Kneedle"). The paper picks
/// its set by eye from the same curve (Fig. 2). Returns an index into `sizes`. O(#sizes).
/// Throws InvalidArgument for no points, sizes of different lengths or a non-finite error.
[[nodiscard]] std::size_t chooseKnee(const std::vector<Eigen::Index>& sizes,
                                     const std::vector<double>& errorA, const std::vector<double>& errorB);

} // namespace mocap

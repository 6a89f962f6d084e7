#pragma once
// Which samples a single cleaning step from Python may change (mocap.detect_spikes, fill_gaps and
// smooth with markers= and frames=), as a selection limits a step in the studio's cleaning panel:
// the step is worked out on the whole take and only its changes inside the selection are applied.

#include "mocap/model/gaps.h"
#include "mocap/model/processing_step.h"
#include "mocap/model/sample_patch.h"
#include "mocap/model/take.h"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace mocap::python {

struct StepSelection
{
  std::vector<std::string> labels;   ///< the markers named; empty: every marker
  std::vector<Eigen::Index> markers; ///< their indices, ascending
  bool ranged = false;
  Eigen::Index first = 0;            ///< 0-based frames [first, last] when ranged
  Eigen::Index last = -1;

  /// The selection `markers` (labels) and `frames` ((first, last) as the take numbers them, both
  /// included) name, or nullopt when neither is given (the whole take). Throws InvalidArgument for
  /// a label the take lacks or a range that is empty or outside the take. O(#labels · #markers).
  [[nodiscard]] static std::optional<StepSelection> of(const Take& take,
                                                       const std::optional<std::vector<std::string>>& markers,
                                                       const std::optional<std::pair<long long, long long>>& frames);

  [[nodiscard]] bool holdsMarker(Eigen::Index marker) const;
  [[nodiscard]] bool holds(Eigen::Index marker, Eigen::Index frame) const;
  /// Whether the gap is one of the selected markers' and overlaps the range.
  [[nodiscard]] bool overlaps(const Gap& gap) const;
  /// The patches' samples inside the selection; empty patches dropped. O(total patch size).
  [[nodiscard]] std::vector<SamplePatch> within(std::vector<SamplePatch> patches) const;
  /// Narrows a history step recorded for the whole take to the markers and frames selected.
  void narrow(ProcessingStep& step, const Take& take) const;
};

/// The number of samples the patches hold. O(#patches).
[[nodiscard]] Eigen::Index sampleCount(const std::vector<SamplePatch>& patches);

} // namespace mocap::python

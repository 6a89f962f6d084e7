#pragma once

#include "document/layout_highlight.h"
#include "mocap/evaluation/layout_rig_error.h"
#include "mocap/layout/layout_planning.h"

#include <QObject>
#include <QString>

#include <Eigen/Core>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace mocap::ui {

class TakeDocument;

/// A finished (or failed) planning run: the core result (planned frames, pairs, plan, the head
/// reference markers it was planned with) and what is shown beside it.
struct LayoutPlanResult : LayoutResult
{
  QString pairSource;  ///< where the pairs came from, in words
  QString error;       ///< non-empty when the run failed
  std::optional<PlanRigErrors> rig;  ///< the layouts judged on the blendshape rig, when asked
  QString rigError;                  ///< why they could not be (the plan itself stands)
};

/// The session's marker layout plan: the last successful planning result and the marker count
/// picked on its error plot. The Layout planning dock runs plans and picks sizes; the 3D view
/// highlights the picked layout on the open take (mapped by label, so it fits the open take even
/// when that was not the first planned).
class LayoutPlanModel final : public QObject
{
  Q_OBJECT

public:
  explicit LayoutPlanModel(TakeDocument& document, QObject* parent = nullptr);

  /// The last successful plan, or nullptr.
  [[nodiscard]] const LayoutPlanResult* result() const { return m_result.get(); }
  /// The same, shared (a plan is never changed once kept: a saved session state shares it).
  [[nodiscard]] const std::shared_ptr<const LayoutPlanResult>& sharedResult() const { return m_result; }
  /// Keeps `result` (a successful plan) with `size` markers picked.
  void setResult(std::shared_ptr<const LayoutPlanResult> result, Eigen::Index size);
  [[nodiscard]] Eigen::Index selectedSize() const { return m_size; }
  void setSelectedSize(Eigen::Index size);

  /// The layout of the picked size (the plan's method), or nullptr. O(#sizes).
  [[nodiscard]] const ScoredLayout* selectedLayout() const;
  /// The planned markers of the picked size, in plan order; empty if none. O(#markers).
  [[nodiscard]] std::vector<std::string> selectedLabels() const;
  /// What a capture with the picked layout records: its markers and the head reference markers.
  [[nodiscard]] std::vector<std::string> captureLabels() const;
  /// The picked layout on the open take; empty without one. O(#markers · log #markers).
  [[nodiscard]] LayoutHighlight highlight() const;

signals:
  /// Another plan or size: the table, the exports and the highlight follow.
  void changed();
  /// The open take's markers changed (removed, inserted, renamed): the highlight maps again.
  void highlightChanged();

private:
  TakeDocument& m_document;
  std::shared_ptr<const LayoutPlanResult> m_result;
  Eigen::Index m_size = 0;
};

} // namespace mocap::ui

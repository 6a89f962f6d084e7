#include "document/layout_plan_model.h"

#include "document/take_document.h"

namespace mocap::ui {

LayoutPlanModel::LayoutPlanModel(TakeDocument& document, QObject* parent) : QObject(parent), m_document(document)
{
  connect(&document, &TakeDocument::markersChanged, this, &LayoutPlanModel::highlightChanged);
  connect(&document, &TakeDocument::markerRenamed, this, &LayoutPlanModel::highlightChanged);
}

void LayoutPlanModel::setResult(std::shared_ptr<const LayoutPlanResult> result, Eigen::Index size)
{
  m_result = std::move(result);
  m_size = size;
  emit changed();
}

void LayoutPlanModel::setSelectedSize(Eigen::Index size)
{
  m_size = size;
  emit changed();
}

const ScoredLayout* LayoutPlanModel::selectedLayout() const
{
  return m_result ? m_result->layout(m_size) : nullptr;
}

std::vector<std::string> LayoutPlanModel::selectedLabels() const
{
  const ScoredLayout* layout = selectedLayout();
  return layout ? m_result->labelsOf(layout->markers) : std::vector<std::string>{};
}

std::vector<std::string> LayoutPlanModel::captureLabels() const
{
  const ScoredLayout* layout = selectedLayout();
  return layout ? m_result->captureLabels(layout) : std::vector<std::string>{};
}

LayoutHighlight LayoutPlanModel::highlight() const
{
  const std::vector<std::string> labels = selectedLabels();
  if (labels.empty())
    return {};
  const Take& take = m_document.take();
  const auto flags = [&take](const std::vector<std::string>& marked) {
    std::vector<bool> result(static_cast<std::size_t>(take.markerCount()), false);
    for (const std::string& label : marked)
      if (const auto m = take.markerIndex(label))
        result[static_cast<std::size_t>(*m)] = true;
    return result;
  };
  return {flags(labels), flags(m_result->stabilizeLabels)};
}

} // namespace mocap::ui

#include "document/view_state.h"

#include "document/studio_options.h"

#include <algorithm>
#include <utility>

namespace mocap::ui {

ViewState::ViewState(QObject* parent) : QObject(parent) {}

void ViewState::setUpAxis(int axis)
{
  axis = axis == 1 ? 1 : 2;
  if (axis == m_upAxis)
    return;
  m_upAxis = axis;
  emit upAxisChanged(axis);
}

void ViewState::setTrailFrames(int frames)
{
  frames = std::max(frames, 0);
  if (frames == m_trailFrames)
    return;
  m_trailFrames = frames;
  emit trailFramesChanged(frames);
}

void ViewState::setMarkerScale(double fraction)
{
  if (fraction == m_markerScale)
    return;
  m_markerScale = fraction;
  emit markerScaleChanged(fraction);
}

void ViewState::setLinksVisible(bool visible)
{
  if (visible == m_linksVisible)
    return;
  m_linksVisible = visible;
  emit linksVisibleChanged(visible);
}

void ViewState::setHeadReference(std::vector<Eigen::Index> markers)
{
  m_headReference = std::move(markers);
  emit headReferenceChanged();
}

void ViewState::setFollowHead(bool on)
{
  if (on == m_followHead)
    return;
  m_followHead = on;
  emit followHeadChanged(on);
}

void ViewState::setDisplayUnit(LengthUnit unit)
{
  if (unit == m_displayUnit)
    return;
  m_displayUnit = unit;
  emit displayUnitChanged(unit);
}

void ViewState::setColors(const ColorScheme& colors)
{
  setColorScheme(colors);  // also when unchanged here: another session may have set another
  if (colors == m_colors)
    return;
  m_colors = colors;
  emit colorsChanged();
}

void ViewState::setLayoutHighlight(std::vector<bool> kept, std::vector<bool> reference)
{
  // Announced even when equal: a view drops its copy when the take's markers change, and the
  // same flags mapped onto the new take must reach it again.
  m_layoutKept = std::move(kept);
  m_layoutReference = std::move(reference);
  emit layoutHighlightChanged();
}

void ViewState::setMeshOpacity(double opacity)
{
  if (opacity == m_meshOpacity)
    return;
  m_meshOpacity = opacity;
  emit meshLookChanged();
}

void ViewState::setMeshEdges(bool visible)
{
  if (visible == m_meshEdges)
    return;
  m_meshEdges = visible;
  emit meshLookChanged();
}

void ViewState::setRigShown(bool shown)
{
  if (shown == m_rigShown)
    return;
  m_rigShown = shown;
  emit rigShownChanged(shown);
}

void ViewState::setRigBeside(bool beside)
{
  if (beside == m_rigBeside)
    return;
  m_rigBeside = beside;
  emit rigBesideChanged(beside);
}

void ViewState::followOptions(const StudioOptions& options)
{
  options.upAxis.follow(this, [this](int axis) { setUpAxis(axis); });
  options.trailFrames.follow(this, [this](int frames) { setTrailFrames(frames); });
  options.markerSizePercent.follow(this, [this](double percent) { setMarkerScale(percent / 100.0); });
  options.linksVisible.follow(this, [this](bool visible) { setLinksVisible(visible); });
  options.followHead.follow(this, [this](bool on) { setFollowHead(on); });
  options.displayUnit.follow(this, [this, &options](const QString&) { setDisplayUnit(options.lengthUnit()); });
  options.colors.follow(this, [this](const ColorScheme& colors) { setColors(colors); });
}

} // namespace mocap::ui

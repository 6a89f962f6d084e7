#include "document/studio_options.h"

#include <QLatin1String>

#include <algorithm>
#include <cmath>
#include <utility>

namespace mocap::ui {

namespace {
constexpr double kMinMarkerPercent = Preferences::kMinMarkerPercent, kMaxMarkerPercent = Preferences::kMaxMarkerPercent;
constexpr int kMaxTrailFrames = Preferences::kMaxTrailFrames;
constexpr int kMaxAutosaveMinutes = Preferences::kMaxAutosaveMinutes;

// The sub-key of each colour, in the order the dialog lists them.
const std::pair<const char*, QColor ColorScheme::*> kColorKeys[] = {
    {"original", &ColorScheme::original}, {"filled", &ColorScheme::filled},
    {"smoothed", &ColorScheme::smoothed}, {"edited", &ColorScheme::edited},
    {"selection", &ColorScheme::selection}, {"flagged", &ColorScheme::flagged},
    {"background", &ColorScheme::background}};

double clampMarkerSize(const double& percent)
{
  if (std::isnan(percent))  // NaN from a hand-edited file
    return Preferences{}.markerSizePercent;
  return std::clamp(percent, kMinMarkerPercent, kMaxMarkerPercent);
}

int clampTrail(const int& frames)
{
  return std::clamp(frames, 0, kMaxTrailFrames);
}

int clampUpAxis(const int& axis)
{
  return axis == 1 ? 1 : 2;
}

int clampAutosave(const int& minutes)
{
  return std::clamp(minutes, 1, kMaxAutosaveMinutes);
}

QString clampUnit(const QString& unit)
{
  return parseLengthUnit(unit.toStdString()) ? unit : Preferences{}.displayUnit;
}

ColorScheme clampColors(const ColorScheme& colors)
{
  ColorScheme valid = colors;
  for (const auto& [key, member] : kColorKeys)
    if (!(valid.*member).isValid())  // a hand-edited name Qt cannot read
      valid.*member = ColorScheme{}.*member;
  return valid;
}

QString colorKey(const QString& key, const char* name)
{
  return key + QLatin1Char('/') + QLatin1String(name);
}
} // namespace

ColorScheme OptionCodec<ColorScheme>::read(const QSettings& settings, const QString& key, const ColorScheme& fallback)
{
  ColorScheme colors;
  for (const auto& [name, member] : kColorKeys)
    colors.*member = QColor(settings.value(colorKey(key, name), (fallback.*member).name()).toString());
  return colors;
}

void OptionCodec<ColorScheme>::write(QSettings& settings, const QString& key, const ColorScheme& value)
{
  for (const auto& [name, member] : kColorKeys)
    settings.setValue(colorKey(key, name), (value.*member).name());
}

StudioOptions::StudioOptions()
    : markerSizePercent(QStringLiteral("view/markerSizePercent"), Preferences{}.markerSizePercent, clampMarkerSize),
      trailFrames(QStringLiteral("view/trailFrames"), Preferences{}.trailFrames, clampTrail),
      upAxis(QStringLiteral("view/upAxis"), Preferences{}.upAxis, clampUpAxis),
      language(QStringLiteral("language"), QString()),
      autosaveMinutes(QStringLiteral("autosaveMinutes"), Preferences{}.autosaveMinutes, clampAutosave),
      displayUnit(QStringLiteral("view/displayUnit"), Preferences{}.displayUnit, clampUnit),
      colors(QStringLiteral("view/colors"), ColorScheme{}, clampColors),
      linksVisible(QStringLiteral("view/links"), false),
      showModelOutputs(QStringLiteral("view/modelOutputs"), false),
      followHead(QStringLiteral("view/followHead"), false),
      keepRig(QStringLiteral("session/keepRig"), false),
      recentFiles(QStringLiteral("recentFiles"), QStringList()),
      lastFolder(QStringLiteral("lastFolder"), QString()),
      windowGeometry(QStringLiteral("geometry"), QByteArray()),
      windowState(QStringLiteral("windowState"), QByteArray())
{
}

Preferences StudioOptions::preferences() const
{
  Preferences p;
  p.markerSizePercent = markerSizePercent;
  p.trailFrames = trailFrames;
  p.upAxis = upAxis;
  p.language = language;
  p.autosaveMinutes = autosaveMinutes;
  p.displayUnit = displayUnit;
  p.colors = colors;
  return p;
}

void StudioOptions::setPreferences(const Preferences& preferences)
{
  markerSizePercent = preferences.markerSizePercent;
  trailFrames = preferences.trailFrames;
  upAxis = preferences.upAxis;
  if (!preferences.language.isEmpty())
    language = preferences.language;
  autosaveMinutes = preferences.autosaveMinutes;
  displayUnit = preferences.displayUnit;
  colors = preferences.colors;
}

LengthUnit StudioOptions::lengthUnit() const
{
  return parseLengthUnit(displayUnit.get().toStdString()).value_or(LengthUnit::Millimetre);
}

Preferences Preferences::load()
{
  return StudioOptions().preferences();
}

void Preferences::save() const
{
  StudioOptions().setPreferences(*this);
}

Preferences Preferences::clamped() const
{
  Preferences p = *this;
  p.markerSizePercent = clampMarkerSize(p.markerSizePercent);
  p.trailFrames = clampTrail(p.trailFrames);
  p.upAxis = clampUpAxis(p.upAxis);
  p.autosaveMinutes = clampAutosave(p.autosaveMinutes);
  p.displayUnit = clampUnit(p.displayUnit);
  p.colors = clampColors(p.colors);
  return p;
}

} // namespace mocap::ui

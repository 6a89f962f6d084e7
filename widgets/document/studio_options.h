#pragma once

#include "document/color_scheme.h"
#include "document/session_option.h"

#include "mocap/base/length_unit.h"

#include <QByteArray>
#include <QString>
#include <QStringList>

namespace mocap::ui {

/// A colour scheme is kept as one colour name per colour under the option's key
/// ("view/colors/original", …); a name Qt cannot read falls back to the default colour.
template <>
struct OptionCodec<ColorScheme>
{
  [[nodiscard]] static ColorScheme read(const QSettings& settings, const QString& key, const ColorScheme& fallback);
  static void write(QSettings& settings, const QString& key, const ColorScheme& value);
};

/// The user preferences as one value: what the preferences dialog edits.
struct Preferences
{
  static constexpr double kMinMarkerPercent = 0.1, kMaxMarkerPercent = 10.0;
  static constexpr int kMaxTrailFrames = 1000;
  static constexpr int kMaxAutosaveMinutes = 60;

  double markerSizePercent = 1.2;  ///< sphere radius, % of the take's size
  int trailFrames = 50;            ///< ± frames of the selected markers' trails (0: off)
  int upAxis = 2;                  ///< 1 = Y up, 2 = Z up
  QString language;                ///< code, e.g. "de"; empty: the system's
  int autosaveMinutes = 1;         ///< interval of the recovery copy
  QString displayUnit = QStringLiteral("mm");  ///< "mm", "cm" or "m" for read-outs
  ColorScheme colors;                          ///< sample states, selection, 3D background

  /// The remembered preferences (StudioOptions read afresh).
  [[nodiscard]] static Preferences load();
  /// Remembers these (through StudioOptions).
  void save() const;
  /// Clamps every field into its range (settings files can be edited by hand).
  [[nodiscard]] Preferences clamped() const;
};

/// Every remembered studio setting as a typed option: the one place that reads and writes the
/// studio's QSettings keys. Views, actions and the session follow the options
/// (SessionOption::follow); the preferences dialog and the menus set them.
struct StudioOptions
{
  StudioOptions();
  StudioOptions(const StudioOptions&) = delete;
  StudioOptions& operator=(const StudioOptions&) = delete;

  SessionOption<double> markerSizePercent;
  SessionOption<int> trailFrames;
  SessionOption<int> upAxis;
  SessionOption<QString> language;  // empty: the system's (read at start-up)
  SessionOption<int> autosaveMinutes;
  SessionOption<QString> displayUnit;  // "mm", "cm" or "m"
  SessionOption<ColorScheme> colors;
  SessionOption<bool> linksVisible;
  SessionOption<bool> showModelOutputs;
  SessionOption<bool> followHead;
  SessionOption<bool> keepRig;  // keep the face rig for the next take
  SessionOption<QStringList> recentFiles;  // newest first, absolute paths
  SessionOption<QString> lastFolder;       // where Open starts
  SessionOption<QByteArray> windowGeometry;  // the main window's (QWidget::saveGeometry)
  SessionOption<QByteArray> windowState;     // its docks and toolbars (QMainWindow::saveState)

  [[nodiscard]] Preferences preferences() const;
  /// Sets each option from `preferences` (clamped); an empty language leaves the language as it is.
  void setPreferences(const Preferences& preferences);
  /// The display unit as a LengthUnit.
  [[nodiscard]] LengthUnit lengthUnit() const;
};

} // namespace mocap::ui

#pragma once

#include "views/sample_colors.h"

#include <QDialog>
#include <QString>
#include <QStringList>

#include <utility>
#include <vector>

class QComboBox;
class QFormLayout;
class QPushButton;
class QDoubleSpinBox;
class QSpinBox;

namespace mocap::ui {

/// The studio's per-user view and safety settings, kept in QSettings.
struct Preferences
{
  double markerSizePercent = 1.2;  ///< sphere radius, % of the take's size
  int trailFrames = 50;            ///< ± frames of the selected markers' trails (0: off)
  int upAxis = 2;                  ///< 1 = Y up, 2 = Z up
  QString language;                ///< code, e.g. "de"; empty: the system's
  int autosaveMinutes = 1;         ///< interval of the recovery copy
  QString displayUnit = QStringLiteral("mm");  ///< "mm", "cm" or "m" for read-outs
  ColorScheme colors;                          ///< sample states, selection, 3D background

  [[nodiscard]] static Preferences load();
  void save() const;
  /// Clamps every field into its range (settings files can be edited by hand).
  [[nodiscard]] Preferences clamped() const;
};

/// Edits Preferences; the language list is given as (code, name) pairs so the dialog does not
/// depend on how the application installs translations.
class PreferencesDialog final : public QDialog
{
  Q_OBJECT

public:
  PreferencesDialog(const Preferences& preferences, const QStringList& languageCodes,
                    const QStringList& languageNames, QWidget* parent = nullptr);

  [[nodiscard]] Preferences preferences() const;
  /// The colour buttons (object names "color-original", "color-filled", "color-smoothed",
  /// "color-edited", "color-selection", "color-flagged", "color-background"); clicking one opens a colour dialog.
  [[nodiscard]] ColorScheme colors() const { return m_colors; }
  void setColors(const ColorScheme& colors);

private:
  void addColorButton(QFormLayout* form, const QString& name, const QString& text, QColor ColorScheme::*member);
  void updateColorButtons();

  ColorScheme m_colors;
  std::vector<std::pair<QPushButton*, QColor ColorScheme::*>> m_colorButtons;
  QDoubleSpinBox* m_markerSize = nullptr;
  QSpinBox* m_trail = nullptr;
  QComboBox* m_upAxis = nullptr;
  QComboBox* m_language = nullptr;
  QSpinBox* m_autosave = nullptr;
  QComboBox* m_unit = nullptr;
};

} // namespace mocap::ui

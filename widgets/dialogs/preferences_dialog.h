#pragma once

#include "document/studio_options.h"

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

/// Edits Preferences (the value of StudioOptions); the language list is given as (code, name) pairs so the dialog does not
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

/// Tells the user that a newly chosen language is used from the next start.
void sayLanguageIsUsedFromTheNextStart(QWidget& parent);

/// Edit ▸ Preferences: shows the dialog on `options` (with `fallbackLanguage` when none is
/// chosen yet) and, when accepted, sets the options, which every view follows; says that a new
/// language is used from the next start. Returns whether it was accepted.
bool editPreferences(StudioOptions& options, const QStringList& languageCodes, const QStringList& languageNames,
                     const QString& fallbackLanguage, QWidget* parent);

} // namespace mocap::ui

#include "dialogs/preferences_dialog.h"

#include <QColorDialog>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QPushButton>
#include <QMessageBox>
#include <QSpinBox>

#include <algorithm>

namespace mocap::ui {

namespace {
constexpr double kMinMarkerPercent = Preferences::kMinMarkerPercent, kMaxMarkerPercent = Preferences::kMaxMarkerPercent;
constexpr int kMaxTrailFrames = Preferences::kMaxTrailFrames;
constexpr int kMaxAutosaveMinutes = Preferences::kMaxAutosaveMinutes;
} // namespace

PreferencesDialog::PreferencesDialog(const Preferences& preferences, const QStringList& languageCodes,
                                     const QStringList& languageNames, QWidget* parent)
    : QDialog(parent)
{
  setWindowTitle(tr("Preferences"));
  auto* form = new QFormLayout(this);
  m_markerSize = new QDoubleSpinBox(this);
  m_markerSize->setRange(kMinMarkerPercent, kMaxMarkerPercent);
  m_markerSize->setSingleStep(0.1);
  m_markerSize->setSuffix(QStringLiteral(" %"));
  m_markerSize->setValue(preferences.markerSizePercent);
  m_markerSize->setToolTip(tr("Radius of the marker spheres as a share of the take's size"));
  form->addRow(tr("Marker size:"), m_markerSize);
  m_trail = new QSpinBox(this);
  m_trail->setRange(0, kMaxTrailFrames);
  m_trail->setValue(preferences.trailFrames);
  m_trail->setSpecialValueText(tr("Off"));
  m_trail->setToolTip(tr("Frames before and after the current one drawn as trails of the selected markers"));
  form->addRow(tr("Trail length (frames):"), m_trail);
  m_upAxis = new QComboBox(this);
  m_upAxis->addItem(tr("Y up"), 1);
  m_upAxis->addItem(tr("Z up"), 2);
  m_upAxis->setCurrentIndex(preferences.upAxis == 1 ? 0 : 1);
  form->addRow(tr("Up axis:"), m_upAxis);
  m_unit = new QComboBox(this);
  for (const char* unit : {"mm", "cm", "m"})
    m_unit->addItem(QString::fromLatin1(unit), QString::fromLatin1(unit));
  m_unit->setCurrentIndex(std::max(0, m_unit->findData(preferences.displayUnit)));
  m_unit->setToolTip(tr("Unit of the curve labels and read-outs; the take keeps its own units"));
  form->addRow(tr("Display units:"), m_unit);
  m_language = new QComboBox(this);
  for (int i = 0; i < languageCodes.size() && i < languageNames.size(); ++i)
    m_language->addItem(languageNames[i], languageCodes[i]);
  m_language->setCurrentIndex(std::max(0, static_cast<int>(languageCodes.indexOf(preferences.language))));
  m_language->setToolTip(tr("Used from the next start"));
  form->addRow(tr("Language:"), m_language);
  m_autosave = new QSpinBox(this);
  m_autosave->setRange(1, kMaxAutosaveMinutes);
  m_autosave->setSuffix(tr(" min"));
  m_autosave->setValue(preferences.autosaveMinutes);
  m_autosave->setToolTip(tr("How often unsaved edits are copied to a recovery file"));
  form->addRow(tr("Autosave every:"), m_autosave);
  m_colors = preferences.colors;
  addColorButton(form, QStringLiteral("original"), tr("Captured samples:"), &ColorScheme::original);
  addColorButton(form, QStringLiteral("filled"), tr("Filled samples:"), &ColorScheme::filled);
  addColorButton(form, QStringLiteral("smoothed"), tr("Smoothed samples:"), &ColorScheme::smoothed);
  addColorButton(form, QStringLiteral("edited"), tr("Edited samples:"), &ColorScheme::edited);
  addColorButton(form, QStringLiteral("selection"), tr("Selection:"), &ColorScheme::selection);
  addColorButton(form, QStringLiteral("flagged"), tr("Bad points:"), &ColorScheme::flagged);
  addColorButton(form, QStringLiteral("background"), tr("3D background:"), &ColorScheme::background);
  auto* defaults = new QPushButton(tr("Default Colours"), this);
  connect(defaults, &QPushButton::clicked, this, [this] { setColors(ColorScheme{}); });
  form->addRow(QString(), defaults);
  updateColorButtons();
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  form->addRow(buttons);
}

Preferences PreferencesDialog::preferences() const
{
  Preferences p;
  p.markerSizePercent = m_markerSize->value();
  p.trailFrames = m_trail->value();
  p.upAxis = m_upAxis->currentData().toInt();
  p.language = m_language->currentData().toString();
  p.autosaveMinutes = m_autosave->value();
  p.displayUnit = m_unit->currentData().toString();
  p.colors = m_colors;
  return p.clamped();
}

void PreferencesDialog::addColorButton(QFormLayout* form, const QString& name, const QString& text,
                                       QColor ColorScheme::*member)
{
  auto* button = new QPushButton(this);
  button->setObjectName(QStringLiteral("color-") + name);
  connect(button, &QPushButton::clicked, this, [this, text, member] {
    const QColor chosen = QColorDialog::getColor(m_colors.*member, this, text);
    if (chosen.isValid()) {
      m_colors.*member = chosen;
      updateColorButtons();
    }
  });
  form->addRow(text, button);
  m_colorButtons.emplace_back(button, member);
}

void PreferencesDialog::setColors(const ColorScheme& colors)
{
  m_colors = colors;
  updateColorButtons();
}

void PreferencesDialog::updateColorButtons()
{
  for (const auto& [button, member] : m_colorButtons) {
    const QColor color = m_colors.*member;
    button->setText(color.name());
    button->setStyleSheet(QStringLiteral("background-color: %1; color: %2")
                              .arg(color.name(), color.lightnessF() > 0.5f ? QStringLiteral("black")
                                                                          : QStringLiteral("white")));
  }
}

void sayLanguageIsUsedFromTheNextStart(QWidget& parent)
{
  QMessageBox::information(&parent, PreferencesDialog::tr("Language"),
                           PreferencesDialog::tr("The new language is used from the next start."));
}

bool editPreferences(StudioOptions& options, const QStringList& languageCodes, const QStringList& languageNames,
                     const QString& fallbackLanguage, QWidget* parent)
{
  Preferences preferences = options.preferences();
  if (preferences.language.isEmpty())
    preferences.language = fallbackLanguage;
  PreferencesDialog dialog(preferences, languageCodes, languageNames, parent);
  if (dialog.exec() != QDialog::Accepted)
    return false;
  const Preferences chosen = dialog.preferences();
  if (chosen.language != preferences.language && parent)
    sayLanguageIsUsedFromTheNextStart(*parent);
  options.setPreferences(chosen);
  return true;
}

} // namespace mocap::ui

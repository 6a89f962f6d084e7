#include "dialogs/preferences_dialog.h"

#include <QColorDialog>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>

#include "mocap/base/length_unit.h"

#include <algorithm>

namespace mocap::ui {

namespace {
constexpr double kMinMarkerPercent = 0.1, kMaxMarkerPercent = 10.0;
constexpr int kMaxTrailFrames = 1000;
constexpr int kMaxAutosaveMinutes = 60;

// The settings key of each colour, in the order the dialog lists them.
const std::pair<const char*, QColor ColorScheme::*> kColorKeys[] = {
    {"original", &ColorScheme::original}, {"filled", &ColorScheme::filled},
    {"smoothed", &ColorScheme::smoothed}, {"edited", &ColorScheme::edited},
    {"selection", &ColorScheme::selection}, {"flagged", &ColorScheme::flagged},
    {"background", &ColorScheme::background}};
} // namespace

Preferences Preferences::load()
{
  const QSettings settings;
  Preferences p;
  p.markerSizePercent = settings.value(QStringLiteral("view/markerSizePercent"), p.markerSizePercent).toDouble();
  p.trailFrames = settings.value(QStringLiteral("view/trailFrames"), p.trailFrames).toInt();
  p.upAxis = settings.value(QStringLiteral("view/upAxis"), p.upAxis).toInt();
  p.language = settings.value(QStringLiteral("language")).toString();
  p.autosaveMinutes = settings.value(QStringLiteral("autosaveMinutes"), p.autosaveMinutes).toInt();
  p.displayUnit = settings.value(QStringLiteral("view/displayUnit"), p.displayUnit).toString();
  for (const auto& [key, member] : kColorKeys)
    p.colors.*member = QColor(settings.value(QStringLiteral("view/colors/") + QLatin1String(key),
                                             (p.colors.*member).name()).toString());
  return p.clamped();
}

void Preferences::save() const
{
  QSettings settings;
  settings.setValue(QStringLiteral("view/markerSizePercent"), markerSizePercent);
  settings.setValue(QStringLiteral("view/trailFrames"), trailFrames);
  settings.setValue(QStringLiteral("view/upAxis"), upAxis);
  if (!language.isEmpty())
    settings.setValue(QStringLiteral("language"), language);
  settings.setValue(QStringLiteral("autosaveMinutes"), autosaveMinutes);
  settings.setValue(QStringLiteral("view/displayUnit"), displayUnit);
  for (const auto& [key, member] : kColorKeys)
    settings.setValue(QStringLiteral("view/colors/") + QLatin1String(key), (colors.*member).name());
}

Preferences Preferences::clamped() const
{
  Preferences p = *this;
  p.markerSizePercent = std::clamp(p.markerSizePercent, kMinMarkerPercent, kMaxMarkerPercent);
  if (!(p.markerSizePercent == p.markerSizePercent))  // NaN from a hand-edited file
    p.markerSizePercent = Preferences{}.markerSizePercent;
  p.trailFrames = std::clamp(p.trailFrames, 0, kMaxTrailFrames);
  p.upAxis = p.upAxis == 1 ? 1 : 2;
  p.autosaveMinutes = std::clamp(p.autosaveMinutes, 1, kMaxAutosaveMinutes);
  if (!parseLengthUnit(p.displayUnit.toStdString()))
    p.displayUnit = Preferences{}.displayUnit;
  for (const auto& [key, member] : kColorKeys)
    if (!(p.colors.*member).isValid())  // a hand-edited name Qt cannot read
      p.colors.*member = ColorScheme{}.*member;
  return p;
}

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

} // namespace mocap::ui

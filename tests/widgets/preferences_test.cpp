// Preferences: remembered across runs, and absurd hand-edited values are clamped, never used.
#include "dialogs/preferences_dialog.h"
#include "views/display_units.h"
#include "views/sample_colors.h"

#include <QPushButton>
#include <QSettings>

#include <gtest/gtest.h>

#include <limits>

namespace mocap {
namespace {

using ui::Preferences;

TEST(Preferences, SavedValuesComeBackAndAbsurdOnesAreClamped)
{
  QSettings().clear();
  Preferences p;
  p.markerSizePercent = 2.5;
  p.trailFrames = 120;
  p.upAxis = 1;
  p.language = QStringLiteral("de");
  p.autosaveMinutes = 5;
  p.displayUnit = QStringLiteral("cm");
  p.save();
  const Preferences loaded = Preferences::load();
  EXPECT_DOUBLE_EQ(loaded.markerSizePercent, 2.5);
  EXPECT_EQ(loaded.trailFrames, 120);
  EXPECT_EQ(loaded.upAxis, 1);
  EXPECT_EQ(loaded.language, QStringLiteral("de"));
  EXPECT_EQ(loaded.autosaveMinutes, 5);
  EXPECT_EQ(loaded.displayUnit, QStringLiteral("cm"));

  QSettings settings;
  settings.setValue(QStringLiteral("view/markerSizePercent"), std::numeric_limits<double>::quiet_NaN());
  settings.setValue(QStringLiteral("view/trailFrames"), -7);
  settings.setValue(QStringLiteral("view/upAxis"), 9);
  settings.setValue(QStringLiteral("autosaveMinutes"), 100000);
  settings.setValue(QStringLiteral("view/displayUnit"), QStringLiteral("furlong"));
  settings.sync();
  const Preferences clamped = Preferences::load();
  EXPECT_DOUBLE_EQ(clamped.markerSizePercent, Preferences{}.markerSizePercent);
  EXPECT_EQ(clamped.trailFrames, 0);
  EXPECT_EQ(clamped.upAxis, 2);
  EXPECT_EQ(clamped.autosaveMinutes, 60);
  EXPECT_EQ(clamped.displayUnit, QStringLiteral("mm"));
  QSettings().clear();
}

TEST(DisplayUnits, LengthsConvertBetweenTheTakeAndTheDisplayUnit)
{
  EXPECT_EQ(ui::formatLength(1234.5, LengthUnit::Millimetre, LengthUnit::Centimetre), QStringLiteral("123.45"));
  EXPECT_EQ(ui::formatLength(1.2345, LengthUnit::Metre, LengthUnit::Millimetre), QStringLiteral("1234.5"));
  EXPECT_EQ(ui::formatLength(12.0, LengthUnit::Millimetre, LengthUnit::Metre), QStringLiteral("0.0120"));
  EXPECT_EQ(ui::unitLabel(LengthUnit::Centimetre), QStringLiteral("cm"));
}

TEST(Preferences, ColoursAreRememberedAndUnreadableOnesFallBackToTheDefaults)
{
  QSettings().clear();
  Preferences p;
  p.colors.filled = QColor(1, 2, 3);
  p.colors.background = QColor(200, 10, 10);
  p.save();
  EXPECT_TRUE(Preferences::load().colors == p.colors);
  QSettings().setValue(QStringLiteral("view/colors/edited"), QStringLiteral("not-a-colour"));
  const Preferences loaded = Preferences::load();
  EXPECT_EQ(loaded.colors.edited, ui::ColorScheme{}.edited);
  EXPECT_EQ(loaded.colors.filled, QColor(1, 2, 3));
  QSettings().clear();

  ui::PreferencesDialog dialog(p, {QStringLiteral("en")}, {QStringLiteral("English")});
  const auto* button = dialog.findChild<QPushButton*>(QStringLiteral("color-filled"));
  ASSERT_NE(button, nullptr);
  EXPECT_EQ(button->text(), QStringLiteral("#010203"));
  EXPECT_TRUE(dialog.preferences().colors == p.colors);
  dialog.setColors(ui::ColorScheme{});
  EXPECT_TRUE(dialog.preferences().colors == ui::ColorScheme{});

  ui::setColorScheme(p.colors);
  EXPECT_EQ(ui::stateColor(SampleOrigin::Filled), QColor(1, 2, 3));
  ui::setColorScheme(ui::ColorScheme{});
  EXPECT_EQ(ui::stateColor(SampleOrigin::Filled), ui::ColorScheme{}.filled);
}

TEST(Preferences, TheDialogShowsAndReturnsThePreferences)
{
  Preferences p;
  p.trailFrames = 33;
  p.language = QStringLiteral("zh_CN");
  const ui::PreferencesDialog dialog(p, {QStringLiteral("en"), QStringLiteral("de"), QStringLiteral("zh_CN")},
                                     {QStringLiteral("English"), QStringLiteral("Deutsch"), QStringLiteral("中文")});
  const Preferences shown = dialog.preferences();
  EXPECT_EQ(shown.trailFrames, 33);
  EXPECT_EQ(shown.language, QStringLiteral("zh_CN"));
  EXPECT_EQ(shown.upAxis, 2);
}

} // namespace
} // namespace mocap

#pragma once

#include <QString>
#include <QWidget>

#include <optional>
#include <string>

class QComboBox;
class QLineEdit;
class QPushButton;

namespace mocap::ui {

/// The retarget map choice every studio export and import offers, as `--map` takes it: none (the
/// caller says what none means), one of the shipped maps (shippedRetargetMapNames), or a map
/// file typed or browsed for; and, when the caller offers it, a map it holds in memory (the
/// Retarget section's, its gains edited). changed() fires on every choice, so the caller can
/// check the map against the rig at once.
class RetargetMapChooser final : public QWidget
{
  Q_OBJECT

public:
  /// `noneText` names the first entry ("None (the rig's own names)", "By name").
  explicit RetargetMapChooser(const QString& noneText, QWidget* parent = nullptr);

  /// nullopt for none (and for the map in memory), else a shipped map's name or the file's path
  /// (readRetargetMapByNameOrPath).
  [[nodiscard]] std::optional<std::string> map() const;
  /// Adds the caller's map in memory as the entry after none, named `text`, and selects it.
  void offerLoadedMap(const QString& text);
  /// True when the map in memory is chosen (the caller supplies it).
  [[nodiscard]] bool loadedMapChosen() const;
  /// Selects none (""), a shipped map by name, or else a map file at `nameOrPath`.
  void setMap(const QString& nameOrPath);
  /// True when "Map file…" is chosen and no file is given yet.
  [[nodiscard]] bool lacksFile() const;

  /// The choice as one string for a remembered option ("", a shipped name, "file:" + path) and back
  /// (the map in memory is restored only while it is offered).
  [[nodiscard]] QString settingValue() const;
  void restoreSettingValue(const QString& value);

signals:
  void changed();

private:
  void browse();
  void onChoice();

  QComboBox* m_choice = nullptr;
  QLineEdit* m_file = nullptr;
  QPushButton* m_browse = nullptr;
};

} // namespace mocap::ui

#pragma once

#include "mocap/model/retarget_map.h"

#include <QObject>
#include <QString>

#include <optional>

namespace mocap::ui {

/// The retarget map the Retarget section of the solve dock shows and edits: our weight names onto
/// a target rig's channels (model/retarget_map.h), loaded from a shipped map or a file, its gains
/// edited through EditRetargetGainCommand on the document's undo stack. Loading another map starts
/// a new generation, so the gain edits of the one before no longer apply.
class RetargetMapModel final : public QObject
{
  Q_OBJECT

public:
  explicit RetargetMapModel(QObject* parent = nullptr);

  /// Replaces the map (nullopt: none); `name` is what the map was read from (a shipped name or a path);
  /// `edited`: its gains were changed since (a map restored with its edits after a crash).
  void setMap(std::optional<RetargetMap> map, QString name, bool edited = false);
  [[nodiscard]] const std::optional<RetargetMap>& map() const { return m_map; }
  [[nodiscard]] const QString& name() const { return m_name; }
  /// True once a gain was changed since the map was loaded or saved.
  [[nodiscard]] bool edited() const { return m_edited; }
  void markSaved(QString name);
  [[nodiscard]] int generation() const { return m_generation; }

  /// Sets the gain of source `source` of channel `channel` and returns the gain it had, so setting
  /// that back undoes it. Throws InvalidArgument for a source the map does not have or a gain
  /// that is not finite. O(1).
  double swapGain(int channel, int source, double gain);

signals:
  void mapChanged();
  void gainChanged(int channel, int source);

private:
  std::optional<RetargetMap> m_map;
  QString m_name;
  bool m_edited = false;
  int m_generation = 0;
};

} // namespace mocap::ui

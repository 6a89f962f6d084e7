#pragma once

#include <QDialog>
#include <QString>

#include <optional>
#include <string>

class QLineEdit;

namespace mocap::ui {

class RetargetMapChooser;

/// Asks for a Live Link Face recording (the CSV Epic's app writes) and the map from its 52 curves
/// onto the loaded rig's shapes: by name (rigMapFromLiveLinkFace, the default), a shipped map
/// (arkit_to_ict) or a map file. The folder and the map are remembered (session options "liveLinkOpen/…").
class LiveLinkOpenDialog final : public QDialog
{
  Q_OBJECT

public:
  explicit LiveLinkOpenDialog(QWidget* parent = nullptr);

  [[nodiscard]] QString recordingPath() const;
  void setRecordingPath(const QString& path);
  /// nullopt: by name; else a shipped map's name or a map file.
  [[nodiscard]] std::optional<std::string> map() const;
  void setMap(const QString& nameOrPath);

  /// Remembers the choices and closes with Accepted, unless no recording is named.
  void accept() override;

private:
  void browse();

  QLineEdit* m_path = nullptr;
  RetargetMapChooser* m_map = nullptr;
};

} // namespace mocap::ui

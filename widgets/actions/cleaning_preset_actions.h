#pragma once

#include "mocap/batch/clean_preset.h"

#include <QObject>
#include <QString>
#include <QStringList>

#include <functional>

class QWidget;

namespace mocap::ui {

class TakeDocument;

/// File ▸ Save Cleaning Preset… and Load Cleaning Preset…: the cleaning settings as the JSON
/// `mocap clean --preset` and `mocap batch --preset` read. The settings come from and go to a
/// `CleanOptionsSource` (the Cleaning dock's steps), so the actions know no panel.
class CleaningPresetActions final : public QObject
{
  Q_OBJECT

public:
  /// Where the settings are: `current()` reads them, `load(options)` shows them (untouched take)
  /// and returns the steps the options turn off.
  struct CleanOptionsSource
  {
    std::function<CleanOptions()> current;
    std::function<QStringList(const CleanOptions&)> load;
  };

  /// `dialogParent` parents the file dialogs and warnings.
  CleaningPresetActions(TakeDocument& document, QWidget& dialogParent, CleanOptionsSource source,
                        QObject* parent = nullptr);

  /// Writes the settings as a preset, atomically. The take's head markers go in only
  /// `withHeadMarkers` (a preset carries options; the markers are this take's). Returns the error
  /// message, empty on success.
  QString save(const QString& path, bool withHeadMarkers = false);
  /// Reads a preset into the settings (shown, the take untouched until Apply), then emits
  /// loaded() and says what it did. Returns the error message (nothing loaded), empty on success.
  QString load(const QString& path);
  /// Asks for the file (with an "include head markers" box, off), then save().
  void saveWithDialog();
  /// Asks for the file, then load().
  void loadWithDialog();

signals:
  /// A preset was loaded into the settings (the window shows them).
  void loaded();
  /// What was saved or loaded, for the status bar.
  void message(const QString& text, int timeoutMs);

private:
  TakeDocument& m_document;
  QWidget& m_dialogParent;
  CleanOptionsSource m_source;
};

} // namespace mocap::ui

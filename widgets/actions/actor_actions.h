#pragma once

#include <QObject>
#include <QString>

class QMenu;
class QWidget;

namespace mocap::ui {

class StudioSession;

/// The Actor menu (per-actor calibration, as `mocap actor` and `mocap solve --actor`):
/// - New from Neutral Frame…: the bound markers at the current frame of the take the face mesh
///   sees (head motion removed), the binding and the rig's shapes as an actor profile
///   (makeActorProfile), written as JSON and loaded;
/// - Calibrate from ROM Take…: the loaded actor's shape extents from a range-of-motion take (read,
///   put in the actor's units and stabilized on the face mesh's head markers), calibrateActorRange
///   on a worker, written and loaded;
/// - Load Actor…: a profile file, checked against the rig's shapes.
/// The loaded actor is the solve's (BlendshapeSolveModel::actor) and is remembered with the take
/// (the session option "actorForTake/…", the take's path → the profile's), so opening the take again loads
/// it; another take starts without one unless it remembers its own.
class ActorActions final : public QObject
{
  Q_OBJECT

public:
  ActorActions(StudioSession& session, QWidget& dialogParent, QObject* parent = nullptr);

  /// The Actor menu with the three actions, Clear Actor and the loaded actor's name.
  [[nodiscard]] QMenu* createMenu(QWidget* parent);

  /// Each returns "" or the error (also sent as message()).
  QString newFromNeutralFrame(const QString& outPath);
  QString calibrateFromRom(const QString& romTakePath, const QString& outPath);
  QString loadActor(const QString& path);
  void clearActor();

signals:
  /// What an action did or why it did nothing, for the status bar.
  void message(const QString& text, int timeoutMs);

private:
  void newDialog();
  void calibrateDialog();
  void loadDialog();
  /// The take's remembered actor, loaded when a take is opened.
  void restoreForTake();
  void rememberForTake(const QString& actorPath) const;
  QString failed(const QString& why);

  StudioSession& m_session;
  QWidget& m_dialogParent;
};

} // namespace mocap::ui

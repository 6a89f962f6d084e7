#include "actions/actor_actions.h"

#include "dialogs/job_dialog.h"
#include "dialogs/remembered_file_dialog.h"
#include "document/blendshape_solve_model.h"
#include "document/face_mesh_model.h"
#include "document/remembered_folder.h"
#include "document/session_option.h"
#include "document/studio_session.h"
#include "document/take_document.h"
#include "views/status_timeout.h"

#include "mocap/deform/actor_calibration.h"
#include "mocap/deform/actor_profile_io.h"
#include "mocap/deform/retarget.h"
#include "mocap/io/take_io.h"

#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QUrl>

#include <memory>

namespace mocap::ui {

namespace {

const QString kFolderGroup = QStringLiteral("actor/");  // its dialogs' folder: "actor/folder"

/// The actor profile a take remembers ("actorForTake/" + the take's encoded path).
SessionOption<QString> actorOfTake(const QString& takePath)
{
  return {QStringLiteral("actorForTake/") +
              QString::fromLatin1(QUrl::toPercentEncoding(QFileInfo(takePath).absoluteFilePath())),
          QString()};
}

std::vector<std::string> boundLabels(const MeshBinding& binding)
{
  std::vector<std::string> labels;
  for (const MarkerBinding& marker : binding.markers)
    labels.push_back(marker.label);
  return labels;
}

} // namespace

ActorActions::ActorActions(StudioSession& session, QWidget& dialogParent, QObject* parent)
    : QObject(parent), m_session(session), m_dialogParent(dialogParent)
{
  connect(&session, &StudioSession::takeContextReset, this, &ActorActions::restoreForTake);
}

QMenu* ActorActions::createMenu(QWidget* parent)
{
  auto* menu = new QMenu(tr("&Actor"), parent);
  menu->addAction(tr("&New from Neutral Frame…"), this, &ActorActions::newDialog)
      ->setToolTip(tr("The bound markers at the current frame as an actor's neutral (mocap actor --neutral TAKE:FRAME)"));
  menu->addAction(tr("&Calibrate from ROM Take…"), this, &ActorActions::calibrateDialog)
      ->setToolTip(tr("Each shape's extent for the loaded actor from a range-of-motion take (mocap actor --rom)"));
  menu->addAction(tr("&Load Actor…"), this, &ActorActions::loadDialog)
      ->setToolTip(tr("An actor profile for the solve (mocap solve --actor)"));
  QAction* clear = menu->addAction(tr("C&lear Actor"), this, &ActorActions::clearActor);
  BlendshapeSolveModel& model = m_session.blendshapes();
  const auto update = [clear, &model] { clear->setEnabled(model.actor() != nullptr); };
  connect(&model, &BlendshapeSolveModel::actorChanged, clear, update);
  update();
  return menu;
}

QString ActorActions::failed(const QString& why)
{
  emit message(why, kStatusMessageMs);
  return why;
}

QString ActorActions::newFromNeutralFrame(const QString& outPath)
{
  const TakeDocument& document = m_session.document();
  const FaceMeshModel& face = m_session.faceMesh();
  BlendshapeSolveModel& model = m_session.blendshapes();
  if (!document.hasTake() || !model.hasRig() || face.binding().markers.empty())
    return failed(tr("Open a take, load a rig and bind the markers to its neutral first."));
  try {
    const Take& take = face.rigTake();  // head motion removed, as the solve sees it
    const long long frame = take.firstFrame() + document.currentFrame();
    const PointSet neutral = neutralFromFrame(take, boundLabels(face.binding()), frame);
    const std::string source = QFileInfo(document.filePath()).fileName().toStdString() + ":" + std::to_string(frame);
    const ActorProfile profile = makeActorProfile(QFileInfo(outPath).completeBaseName().toStdString(), face.binding(),
                                                  *model.rig(), neutral, take.units(), source);
    writeActorProfile(outPath.toStdString(), profile);
  } catch (const std::exception& e) {
    return failed(tr("No actor made: %1").arg(QString::fromStdString(e.what())));
  }
  return loadActor(outPath);
}

QString ActorActions::calibrateFromRom(const QString& romTakePath, const QString& outPath)
{
  BlendshapeSolveModel& model = m_session.blendshapes();
  if (!model.actor() || !model.hasRig())
    return failed(tr("Load a rig and an actor (or make one from a neutral frame) first."));
  ActorProfile profile = *model.actor();
  const std::vector<std::string> stabilization = m_session.faceMesh().stabilization();
  const std::shared_ptr<const BlendshapeRig> rig = model.rig();
  try {
    const bool done = runJob(&m_dialogParent, tr("Calibrating from %1…").arg(QFileInfo(romTakePath).fileName()),
                             [&](const JobControl& control) {
                               Take rom = readTake(romTakePath.toStdString());
                               if (rom.units() != profile.units)
                                 rom.convertUnits(profile.units);
                               if (!stabilization.empty())
                                 (void)stabilizeTake(rom, stabilization);
                               (void)calibrateActorRange(profile, *rig, rom,
                                                         QFileInfo(romTakePath).fileName().toStdString(), {}, control);
                             });
    if (!done)
      return failed(tr("Calibration cancelled; the actor is as it was."));
    writeActorProfile(outPath.toStdString(), profile);
  } catch (const std::exception& e) {
    return failed(tr("Not calibrated: %1").arg(QString::fromStdString(e.what())));
  }
  return loadActor(outPath);
}

QString ActorActions::loadActor(const QString& path)
{
  BlendshapeSolveModel& model = m_session.blendshapes();
  std::shared_ptr<const ActorProfile> profile;
  try {
    profile = std::make_shared<const ActorProfile>(readActorProfile(path.toStdString()));
    if (model.hasRig())
      (void)actorExtents(*profile, model.rig()->shapeNames());  // a profile made for another rig: said now
  } catch (const std::exception& e) {
    return failed(tr("Cannot load the actor: %1").arg(QString::fromStdString(e.what())));
  }
  model.setActor(profile, path);
  rememberForTake(path);
  emit message(tr("Actor %1: the solve uses its neutral and range.").arg(QString::fromStdString(profile->name)),
               kStatusMessageMs);
  return {};
}

void ActorActions::clearActor()
{
  m_session.blendshapes().setActor(nullptr, {});
  rememberForTake({});
}

void ActorActions::restoreForTake()
{
  BlendshapeSolveModel& model = m_session.blendshapes();
  model.setActor(nullptr, {});  // an actor belongs to the takes that remember it
  const QString takePath = m_session.document().filePath();
  if (takePath.isEmpty())
    return;
  const QString actorPath = actorOfTake(takePath).get();
  if (!actorPath.isEmpty())
    (void)loadActor(actorPath);
}

void ActorActions::rememberForTake(const QString& actorPath) const
{
  const QString takePath = m_session.document().filePath();
  if (takePath.isEmpty())
    return;
  SessionOption<QString> actor = actorOfTake(takePath);
  if (actorPath.isEmpty())
    actor.forget();
  else
    actor = QFileInfo(actorPath).absoluteFilePath();
}

void ActorActions::newDialog()
{
  const QString path =
      saveFileOfGroup(&m_dialogParent, tr("New Actor from Neutral Frame"), kFolderGroup, tr("Actor profiles (*.json)"));
  if (path.isEmpty())
    return;
  (void)newFromNeutralFrame(path.endsWith(QStringLiteral(".json"), Qt::CaseInsensitive) ? path : path + QStringLiteral(".json"));
}

void ActorActions::calibrateDialog()
{
  const QString rom = QFileDialog::getOpenFileName(&m_dialogParent, tr("Range-of-Motion Take"),
                                                   rememberedFolder(kFolderGroup), tr("Takes (*.c3d *.trc);;All files (*)"));
  if (rom.isEmpty())
    return;
  const QString out = QFileDialog::getSaveFileName(&m_dialogParent, tr("Save the Calibrated Actor"),
                                                   m_session.blendshapes().actorPath(), tr("Actor profiles (*.json)"));
  if (!out.isEmpty())
    (void)calibrateFromRom(rom, out);
}

void ActorActions::loadDialog()
{
  const QString path =
      openFileOfGroup(&m_dialogParent, tr("Load Actor"), kFolderGroup, tr("Actor profiles (*.json);;All files (*)"));
  if (!path.isEmpty())
    (void)loadActor(path);
}

} // namespace mocap::ui

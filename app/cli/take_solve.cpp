#include "take_solve.h"

#include "arguments.h"
#include "rig_input.h"
#include "take_input.h"

#include "mocap/base/stopwatch.h"
#include "mocap/cleaning/head_angles.h"
#include "mocap/cleaning/head_marker_labels.h"
#include "mocap/deform/actor_profile_io.h"
#include "mocap/deform/mesh_binding.h"
#include "mocap/deform/retarget.h"

namespace mocap::cli {

Eigen::MatrixXd SolvedTake::headRotation() const
{
  return motion ? headYawPitchRoll(*motion, solver->retarget().rotation) : Eigen::MatrixXd();
}

std::string SolvedTake::unstabilizedHeadNote() const
{
  if (motion)
    return {};
  const std::vector<Eigen::Index> head = labelledHeadMarkers(take);
  if (head.empty())
    return {};
  std::string labels;
  for (const Eigen::Index m : head)
    labels += (labels.empty() ? "" : ",") + take.label(m);
  return "the take names head-mounted markers but --stabilize was not given, so the head's motion was solved as "
         "expression; to remove it first, add --stabilize " + labels;
}

SolvedTake solveInputTake(const SolveInput& input, const std::function<void(const BlendshapeRig&)>& checkRig)
{
  BlendshapeSolveOptions settings = input.settings;
  settings.method = parseBlendshapeSolveMethod(input.method).value();
  SolvedTake solved;
  const Stopwatch load;
  solved.rig = std::make_unique<const BlendshapeRig>(readInputRig(input.meshPath, input.shapesPath, input.only));
  solved.rigLoadSeconds = load.seconds();
  if (checkRig)
    checkRig(*solved.rig);
  solved.take = readInputTake(input.takePath);
  if (input.actor) {
    settings.actor = std::make_shared<const ActorProfile>(readActorProfile(*input.actor));
    if (solved.take.units() != settings.actor->units)
      solved.take.convertUnits(settings.actor->units);
  }
  if (input.stabilize) {
    solved.motion = estimateHeadMotion(solved.take, markerIndices(solved.take, splitList(*input.stabilize, "--stabilize")));
    removeHeadMotion(solved.take, *solved.motion);
  }
  solved.solver = std::make_unique<const BlendshapeSolver>(
      *solved.rig, readBinding(input.bindingPath, solved.rig->neutral.vertexCount()), solved.take, settings);
  solved.result = solved.solver->solve(solved.take);
  return solved;
}

} // namespace mocap::cli

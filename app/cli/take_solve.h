#pragma once

#include "mocap/cleaning/head_stabilization.h"
#include "mocap/deform/blendshape_solver.h"
#include "mocap/model/blendshape_rig.h"
#include "mocap/model/take.h"

#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace mocap::cli {

/// What a solve on the command line reads: `mocap solve` and `mocap stream` take the same options.
struct SolveInput
{
  std::string meshPath, shapesPath, bindingPath, takePath;
  std::optional<std::string> stabilize, only, actor;
  BlendshapeSolveOptions settings;
  std::string method = std::string(blendshapeSolveMethodName(BlendshapeSolveOptions{}.method));
};

/// A take solved to a rig, and what the outputs need of it.
struct SolvedTake
{
  std::unique_ptr<const BlendshapeRig> rig;  // the solver refers to it
  Take take;                                 // as solved: stabilized, in the actor's units
  std::optional<HeadMotion> motion;          // what --stabilize removed
  std::unique_ptr<const BlendshapeSolver> solver;
  BlendshapeSolveResult result;
  double rigLoadSeconds = 0.0;

  /// The head's yaw, pitch and roll per frame in the rig's axes (Live Link's head rotation) from
  /// the motion --stabilize removed; empty (zeros) without it. O(#frames).
  [[nodiscard]] Eigen::MatrixXd headRotation() const;
  /// When the take names head-mounted markers (root…/head…) and --stabilize was not given, a
  /// sentence saying so and the option to pass: their motion was solved as expression, which
  /// on a moving head costs tens of millimetres of residual. The CLI guesses nothing, so it only
  /// says. Else empty. O(#markers).
  [[nodiscard]] std::string unstabilizedHeadNote() const;
};

/// Reads the rig, then calls `checkRig` (so a wrong map fails before the take is read or solved),
/// reads the take, applies --actor and --stabilize, and solves. Throws whatever the readers and
/// the solver throw. O(the files' size + the solve).
[[nodiscard]] SolvedTake solveInputTake(const SolveInput& input,
                                        const std::function<void(const BlendshapeRig&)>& checkRig);

} // namespace mocap::cli

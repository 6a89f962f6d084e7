#pragma once

#include <CLI/CLI.hpp>

#include <functional>

namespace mocap::cli {

/// One `mocap` command: its CLI11 subcommand, whose options are bound to state that `run` owns,
/// and `run`, called once the arguments parsed, which returns the exit code.
struct Command
{
  CLI::App* app = nullptr;
  std::function<int()> run;
};

// Each adds its command to `mocap`; the usage text is generated from these definitions.

/// `mocap info FILE`: what the take holds and every gap.
Command addInfo(CLI::App& mocap);
/// `mocap convert IN OUT`: reads IN and writes OUT, formats by extension, optionally rescaled.
Command addConvert(CLI::App& mocap);
/// `mocap clean IN -o OUT`: stabilize, spikes, fill, smooth (issue 3); `--manifest F --index I`
/// cleans one take of a batch manifest (a cluster array task).
Command addClean(CLI::App& mocap);
/// `mocap batch MANIFEST -o OUTDIR`: every take of a manifest cleaned in parallel (issue 17).
Command addBatch(CLI::App& mocap);
/// `mocap summarize OUTDIR -o report.html`: the archive report of a batch (issue 17).
Command addSummarize(CLI::App& mocap);
/// `mocap eval-fill TAKE`: gap-filling methods against hidden truth (Gløersen & Federolf protocol).
Command addEvalFill(CLI::App& mocap);
/// `mocap eval-spikes TAKE`: recall and false alarms of the spike detectors.
Command addEvalSpikes(CLI::App& mocap);
/// `mocap eval-smooth TAKE`: smoothing methods against clean data with added noise.
Command addEvalSmooth(CLI::App& mocap);
/// `mocap smooth-table TAKE`: the paper's Table 1 (smoothness per B-spline order).
Command addSmoothTable(CLI::App& mocap);
/// `mocap pfa TAKE [TAKE...]`: marker layout planning (Principal Feature Analysis and greedy).
Command addPfa(CLI::App& mocap);
/// `mocap track IN -o OUT`: unlabelled points into labelled trajectories.
Command addTrack(CLI::App& mocap);
/// `mocap fix-swaps IN -o OUT`: finds and repairs label swaps.
Command addFixSwaps(CLI::App& mocap);
/// `mocap eval-track TAKE`: label recovery and swap detection on a labelled take.
Command addEvalTrack(CLI::App& mocap);
/// `mocap bind --mesh FACE.obj --take TAKE -o BIND.json`: binds markers to mesh points.
Command addBind(CLI::App& mocap);
/// `mocap deform --mesh FACE.obj --binding BIND.json --take TAKE -o OUT`: RBF or Laplacian
/// face-mesh deformation driven by the take's markers.
Command addDeform(CLI::App& mocap);
/// `mocap rig --mesh NEUTRAL.obj|RIG.glb [--shapes DIR] -o RIG.glb`: a blendshape rig as one GLB,
/// optionally cut to some shapes or a vertex range.
Command addRig(CLI::App& mocap);
/// `mocap solve --mesh NEUTRAL.obj|RIG.glb [--shapes DIR] --binding BIND.json --take TAKE -o OUT`:
/// the take's blendshape weights on a rig (bvls, ridge, temporal), as CSV curves, an animated GLB
/// or a PC2 cache.
Command addSolve(CLI::App& mocap);
/// `mocap actor --rig RIG --binding BIND.json --neutral TAKE[:FRAME] [--rom TAKE] -o ACTOR.json`:
/// an actor profile (neutral, binding, each shape's extent) for `mocap solve --actor`.
Command addActor(CLI::App& mocap);
/// `mocap stream TAKE --rig RIG --binding BIND.json --protocol livelink|vmc --to HOST:PORT`: the
/// solved weights (or --weights curves) and markers sent live over UDP in real time (issue 34).
Command addStream(CLI::App& mocap);

/// `mocap review TAKE -o OUT.mp4`: a review video (playblast) of the 3D view (issue 16).
Command addReview(CLI::App& mocap);

} // namespace mocap::cli

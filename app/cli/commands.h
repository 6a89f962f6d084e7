#pragma once

#include <string>
#include <vector>

namespace mocap::cli {

/// `mocap info FILE [--json]`: what the take holds and every gap. Returns the exit code.
int runInfo(const std::vector<std::string>& args);

/// `mocap convert IN OUT [--units mm|cm|m]`: reads IN and writes OUT, formats by extension,
/// optionally rescaling positions to other units.
int runConvert(const std::vector<std::string>& args);

/// `mocap clean IN -o OUT ...`: stabilize, spikes, fill, smooth; see issue 3 for the flags.
int runClean(const std::vector<std::string>& args);

/// `mocap eval-fill TAKE ...`: gap-filling methods against hidden truth (Gløersen & Federolf protocol).
int runEvalFill(const std::vector<std::string>& args);

/// `mocap eval-spikes TAKE ...`: recall and false alarms of the spike detectors.
int runEvalSpikes(const std::vector<std::string>& args);

/// `mocap eval-smooth TAKE ...`: smoothing methods against clean data with added noise.
int runEvalSmooth(const std::vector<std::string>& args);

/// `mocap smooth-table TAKE ...`: the paper's Table 1 (smoothness per B-spline order).
int runSmoothTable(const std::vector<std::string>& args);

/// `mocap pfa TAKE [TAKE...] ...`: marker layout planning (Principal Feature Analysis and greedy).
int runPfa(const std::vector<std::string>& args);

/// `mocap track IN -o OUT [--template TAKE_OR_MARKERSET] [--max-speed MM_PER_FRAME] [--json]`:
/// unlabelled points into labelled trajectories.
int runTrack(const std::vector<std::string>& args);

/// `mocap fix-swaps IN -o OUT [--report FILE.json]`: finds and repairs label swaps.
int runFixSwaps(const std::vector<std::string>& args);

/// `mocap eval-track TAKE [--seed S] [--json]`: label recovery and swap detection on a labelled take.
int runEvalTrack(const std::vector<std::string>& args);

/// `mocap deform --mesh FACE.obj --binding BIND.json --take TAKE ... -o OUT.pc2|OUTDIR`: RBF or
/// Laplacian face-mesh deformation driven by the take's markers.
int runDeform(const std::vector<std::string>& args);

/// `mocap bind --mesh FACE.obj --take TAKE [--pairs LABEL=VERTEX,...] -o BIND.json`: binds markers
/// to mesh points (similarity alignment of the neutral frame, nearest surface points).
int runBind(const std::vector<std::string>& args);

} // namespace mocap::cli

// `mocap`: the batch command line over mocap::core. Each command lives in its own file; this
// file only dispatches and maps errors to exit codes (1 bad input, 2 bad usage).
#include "cli_error.h"
#include "commands.h"

#include "mocap/base/error.h"

#include <algorithm>
#include <functional>
#include <iostream>
#include <map>

namespace {

constexpr const char* kUsage =
    "usage: mocap <command> [arguments]\n"
    "commands:\n"
    "  info FILE [--json]   markers, frames, rate, units, analog channels, valid fraction and every gap\n"
    "  convert IN OUT [--units mm|cm|m]\n"
    "                       convert between .c3d .trc (read/write) and .csv .bvh (write)\n"
    "  clean IN -o OUT [--spikes paper|robust|off] [--spike-factor F] [--spike-threshold T] [--fill METHOD|off]\n"
    "      [--max-gap-seconds S (0.5) | --max-gap N (frames; 0 = unlimited)] [--extrapolate] [--min-valid F (0.2)]\n"
    "      [--neighbours N] [--smooth bspline|butterworth|gcvspl|savgol|off] [--order K]\n"
    "      [--knot-spacing N] [--cutoff HZ] [--stabilize LABEL,...] [--keep-stabilized] [--report FILE.json]\n"
    "                       stabilize, remove spikes, fill gaps, smooth; write OUT and a JSON report\n"
    "  eval-fill TAKE [--lengths 10,30,60,120,240] [--copies N] [--seed S] [--methods a,b,...] [--json]\n"
    "                       gap-filling methods against hidden truth (Gloersen & Federolf protocol)\n"
    "  eval-spikes TAKE [--count N] [--amplitude MM] [--seed S] [--factor F] [--threshold T] [--passes N] [--json]\n"
    "                       inject spikes, report recall and false alarms per detector\n"
    "  eval-smooth TAKE [--noise MM] [--seed S] [--json]\n"
    "                       add noise, report position and acceleration RMSE per smoother\n"
    "  smooth-table TAKE [--markers A,B,...] [--json]\n"
    "                       the paper's Table 1: smoothness per B-spline order\n"
    "  pfa TAKE [TAKE...] [--method pfa|greedy] [--variance 0.98] [--restarts 1000] [--k MIN:MAX]\n"
    "      [--seed S] [--pairs FILE] [--stabilize LABELS] [--keyposes auto|F1,F2,...] [--json]\n"
    "      [--curve OUT.csv] [--export-subset K OUT.c3d] [--markers PATTERNS] [--exclude PATTERNS]\n"
    "      [--random N] [--threads N] [--progress]\n"
    "                       marker layout planning: error vs marker count, recommended size\n"
    "  track IN -o OUT [--template TAKE_OR_MARKERSET] [--max-speed MM_PER_FRAME] [--keep-fragments]\n"
    "      [--rate HZ] [--save-marker-set FILE.json] [--json]\n"
    "                       unlabelled points (C3D/TRC fragments or CSV frame,x,y,z) into labelled trajectories\n"
    "  fix-swaps IN -o OUT [--report FILE.json] [--jump-factor F] [--json]\n"
    "                       find and repair frames where two labels exchange\n"
    "  eval-track TAKE [--seed S] [--fragment-length N] [--cut-gap N] [--swaps N] [--keep-fragments] [--json]\n"
    "                       label recovery of a fragmented unlabelled copy; injected swaps found\n"
    "  bind --mesh FACE.obj --take TAKE [--pairs LABEL=VERTEX,...] [--neutral FRAME] [--stabilize LABELS]\n"
    "      [--markers LABELS] [--vertices FIRST:LAST] -o BIND.json [--json]\n"
    "                       bind markers to mesh points; per-marker residuals\n"
    "  deform --mesh FACE.obj --binding BIND.json --take TAKE [--neutral FRAME] [--method rbf|laplacian]\n"
    "      [--kernel exp|gaussian|biharmonic|thin-plate] [--radius C] [--regions] [--no-affine] [--up x|y|z]\n"
    "      [--weights uniform|cotangent|mean-value] [--constraint-weight W] [--rotations N] [--stabilize LABELS]\n"
    "      [--scale uniform|per-axis] [--frames FIRST:LAST] [--leave-out FRACTION] [--seed S] [--ply]\n"
    "      -o OUT.pc2|OUTDIR [--json]\n"
    "                       deform a face mesh by the take; PC2 cache or one mesh per frame\n";

/// The lines of kUsage about `command`: its synopsis, continuation and description lines (a
/// command's block starts with two spaces and its name and runs to the next such line).
std::string commandUsage(const std::string& command)
{
  std::string block;
  bool inside = false;
  const std::string text = kUsage;
  for (std::size_t begin = 0; begin < text.size();) {
    const std::size_t end = std::min(text.find('\n', begin), text.size());
    const std::string line = text.substr(begin, end - begin);
    begin = end + 1;
    const bool starts = line.size() > 2 && line.compare(0, 2, "  ") == 0 && line[2] != ' ';
    if (starts)
      inside = line.compare(2, command.size() + 1, command + " ") == 0;
    if (inside)
      block += line + '\n';
  }
  return "usage: mocap " + (block.size() > 2 ? block.substr(2) : command + " [arguments]\n");
}

bool asksForHelp(const std::vector<std::string>& args)
{
  return std::any_of(args.begin(), args.end(), [](const std::string& a) { return a == "--help" || a == "-h"; });
}

} // namespace

int main(int argc, char** argv)
{
  using namespace mocap::cli;
  const std::map<std::string, std::function<int(const std::vector<std::string>&)>> commands = {
      {"info", runInfo},
      {"convert", runConvert},
      {"eval-spikes", runEvalSpikes},
      {"eval-smooth", runEvalSmooth},
      {"smooth-table", runSmoothTable},
      {"pfa", runPfa},
      {"eval-fill", runEvalFill},
      {"clean", runClean},
      {"track", runTrack},
      {"fix-swaps", runFixSwaps},
      {"eval-track", runEvalTrack},
      {"deform", runDeform},
      {"bind", runBind},
  };
  const std::vector<std::string> args(argv + std::min(argc, 2), argv + argc);
  const std::string command = argc > 1 ? argv[1] : "";
  if (command == "--help" || command == "-h" || command == "help") {
    std::cout << kUsage;
    return kExitOk;
  }
  const auto it = commands.find(command);
  if (it == commands.end()) {
    std::cerr << "mocap: " << (command.empty() ? "no command given" : "unknown command '" + command + "'") << '\n'
              << kUsage;
    return kExitBadUsage;
  }
  if (asksForHelp(args)) {
    std::cout << commandUsage(command);
    return kExitOk;
  }
  try {
    return it->second(args);
  } catch (const UsageError& e) {
    std::cerr << "mocap " << command << ": " << e.what() << '\n' << commandUsage(command);
    return kExitBadUsage;
  } catch (const mocap::InvalidArgument& e) {
    std::cerr << e.what() << '\n';
    return kExitBadUsage;
  } catch (const mocap::Error& e) {
    std::cerr << e.what() << '\n';
    return kExitBadInput;
  } catch (const std::exception& e) {
    std::cerr << "mocap " << command << ": " << e.what() << '\n';
    return kExitBadInput;
  }
}

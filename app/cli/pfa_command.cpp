// `mocap pfa`: plans a reduced facial marker layout (Wellein et al. 2007) and reports the
// error-vs-marker-count curve of PFA, greedy selection and random sets, also judged on a
// blendshape rig when one is given.
#include "take_input.h"
#include "arguments.h"
#include "cli_error.h"
#include "commands.h"

#include "mocap/base/error.h"
#include "mocap/base/file_io.h"
#include "mocap/base/json_writer.h"
#include "mocap/evaluation/layout_rig_error.h"
#include "mocap/io/rig_io.h"
#include "mocap/layout/layout_planning.h"
#include "mocap/model/marker_edits.h"
#include "mocap/layout/marker_selection.h"
#include "mocap/base/number_text.h"
#include "mocap/io/take_io.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <set>
#include <sstream>

namespace mocap::cli {

namespace {

/// The options of `mocap pfa`; LayoutPlanOptions and JobControl hold the defaults the usage shows.
/// Key-pose frames are numbered as the first take counts them (TAKE:FRAME for another take);
/// PATTERNS are comma-separated globs (`*`, `?`).
struct PfaArguments
{
  std::vector<std::string> takes;
  std::string method = std::string(selectionMethodName(LayoutPlanOptions{}.method));
  LayoutPlanOptions options;
  std::optional<std::string> k, pairs, stabilize, keyposes, curve, markers, exclude;
  std::optional<std::pair<std::string, std::string>> exportSubset;
  /// The rig measure: --rig, --rig-shapes, --binding, --rig-only; method and frames as below.
  std::optional<std::string> rig, rigShapes, binding, rigOnly;
  LayoutRigErrorOptions rigOptions;
  std::string rigMethod = std::string(blendshapeSolveMethodName(LayoutRigErrorOptions{}.solve.method));
  int threads = JobControl{}.threads();
  bool progress = false;
  bool json = false;
};

std::string csvNumber(double value)
{
  std::string text;
  appendNumber(text, value);
  return text;
}

// --k MIN:MAX or K.
std::pair<Eigen::Index, Eigen::Index> parseKRange(const std::string& text)
{
  const auto parse = [&](const std::string& part) {
    std::size_t used = 0;
    long long value = 0;
    try {
      value = std::stoll(part, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != part.size() || value < 1 || value > 1000000)
      throw UsageError("--k needs MIN:MAX or K with whole numbers ≥ 1, not '" + text + "'");
    return static_cast<Eigen::Index>(value);
  };
  const std::size_t colon = text.find(':');
  if (colon == std::string::npos) {
    const Eigen::Index k = parse(text);
    return {k, k};
  }
  const Eigen::Index low = parse(text.substr(0, colon));
  const Eigen::Index high = parse(text.substr(colon + 1));
  if (low > high)
    throw UsageError("--k: MIN must not exceed MAX in '" + text + "'");
  return {low, high};
}

struct Report
{
  std::vector<std::string> inputs;
  const LayoutResult& result;
  const LayoutFrames& frames;
  const LayoutPlan& plan;
  const MarkerSymmetry& symmetry;
  const std::optional<PairDetection>& detection;
  std::string pairSource;
  const PlanRigErrors* rig = nullptr;  ///< the rig measure, when --rig was given

  [[nodiscard]] std::vector<std::string> labelsOf(const std::vector<Eigen::Index>& markers) const
  {
    return result.labelsOf(markers);
  }
};

void writeLayout(JsonWriter& json, const Report& report, const ScoredLayout& layout, bool withFrequencies,
                 const std::optional<RigLayoutError>& rig)
{
  json.beginObject();
  json.key("labels").beginArray();
  for (const std::string& label : report.labelsOf(layout.markers))
    json.value(label);
  json.endArray();
  if (withFrequencies) {
    json.key("k").value(static_cast<std::int64_t>(layout.k));
    json.key("stability").value(layout.stability);
    json.key("pair_frequencies").beginArray();
    std::set<Eigen::Index> units;
    for (const Eigen::Index m : layout.markers)
      units.insert(report.symmetry.unitOf(m));
    for (const Eigen::Index u : units) {
      const auto& unit = report.symmetry.units()[static_cast<std::size_t>(u)];
      json.beginObject();
      json.key("markers").beginArray();
      for (const std::string& label : report.labelsOf(unit))
        json.value(label);
      json.endArray();
      json.key("frequency").value(layout.unitFrequency[static_cast<std::size_t>(u)]);
      json.endObject();
    }
    json.endArray();
  }
  json.key("blendshape_mse").value(layout.blendshapeError);
  json.key("reconstruction_rmse_mm").value(layout.reconstructionRmse);
  json.key("rig_weight_mse").value(rig ? rig->mse : std::nan(""));
  json.endObject();
}

/// The rig measure at `markerCount` for `method`'s layout: none without --rig or such a layout.
std::optional<RigLayoutError> rigErrorOf(const Report& report, Eigen::Index markerCount, SelectionMethod method)
{
  const LayoutSizeRigErrors* entry = report.rig ? report.rig->size(markerCount) : nullptr;
  if (!entry)
    return std::nullopt;
  return method == SelectionMethod::Pfa ? entry->pfa : entry->greedy;
}

double randomRigError(const Report& report, Eigen::Index markerCount)
{
  const LayoutSizeRigErrors* entry = report.rig ? report.rig->size(markerCount) : nullptr;
  return entry ? entry->randomMse : std::nan("");
}

void writeRig(JsonWriter& json, const Report& report, const PfaArguments& arguments)
{
  json.key("rig");
  if (!report.rig) {
    json.null();
    return;
  }
  const PlanRigErrors& rig = *report.rig;
  json.beginObject();
  json.key("path").value(arguments.rig.value_or(""));
  json.key("method").value(arguments.rigMethod);
  json.key("bound_markers").value(static_cast<std::int64_t>(rig.boundMarkers));
  json.key("frames").value(static_cast<std::int64_t>(rig.frames));
  json.key("planned_bound_markers").value(static_cast<std::int64_t>(rig.planned.boundMarkers));
  json.key("planned_rig_weight_mse").value(rig.planned.mse);
  json.key("seconds").value(rig.seconds);
  json.key("cancelled").value(rig.cancelled);
  json.endObject();
}

std::string jsonReport(const Report& report, const PfaArguments& arguments)
{
  const LayoutPlan& plan = report.plan;
  const LayoutFrames& frames = report.frames;
  JsonWriter json;
  json.beginObject();
  json.key("inputs").beginArray();
  for (const std::string& input : report.inputs)
    json.value(input);
  json.endArray();
  json.key("method").value(selectionMethodName(plan.method));
  json.key("markers").beginArray();
  for (const std::string& label : frames.labels)
    json.value(label);
  json.endArray();
  json.key("frames").beginObject();
  json.key("used").value(static_cast<std::int64_t>(frames.frames.rows()));
  json.key("training").value(static_cast<std::int64_t>(frames.training.size()));
  json.key("test").value(static_cast<std::int64_t>(frames.test.size()));
  json.key("dropped").value(static_cast<std::int64_t>(frames.droppedFrames));
  json.key("stabilized").value(frames.stabilized);
  json.endObject();
  json.key("pca").beginObject();
  json.key("components").value(static_cast<std::int64_t>(plan.pcaComponents));
  json.key("explained_variance").value(plan.explainedVariance);
  json.endObject();
  json.key("symmetry").beginObject();
  json.key("source").value(report.pairSource);
  json.key("pairs").beginArray();
  if (report.detection) {
    for (const DetectedPair& pair : report.detection->pairs) {
      json.beginObject();
      json.key("markers")
          .beginArray()
          .value(frames.labels[static_cast<std::size_t>(pair.first)])
          .value(frames.labels[static_cast<std::size_t>(pair.second)])
          .endArray();
      json.key("mismatch_mm").value(pair.mismatch);
      json.key("from_labels").value(pair.fromLabels);
      json.endObject();
    }
  } else {
    for (const auto& [a, b] : report.symmetry.pairs()) {
      json.beginObject();
      json.key("markers")
          .beginArray()
          .value(frames.labels[static_cast<std::size_t>(a)])
          .value(frames.labels[static_cast<std::size_t>(b)])
          .endArray();
      json.endObject();
    }
  }
  json.endArray();
  json.key("single").beginArray();
  for (const auto& unit : report.symmetry.units())
    if (unit.size() == 1)
      json.value(frames.labels[static_cast<std::size_t>(unit[0])]);
  json.endArray();
  json.endObject();
  json.key("key_poses").beginObject();
  const auto frameName = [&](Eigen::Index row) {
    const auto& [take, frame] = frames.origin[static_cast<std::size_t>(row)];
    return std::to_string(take + 1) + ":" + std::to_string(frame);
  };
  json.key("neutral").value(frameName(plan.basis.neutralFrame));
  json.key("frames").beginArray();
  for (const Eigen::Index row : plan.basis.keyFrames)
    json.value(frameName(row));
  json.endArray();
  json.endObject();
  json.key("motion_rms_mm").value(plan.motionRms);
  json.key("sizes").beginArray();
  for (const LayoutSize& entry : plan.sizes) {
    json.beginObject();
    json.key("markers").value(static_cast<std::int64_t>(entry.markerCount));
    if (const ScoredLayout* layout = entry.layout(plan.method)) {
      json.key("selected");
      writeLayout(json, report, *layout, plan.method == SelectionMethod::Pfa,
                  rigErrorOf(report, entry.markerCount, plan.method));
    } else {
      json.key("selected").null();
    }
    json.key("pfa");
    if (entry.pfa)
      writeLayout(json, report, *entry.pfa, true, rigErrorOf(report, entry.markerCount, SelectionMethod::Pfa));
    else
      json.null();
    json.key("greedy");
    if (entry.greedy)
      writeLayout(json, report, *entry.greedy, false, rigErrorOf(report, entry.markerCount, SelectionMethod::Greedy));
    else
      json.null();
    json.key("random").beginObject();
    json.key("count").value(entry.randomCount);
    json.key("blendshape_mse").value(entry.randomCount ? entry.randomBlendshapeError : std::nan(""));
    json.key("reconstruction_rmse_mm")
        .value(entry.randomCount ? entry.randomReconstructionRmse : std::nan(""));
    json.key("rig_weight_mse").value(randomRigError(report, entry.markerCount));
    if (const LayoutSizeRigErrors* rig = report.rig ? report.rig->size(entry.markerCount) : nullptr)
      json.key("rig_count").value(rig->randomCount);
    json.endObject();
    json.endObject();
  }
  json.endArray();
  json.key("recommended").beginObject();
  json.key("markers").value(static_cast<std::int64_t>(plan.recommendedSize));
  json.key("rule").value(plan.recommendationRule);
  json.key("labels").beginArray();
  if (const LayoutSize* entry = plan.size(plan.recommendedSize))
    if (const ScoredLayout* layout = entry->layout(plan.method))
      for (const std::string& label : report.labelsOf(layout->markers))
        json.value(label);
  json.endArray();
  json.endObject();
  writeRig(json, report, arguments);
  json.key("cancelled").value(plan.cancelled);
  json.endObject();
  return json.str() + "\n";
}

// A rig MSE cell: empty where not judged.
std::string rigCsvCell(double mse)
{
  return std::isnan(mse) ? std::string() : csvNumber(mse);
}

// With --rig, three columns more at the end (the columns before keep their places).
std::string curveCsv(const Report& report)
{
  const LayoutPlan& plan = report.plan;
  std::string csv = "markers,pfa_k,pfa_blendshape_mse,pfa_rmse_mm,greedy_blendshape_mse,greedy_rmse_mm,"
                    "random_blendshape_mse,random_rmse_mm";
  csv += report.rig ? ",pfa_rig_weight_mse,greedy_rig_weight_mse,random_rig_weight_mse\n" : "\n";
  for (const LayoutSize& entry : plan.sizes) {
    csv += std::to_string(entry.markerCount) + ",";
    if (entry.pfa)
      csv += std::to_string(entry.pfa->k) + "," + csvNumber(entry.pfa->blendshapeError) + "," +
             csvNumber(entry.pfa->reconstructionRmse) + ",";
    else
      csv += ",,,";
    if (entry.greedy)
      csv +=
          csvNumber(entry.greedy->blendshapeError) + "," + csvNumber(entry.greedy->reconstructionRmse) + ",";
    else
      csv += ",,";
    if (entry.randomCount > 0)
      csv += csvNumber(entry.randomBlendshapeError) + "," + csvNumber(entry.randomReconstructionRmse);
    else
      csv += ",";
    if (report.rig) {
      const auto pfa = rigErrorOf(report, entry.markerCount, SelectionMethod::Pfa);
      const auto greedy = rigErrorOf(report, entry.markerCount, SelectionMethod::Greedy);
      csv += "," + rigCsvCell(pfa ? pfa->mse : std::nan("")) + "," + rigCsvCell(greedy ? greedy->mse : std::nan("")) +
             "," + rigCsvCell(randomRigError(report, entry.markerCount));
    }
    csv += "\n";
  }
  return csv;
}

void printText(const Report& report)
{
  const LayoutPlan& plan = report.plan;
  const LayoutFrames& frames = report.frames;
  std::ostringstream out;
  out << frames.markerCount() << " markers, " << frames.frames.rows() << " frames (" << frames.training.size()
      << " training, " << frames.test.size() << " test, " << frames.droppedFrames
      << " dropped for a missing marker)" << (frames.stabilized ? ", head motion removed" : "") << "\n";
  if (plan.pcaComponents > 0)
    out << "PCA: " << plan.pcaComponents << " components explain "
        << fixedNumber(100.0 * plan.explainedVariance, 2) << " % of the variance\n";
  out << "symmetry (" << report.pairSource << "): " << report.symmetry.pairs().size() << " pairs";
  if (report.detection) {
    out << "\n";
    for (const DetectedPair& pair : report.detection->pairs)
      out << "  " << frames.labels[static_cast<std::size_t>(pair.first)] << " <-> "
          << frames.labels[static_cast<std::size_t>(pair.second)] << "  mismatch " << fixedNumber(pair.mismatch, 1)
          << " mm" << (pair.fromLabels ? " (labels)" : "") << "\n";
    out << "  midline:";
    for (const Eigen::Index m : report.detection->midline)
      out << " " << frames.labels[static_cast<std::size_t>(m)];
    out << "\n  unpaired:";
    for (const Eigen::Index m : report.detection->unpaired)
      out << " " << frames.labels[static_cast<std::size_t>(m)];
  }
  out << "\nkey poses: " << plan.basis.keyPoseCount()
      << " (blendshape basis from the full set); test motion RMS " << fixedNumber(plan.motionRms, 2) << " mm\n\n";
  // With --rig each group gains a rig-MSE column; without, the table is as it always was.
  const char* rigHeading = report.rig ? "  rig-MSE" : "";
  out << "markers   k | PFA blend-MSE  RMSE mm" << rigHeading << " | greedy blend-MSE  RMSE mm" << rigHeading
      << " | random(mean) blend-MSE  RMSE mm" << rigHeading << "\n";
  const auto rigCell = [&](double mse) {
    if (!report.rig)
      return std::string();
    const std::string text = std::isnan(mse) ? "-" : fixedNumber(mse, 5);
    return std::string(text.size() < 9 ? 9 - text.size() : 1, ' ') + text;
  };
  for (const LayoutSize& entry : plan.sizes) {
    char line[320];
    const auto cell = [](const std::optional<ScoredLayout>& layout, bool mse) {
      return layout ? fixedNumber(mse ? layout->blendshapeError : layout->reconstructionRmse, mse ? 5 : 3)
                    : std::string("-");
    };
    const auto rigOf = [&](SelectionMethod method) {
      const auto error = rigErrorOf(report, entry.markerCount, method);
      return rigCell(error ? error->mse : std::nan(""));
    };
    std::snprintf(line, sizeof line, "%7lld %3s | %13s %8s%s | %16s %8s%s | %22s %8s%s%s\n",
                  static_cast<long long>(entry.markerCount),
                  entry.pfa ? std::to_string(entry.pfa->k).c_str() : "-", cell(entry.pfa, true).c_str(),
                  cell(entry.pfa, false).c_str(), rigOf(SelectionMethod::Pfa).c_str(),
                  cell(entry.greedy, true).c_str(), cell(entry.greedy, false).c_str(),
                  rigOf(SelectionMethod::Greedy).c_str(),
                  entry.randomCount ? fixedNumber(entry.randomBlendshapeError, 5).c_str() : "-",
                  entry.randomCount ? fixedNumber(entry.randomReconstructionRmse, 3).c_str() : "-",
                  rigCell(randomRigError(report, entry.markerCount)).c_str(),
                  entry.markerCount == plan.recommendedSize ? "  <- recommended" : "");
    out << line;
  }
  // The paper's claim (half the markers, about the same quality), read off the curve.
  const double half = 0.5 * static_cast<double>(frames.markerCount());
  for (const SelectionMethod method : {SelectionMethod::Pfa, SelectionMethod::Greedy}) {
    const LayoutSize* nearest = nullptr;
    for (const LayoutSize& entry : plan.sizes)
      if (entry.layout(method) &&
          (!nearest || std::abs(static_cast<double>(entry.markerCount) - half) <
                           std::abs(static_cast<double>(nearest->markerCount) - half)))
        nearest = &entry;
    if (!nearest)
      continue;
    const ScoredLayout& layout = *nearest->layout(method);
    out << "\nat about half the markers (" << nearest->markerCount << " of " << frames.markerCount() << "), "
        << selectionMethodName(method) << ": blendshape weights off by "
        << fixedNumber(std::sqrt(layout.blendshapeError), 3) << " RMS, markers reconstructed to "
        << fixedNumber(layout.reconstructionRmse, 2) << " mm RMS ("
        << fixedNumber(100.0 * layout.reconstructionRmse / plan.motionRms, 1) << " % of the motion RMS)";
    if (nearest->randomCount > 0)
      out << "; random: " << fixedNumber(std::sqrt(nearest->randomBlendshapeError), 3) << " and "
          << fixedNumber(nearest->randomReconstructionRmse, 2) << " mm";
    const auto rig = rigErrorOf(report, nearest->markerCount, method);
    if (rig && rig->judged())
      out << "\n  on the rig: weights off by " << fixedNumber(std::sqrt(rig->mse), 3) << " RMS against the full set's"
          << (std::isnan(randomRigError(report, nearest->markerCount))
                  ? std::string()
                  : "; random: " + fixedNumber(std::sqrt(randomRigError(report, nearest->markerCount)), 3));
  }
  if (report.rig)
    out << "\nrig: " << report.rig->boundMarkers << " bound markers, " << report.rig->frames
        << " frames solved, all planned markers " << fixedNumber(report.rig->planned.mse, 5) << " MSE, "
        << fixedNumber(report.rig->seconds, 2) << " s" << (report.rig->cancelled ? " (cancelled)" : "");
  out << "\n";
  out << "\nrecommended: " << plan.recommendedSize << " of " << frames.markerCount() << " markers ("
      << plan.recommendationRule << ")\n";
  if (const LayoutSize* entry = plan.size(plan.recommendedSize))
    if (const ScoredLayout* layout = entry->layout(plan.method)) {
      out << " ";
      for (const std::string& label : report.labelsOf(layout->markers))
        out << " " << label;
      out << "\n";
    }
  if (plan.cancelled)
    out << "cancelled: results are incomplete\n";
  std::cout << out.str();
}

// The one core planning (layout_planning.h, as the studio's panel runs it); what the request
// names wrongly (a glob matching nothing, a bad key pose) is a usage error naming the option.
LayoutResult planRequested(const std::vector<Take>& takes, LayoutRequest& request,
                           const std::optional<std::string>& keyposes, const JobControl& control)
{
  try {
    if (keyposes)
      request.keyPoses = parseKeyPoses(*keyposes);
    return planLayout(takes, request, control);
  } catch (const LayoutRequestError& e) {
    using Field = LayoutRequestError::Field;
    const char* option = e.field() == Field::Markers   ? "--markers"
                         : e.field() == Field::Exclude ? "--exclude"
                                                       : "--keyposes";
    throw UsageError(std::string(option) + ": " + e.what());
  }
}

/// The rig options go with --rig, and --rig with --binding.
void checkRigOptions(const PfaArguments& arguments, const std::vector<CLI::Option*>& rigOptions)
{
  if (arguments.rig && !arguments.binding)
    throw UsageError("--rig needs --binding BIND.json: the take's markers bound to the rig's neutral");
  if (!arguments.rig)
    for (const CLI::Option* option : rigOptions)
      if (option->count() > 0)
        throw UsageError(option->get_name() + " needs --rig");
}

/// The rig and binding of --rig, read before any planning so a wrong path costs nothing.
struct RigInput
{
  BlendshapeRig rig;
  MeshBinding binding;
};

std::optional<RigInput> readRigInput(const PfaArguments& arguments)
{
  if (!arguments.rig)
    return std::nullopt;
  const std::vector<std::string> only =
      arguments.rigOnly ? splitList(*arguments.rigOnly, "--rig-only") : std::vector<std::string>{};
  RigInput input;
  input.rig = readRig(*arguments.rig, arguments.rigShapes.value_or(""), only);
  input.binding = readBinding(*arguments.binding, input.rig.neutral.vertexCount());
  return input;
}

/// Prints "\rNAME: P %" on stderr, ending the line at 100 %.
std::function<void(double)> progressLine(const char* name)
{
  return [name](double fraction) {
    std::cerr << '\r' << name << ": " << static_cast<int>(std::lround(100.0 * fraction)) << " %" << std::flush;
    if (fraction >= 1.0)
      std::cerr << '\n';
  };
}

int runPfa(const PfaArguments& arguments)
{
  LayoutPlanOptions options = arguments.options;
  options.method = parseSelectionMethod(arguments.method).value();
  if (const auto& k = arguments.k)
    std::tie(options.pfa.minK, options.pfa.maxK) = parseKRange(*k);
  const JobControl control =
      JobControl(arguments.progress ? progressLine("pfa") : JobControl::Progress{}).withThreads(arguments.threads);
  std::optional<Eigen::Index> exportSize;
  const auto& exportRequest = arguments.exportSubset;
  if (exportRequest) {
    const std::string& text = exportRequest->first;
    if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos || text.size() > 9)
      throw UsageError("--export-subset needs a marker count K, not '" + text + "'");
    exportSize = static_cast<Eigen::Index>(std::stol(text));
    (void)formatFromPath(exportRequest->second);
  }

  const std::optional<RigInput> rig = readRigInput(arguments);
  std::vector<Take> takes;
  for (const std::string& input : arguments.takes)
    takes.push_back(readInputTake(input));
  LayoutRequest request;
  if (const auto& labels = arguments.stabilize)
    request.stabilizeLabels = splitList(*labels, "--stabilize");
  if (const auto& patterns = arguments.markers)
    request.markerPatterns = splitList(*patterns, "--markers");
  if (const auto& patterns = arguments.exclude)
    request.excludePatterns = splitList(*patterns, "--exclude");
  if (const auto& pairsFile = arguments.pairs)
    request.pairsFile = *pairsFile;
  request.plan = options;
  const LayoutResult result = planRequested(takes, request, arguments.keyposes, control);
  const LayoutPlan& plan = result.plan;
  const LayoutFrames& frames = result.frames;
  const std::string pairSource = request.pairsFile.empty()
                                     ? "detected on the neutral frame: labels, then mirror matching"
                                     : "file " + request.pairsFile;
  std::optional<PlanRigErrors> rigErrors;
  if (rig && !plan.cancelled) {
    LayoutRigErrorOptions rigOptions = arguments.rigOptions;
    rigOptions.solve.method = parseBlendshapeSolveMethod(arguments.rigMethod).value();
    rigOptions.randomSubsets = options.randomSubsets;
    rigOptions.seed = options.pfa.seed;
    const JobControl rigControl =
        arguments.progress ? JobControl(progressLine("rig")).withThreads(arguments.threads) : control;
    rigErrors = planRigErrors(takes, result, rig->rig, rig->binding, rigOptions, rigControl);
  }
  Report report{arguments.takes, result, frames, plan, result.symmetry, result.detection, pairSource};
  report.rig = rigErrors ? &*rigErrors : nullptr;
  if (arguments.json)
    std::cout << jsonReport(report, arguments);
  else
    printText(report);
  if (const auto& curve = arguments.curve)
    writeFileAtomically(*curve, curveCsv(report));
  if (exportSize) {
    const ScoredLayout* layout = result.layout(*exportSize);
    if (!layout && *exportSize != frames.markerCount()) {
      std::string sizes;
      for (const LayoutSize& e : plan.sizes)
        if (e.layout(plan.method))
          sizes += (sizes.empty() ? "" : ", ") + std::to_string(e.markerCount);
      throw UsageError("--export-subset: the " + std::string(selectionMethodName(plan.method)) +
                       " plan has no " + std::to_string(*exportSize) + "-marker layout (sizes: " + sizes +
                       ")");
    }
    // The planned markers plus the head reference markers a capture with this layout still needs.
    writeTake(subsetTake(takes.front(), result.captureLabels(layout)), exportRequest->second);
  }
  return plan.cancelled ? kExitBadInput : kExitOk;
}

} // namespace

Command addPfa(CLI::App& mocap)
{
  CLI::App* command =
      mocap.add_subcommand("pfa", "marker layout planning: error vs marker count, recommended size");
  const auto a = std::make_shared<PfaArguments>();
  LayoutPlanOptions& options = a->options;
  command->add_option("TAKE", a->takes, "the takes planned on, all with the same markers")
      ->required()
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  oneOf(command->add_option("--method", a->method, "how markers are chosen"), selectionMethodNames())
      ->capture_default_str();
  numberIn(command->add_option("--variance", options.pfa.varianceFraction, "variance the PCA components explain")
               ->type_name(numberText(options.pfa.varianceFraction)),
           1e-6, 1.0);
  wholeNumberIn(command->add_option("--restarts", options.pfa.restarts, "k-means restarts")
                    ->type_name(std::to_string(options.pfa.restarts)),
                1, 1000000);
  command->add_option("--k", a->k, "the PCA components tried: MIN:MAX or K")->type_name("MIN:MAX");
  wholeNumberIn(command->add_option("--seed", options.pfa.seed, "random seed")->type_name("S"), 0,
                std::numeric_limits<long long>::max())
      ->capture_default_str();
  command->add_option("--pairs", a->pairs, "left/right marker pairs: a marker-set JSON file (default: detected)")
      ->type_name("FILE");
  command->add_option("--stabilize", a->stabilize, "head-mounted markers whose motion is removed first")
      ->type_name("LABELS");
  command->add_option("--keyposes", a->keyposes, "the blendshape key poses: frame numbers or TAKE:FRAME")
      ->type_name("auto|F1,F2,...");
  command->add_flag("--json", a->json, "print JSON");
  command->add_option("--curve", a->curve, "write the error curve as CSV")->type_name("OUT.csv");
  command->add_option("--export-subset", a->exportSubset, "write the take with only the K-marker layout")
      ->type_name("K OUT.c3d");
  command->add_option("--markers", a->markers, "the markers planned (default: all but --stabilize)")
      ->type_name("PATTERNS");
  command->add_option("--exclude", a->exclude, "markers left out of the plan")->type_name("PATTERNS");
  wholeNumberIn(command->add_option("--random", options.randomSubsets, "random layouts scored per size")
                    ->type_name("N"),
                0, 100000)
      ->capture_default_str();
  wholeNumberIn(command->add_option("--threads", a->threads, "worker threads (default: one per core)")
                    ->type_name("N"),
                1, 256);
  command->add_flag("--progress", a->progress, "show the progress on stderr");
  // The rig measure: layouts judged by the weights solved on a blendshape rig (mocap solve's).
  command->add_option("--rig", a->rig, "also judge each layout on this blendshape rig (.obj, .ply with --rig-shapes; .glb)")
      ->type_name("RIG");
  const std::vector<CLI::Option*> rigOptions{
      command->add_option("--rig-shapes", a->rigShapes, "the rig's shapes: a folder with one OBJ per shape")
          ->type_name("DIR"),
      command->add_option("--binding", a->binding, "the markers bound to the rig's neutral (mocap bind)")
          ->type_name("BIND.json"),
      oneOf(command->add_option("--rig-method", a->rigMethod, "how the rig's weights are solved"),
            blendshapeSolveMethodNames())
          ->capture_default_str(),
      wholeNumberIn(command->add_option("--rig-frames", a->rigOptions.maxFrames,
                                        "at most N evenly spaced frames per take solved on the rig (0: all)")
                        ->type_name("N"),
                    0, 100000000)
          ->capture_default_str(),
      command->add_option("--rig-only", a->rigOnly, "judge on only these shapes of the rig")->type_name("NAME,...")};
  return {command, [a, rigOptions] {
            checkRigOptions(*a, rigOptions);
            return runPfa(*a);
          }};
}

} // namespace mocap::cli

#include "mocap/cleaning/fill/gap_fill.h"

#include "mocap/base/enum_table.h"
#include "mocap/cleaning/fill/auto_fill.h"
#include "mocap/base/error.h"
#include "mocap/cleaning/fill/fill_context.h"
#include "mocap/cleaning/fill/interpolation_fill.h"
#include "mocap/cleaning/fill/neighbour_propagation.h"
#include "mocap/base/number_text.h"
#include "mocap/cleaning/fill/pca_fill.h"
#include "mocap/cleaning/fill/rigid_fill.h"
#include "mocap/model/marker_edits.h"
#include "mocap/model/marker_points.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>

namespace mocap {

namespace {

constexpr EnumTable<FillMethod, 9> kNames{{{
    {FillMethod::Linear, "linear"},
    {FillMethod::Spline, "spline"},
    {FillMethod::Guenter, "guenter"},
    {FillMethod::LinOuhyoung, "lin-ouhyoung"},
    {FillMethod::Zhang3, "zhang3"},
    {FillMethod::ZhangN, "zhang-n"},
    {FillMethod::Rigid, "rigid"},
    {FillMethod::Pca, "pca"},
    {FillMethod::Auto, "auto"},
}}};

constexpr EnumTable<UnfilledCause, 7> kCauses{{{
    {UnfilledCause::None, ""},
    {UnfilledCause::NeverValid, "never_valid"},
    {UnfilledCause::RarelyValid, "rarely_valid"},
    {UnfilledCause::TooLong, "too_long"},
    {UnfilledCause::EdgeGap, "edge_gap"},
    {UnfilledCause::Method, "method"},
    {UnfilledCause::ModelOutput, "model_output"},
}}};

void checkFillOptions(const FillOptions& options)
{
  if (!parseFillMethod(fillMethodName(options.method)))
    throw InvalidArgument("unknown gap-filling method");
  if (options.maxGap < 0)
    throw InvalidArgument("the longest gap to fill must be 0 (unlimited) or positive, got " +
                          std::to_string(options.maxGap));
  if (options.neighbours < 1 || options.neighbours > 1000)
    throw InvalidArgument("the number of neighbours must be in 1..1000, got " +
                          std::to_string(options.neighbours));
  if (!(std::isfinite(options.maxGapSeconds) && options.maxGapSeconds >= 0.0))
    throw InvalidArgument("the longest gap to fill in seconds must be 0 (unlimited) or positive, got " +
                          std::to_string(options.maxGapSeconds));
  if (!(options.minValidFraction >= 0.0 && options.minValidFraction <= 1.0))
    throw InvalidArgument("the smallest valid fraction of a marker to fill must be in [0, 1], got " +
                          std::to_string(options.minValidFraction));
}

// A number as people write it: 0.5, 20, 12.5 (the shortest text that reads back).
std::string shortNumber(double value)
{
  std::string text;
  appendNumber(text, value);
  return text;
}

// Per marker: may its gaps be filled at all? Empty reason: yes. O(#frames · #markers).
std::vector<std::pair<UnfilledCause, std::string>> markerVerdicts(const Take& take, const FillOptions& options)
{
  std::vector<std::pair<UnfilledCause, std::string>> verdicts(static_cast<std::size_t>(take.markerCount()));
  const auto frames = static_cast<double>(std::max<Eigen::Index>(take.frameCount(), 1));
  for (Eigen::Index m = 0; m < take.markerCount(); ++m) {
    const Eigen::Index valid = take.valid().col(m).count();
    auto& verdict = verdicts[static_cast<std::size_t>(m)];
    const bool named =
        std::find(options.fillAnyway.begin(), options.fillAnyway.end(), m) != options.fillAnyway.end();
    if (valid == 0) {
      verdict = {UnfilledCause::NeverValid, "the marker has no valid sample"};
    } else if (!named && static_cast<double>(valid) < options.minValidFraction * frames) {
      const double percent = std::round(1000.0 * static_cast<double>(valid) / frames) / 10.0;
      verdict = {UnfilledCause::RarelyValid,
                 "marker valid in only " + shortNumber(percent) +
                     " % of the take (under the " + shortNumber(100.0 * options.minValidFraction) +
                     " % needed to fill it)"};
    }
  }
  return verdicts;
}

void checkFinite(const Take& take)
{
  const auto valid = take.valid();
  for (Eigen::Index m = 0; m < take.markerCount(); ++m) {
    const auto trajectory = take.trajectory(m);
    for (Eigen::Index f = 0; f < take.frameCount(); ++f)
      if (valid(f, m) && !trajectory.row(f).allFinite())
        throw InvalidArgument("marker " + take.label(m) + " frame " + std::to_string(f) +
                              ": a valid sample is not finite");
  }
}

void checkGap(const Take& take, const Gap& gap)
{
  if (gap.marker < 0 || gap.marker >= take.markerCount() || gap.length < 1 || gap.firstFrame < 0 ||
      gap.firstFrame > take.frameCount() - gap.length)
    throw InvalidArgument("a gap to fill does not lie inside the take");
  // GapQuery checks that the gap's samples are invalid.
}

GapPrediction predict(const GapQuery& query, const FillOptions& options, const PcaFillModel* pca,
                      const FillContext* context)
{
  switch (options.method) {
  case FillMethod::Linear: return predictLinear(query);
  case FillMethod::Spline: return predictSpline(query);
  case FillMethod::Guenter:
    return propagateFromNeighbours(query, PropagationRule::Guenter, options.neighbours);
  case FillMethod::LinOuhyoung:
    return propagateFromNeighbours(query, PropagationRule::LinOuhyoung, options.neighbours);
  case FillMethod::Zhang3: return propagateFromNeighbours(query, PropagationRule::Zhang3, options.neighbours);
  case FillMethod::ZhangN: return propagateFromNeighbours(query, PropagationRule::ZhangN, options.neighbours);
  case FillMethod::Rigid: return predictRigid(query, options.neighbours);
  case FillMethod::Pca: return pca->predict(query);
  case FillMethod::Auto: return predictAuto(query, AutoFillOptions{options.neighbours, context});
  }
  return GapPrediction::failure("unknown method");
}

// A take with model outputs is filled on a copy of its marker points, so no output serves as a
// neighbour, and the results are mapped back in the order of `gaps`; a gap of an output stays
// open. `gaps` and options are checked. O(#frames · #markers) more than filling the copy.
FillResult fillMarkerPoints(const Take& take, const std::vector<Eigen::Index>& markers, const std::vector<Gap>& gaps,
                            const FillOptions& options, const JobControl& job)
{
  std::vector<Eigen::Index> slot(static_cast<std::size_t>(take.markerCount()), -1);
  for (std::size_t j = 0; j < markers.size(); ++j)
    slot[static_cast<std::size_t>(markers[j])] = static_cast<Eigen::Index>(j);
  FillOptions markerOptions = options;
  markerOptions.fillAnyway.clear();
  for (const Eigen::Index m : options.fillAnyway)
    if (slot[static_cast<std::size_t>(m)] >= 0)
      markerOptions.fillAnyway.push_back(slot[static_cast<std::size_t>(m)]);
  std::vector<Gap> markerGaps;
  for (const Gap& gap : gaps)
    if (const Eigen::Index j = slot[static_cast<std::size_t>(gap.marker)]; j >= 0) {
      markerGaps.push_back(gap);
      markerGaps.back().marker = j;
    }
  FillResult filled;
  if (!markerGaps.empty())
    filled = fillGaps(subsetTake(take, markerLabels(take)), markerGaps, markerOptions, job);
  FillResult result;
  for (SamplePatch& patch : filled.patches) {
    patch.marker = markers[static_cast<std::size_t>(patch.marker)];
    result.patches.push_back(std::move(patch));
  }
  auto next = filled.gaps.begin();
  for (const Gap& gap : gaps) {
    GapFillReport report;
    if (slot[static_cast<std::size_t>(gap.marker)] >= 0) {
      report = std::move(*next++);
    } else {
      report.cause = UnfilledCause::ModelOutput;
      report.reason = "a model output (" + std::string(pointTypeName(take.pointType(gap.marker))) +
                      "), not a marker position";
    }
    report.gap = gap;
    result.gaps.push_back(std::move(report));
  }
  return result;
}

} // namespace

const std::vector<FillMethod>& allFillMethods()
{
  static const std::vector<FillMethod> methods = [] {
    std::vector<FillMethod> list;
    for (const auto& entry : kNames.entries)
      list.push_back(entry.value);
    return list;
  }();
  return methods;
}

std::optional<FillMethod> parseFillMethod(std::string_view name)
{
  return kNames.parse(name);
}

std::string_view unfilledCauseName(UnfilledCause cause)
{
  return kCauses.name(cause, "");
}

Eigen::Index longestGapFrames(const FillOptions& options, double frameRate)
{
  if (!(std::isfinite(frameRate) && frameRate > 0.0))
    throw InvalidArgument("the frame rate must be a positive number to turn seconds into frames");
  if (options.maxGap > 0)
    return options.maxGap;
  if (options.maxGapSeconds <= 0.0)
    return 0;
  const double frames = std::round(options.maxGapSeconds * frameRate);
  return std::max<Eigen::Index>(1, frames >= 1e15 ? Eigen::Index{1} << 50 : static_cast<Eigen::Index>(frames));
}

std::string_view fillMethodName(FillMethod method)
{
  return kNames.name(method, "unknown");
}

FillResult fillGaps(const Take& take, const FillOptions& options, const JobControl& job)
{
  checkFillOptions(options);
  return fillGaps(take, findGaps(take), options, job);
}

std::vector<GapFillReport> checkFillRules(const Take& take, const std::vector<Gap>& gaps, const FillOptions& options)
{
  checkFillOptions(options);
  for (const Gap& gap : gaps)
    checkGap(take, gap);
  for (Eigen::Index m : options.fillAnyway)
    if (m < 0 || m >= take.markerCount())
      throw InvalidArgument("a marker to fill anyway (" + std::to_string(m) + ") is not in the take");
  const Eigen::Index longest = gaps.empty() ? 0 : longestGapFrames(options, take.frameRate());
  const auto verdicts = markerVerdicts(take, options);
  std::vector<GapFillReport> reports(gaps.size());
  for (std::size_t i = 0; i < gaps.size(); ++i) {
    GapFillReport& report = reports[i];
    const Gap& gap = gaps[i];
    report.gap = gap;
    const auto& verdict = verdicts[static_cast<std::size_t>(gap.marker)];
    if (!isMarker(take, gap.marker)) {
      report.cause = UnfilledCause::ModelOutput;
      report.reason = "a model output (" + std::string(pointTypeName(take.pointType(gap.marker))) +
                      "), not a marker position";
    } else if (verdict.first != UnfilledCause::None) {
      report.cause = verdict.first;
      report.reason = verdict.second;
    } else if (longest > 0 && gap.length > longest) {
      std::string limit = std::to_string(longest) + " frames";
      if (options.maxGap == 0)
        limit += ", " + shortNumber(options.maxGapSeconds) + " s";
      report.cause = UnfilledCause::TooLong;
      report.reason = "longer than the longest gap to fill (" + limit + ")";
    } else if (gap.atEdge && !options.extrapolate) {
      report.cause = UnfilledCause::EdgeGap;
      report.reason = "edge gap (extrapolation off)";
    }
  }
  return reports;
}

FillResult fillGaps(const Take& take, const std::vector<Gap>& gaps, const FillOptions& options, const JobControl& job)
{
  std::vector<GapFillReport> rules = checkFillRules(take, gaps, options);
  if (const std::vector<Eigen::Index> markers = markerPoints(take);
      static_cast<Eigen::Index>(markers.size()) != take.markerCount())
    return fillMarkerPoints(take, markers, gaps, options, job);
  checkFinite(take);
  FillResult result;
  std::unique_ptr<PcaFillModel> pca;
  std::unique_ptr<FillContext> context;
  const auto leaveOpen = [&result](GapFillReport& report, UnfilledCause cause, std::string reason) {
    report.cause = cause;
    report.reason = std::move(reason);
    result.gaps.push_back(std::move(report));
  };
  for (std::size_t i = 0; i < gaps.size(); ++i) {
    job.checkpoint(static_cast<double>(i) / static_cast<double>(gaps.size()));
    const Gap& gap = gaps[i];
    const GapQuery query(take, gap.marker, gap.firstFrame, gap.length);  // checks the gap is one
    GapFillReport& report = rules[i];
    if (report.cause != UnfilledCause::None) {
      result.gaps.push_back(std::move(report));
      continue;
    }
    if (options.method == FillMethod::Pca && !pca)
      pca = std::make_unique<PcaFillModel>(take);
    if (options.method == FillMethod::Auto && !context)
      context = std::make_unique<FillContext>(take);
    GapPrediction prediction = predict(query, options, pca.get(), context.get());
    if (prediction.filled() && !prediction.positions.allFinite())
      prediction = GapPrediction::failure(std::string(fillMethodName(options.method)) +
                                          " gave positions that are not finite");
    if (!prediction.filled()) {
      leaveOpen(report, UnfilledCause::Method, std::move(prediction.reason));
      continue;
    }
    std::vector<Eigen::Index> frames(static_cast<std::size_t>(gap.length));
    for (Eigen::Index k = 0; k < gap.length; ++k)
      frames[static_cast<std::size_t>(k)] = gap.firstFrame + k;
    result.patches.push_back(
        makePatch(gap.marker, std::move(frames), std::move(prediction.positions), SampleOrigin::Filled));
    report.filled = true;
    report.method = std::move(prediction.method);
    result.gaps.push_back(std::move(report));
  }
  return result;
}

} // namespace mocap

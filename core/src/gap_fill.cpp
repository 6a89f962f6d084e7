#include "mocap/gap_fill.h"

#include "mocap/auto_fill.h"
#include "mocap/error.h"
#include "mocap/fill_context.h"
#include "mocap/interpolation_fill.h"
#include "mocap/neighbour_propagation.h"
#include "mocap/pca_fill.h"
#include "mocap/rigid_fill.h"

#include <array>
#include <memory>

namespace mocap {

namespace {

struct MethodName
{
  FillMethod method;
  std::string_view name;
};

constexpr std::array<MethodName, 9> kNames{{
    {FillMethod::Linear, "linear"},
    {FillMethod::Spline, "spline"},
    {FillMethod::Guenter, "guenter"},
    {FillMethod::LinOuhyoung, "lin-ouhyoung"},
    {FillMethod::Zhang3, "zhang3"},
    {FillMethod::ZhangN, "zhang-n"},
    {FillMethod::Rigid, "rigid"},
    {FillMethod::Pca, "pca"},
    {FillMethod::Auto, "auto"},
}};

void checkOptions(const FillOptions& options)
{
  if (!parseFillMethod(fillMethodName(options.method)))
    throw InvalidArgument("unknown gap-filling method");
  if (options.maxGap < 0)
    throw InvalidArgument("the longest gap to fill must be 0 (unlimited) or positive, got " +
                          std::to_string(options.maxGap));
  if (options.neighbours < 1 || options.neighbours > 1000)
    throw InvalidArgument("the number of neighbours must be in 1..1000, got " +
                          std::to_string(options.neighbours));
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

} // namespace

const std::vector<FillMethod>& allFillMethods()
{
  static const std::vector<FillMethod> methods = [] {
    std::vector<FillMethod> list;
    for (const auto& entry : kNames)
      list.push_back(entry.method);
    return list;
  }();
  return methods;
}

std::optional<FillMethod> parseFillMethod(std::string_view name)
{
  for (const auto& entry : kNames)
    if (entry.name == name)
      return entry.method;
  return std::nullopt;
}

std::string_view fillMethodName(FillMethod method)
{
  for (const auto& entry : kNames)
    if (entry.method == method)
      return entry.name;
  return "unknown";
}

FillResult fillGaps(const Take& take, const FillOptions& options)
{
  checkOptions(options);
  return fillGaps(take, findGaps(take), options);
}

FillResult fillGaps(const Take& take, const std::vector<Gap>& gaps, const FillOptions& options)
{
  checkOptions(options);
  for (const Gap& gap : gaps)
    checkGap(take, gap);
  checkFinite(take);
  FillResult result;
  std::unique_ptr<PcaFillModel> pca;
  std::unique_ptr<FillContext> context;
  for (const Gap& gap : gaps) {
    GapFillReport report;
    report.gap = gap;
    const GapQuery query(take, gap.marker, gap.firstFrame, gap.length);
    if (options.maxGap > 0 && gap.length > options.maxGap) {
      report.reason = "longer than the longest gap to fill (" + std::to_string(options.maxGap) + " frames)";
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
      report.reason = std::move(prediction.reason);
      result.gaps.push_back(std::move(report));
      continue;
    }
    std::vector<Eigen::Index> frames(static_cast<std::size_t>(gap.length));
    for (Eigen::Index i = 0; i < gap.length; ++i)
      frames[static_cast<std::size_t>(i)] = gap.firstFrame + i;
    result.patches.push_back(
        makePatch(gap.marker, std::move(frames), std::move(prediction.positions), SampleState::Filled));
    report.filled = true;
    report.method = std::move(prediction.method);
    result.gaps.push_back(std::move(report));
  }
  return result;
}

} // namespace mocap

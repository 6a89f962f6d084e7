#include "mocap/cleaning/fill/per_gap_fill.h"

#include "mocap/base/error.h"

#include <algorithm>
#include <string>
#include <utility>

namespace mocap {

namespace {

// The options of one group: `method` under the rules of `rules`, or past them.
FillOptions groupOptions(const FillOptions& rules, FillMethod method, bool pastRules)
{
  FillOptions options;
  options.method = method;
  options.maxGap = rules.maxGap;
  options.maxGapSeconds = rules.maxGapSeconds;
  options.extrapolate = rules.extrapolate;
  options.minValidFraction = rules.minValidFraction;
  return pastRules ? withoutFillRules(options) : options;
}

void checkChoices(const std::vector<Gap>& gaps, const std::vector<FillMethod>& methods,
                  const std::vector<bool>& pastRules)
{
  if (methods.size() != gaps.size() || pastRules.size() != gaps.size())
    throw InvalidArgument("per-gap fill: " + std::to_string(gaps.size()) + " gaps but " +
                          std::to_string(methods.size()) + " methods and " + std::to_string(pastRules.size()) +
                          " rule choices");
}

// Fills gaps[where[k]] with `options`, putting each report at result.gaps[where[k]] and the
// patches at the end of result.patches.
void fillGroup(const Take& take, const std::vector<Gap>& gaps, const std::vector<std::size_t>& where,
               const FillOptions& options, const JobControl& part, FillResult& result)
{
  std::vector<Gap> some;
  for (const std::size_t i : where)
    some.push_back(gaps[i]);
  try {
    FillResult filled = fillGaps(take, some, options, part);
    for (std::size_t k = 0; k < where.size() && k < filled.gaps.size(); ++k)
      result.gaps[where[k]] = std::move(filled.gaps[k]);
    for (SamplePatch& patch : filled.patches)
      result.patches.push_back(std::move(patch));
  } catch (const JobCancelled&) {
    throw;
  } catch (const std::exception& e) {  // the group's gaps stay open, saying why
    for (const std::size_t i : where)
      result.gaps[i] = GapFillReport{gaps[i], false, {}, e.what(), UnfilledCause::Method};
  }
}

} // namespace

FillOptions withoutFillRules(FillOptions options)
{
  options.maxGap = 0;
  options.maxGapSeconds = 0.0;
  options.extrapolate = true;
  options.minValidFraction = 0.0;
  return options;
}

bool sameFillRules(const FillOptions& a, const FillOptions& b)
{
  return a.maxGap == b.maxGap && a.maxGapSeconds == b.maxGapSeconds && a.extrapolate == b.extrapolate &&
         a.minValidFraction == b.minValidFraction;
}

FillResult fillEachGap(const Take& take, const std::vector<Gap>& gaps, const std::vector<FillMethod>& methods,
                       const std::vector<bool>& pastRules, const FillOptions& rules, const JobControl& job)
{
  checkChoices(gaps, methods, pastRules);
  FillResult result;
  result.gaps.resize(gaps.size());
  const double share = gaps.empty() ? 0.0 : 1.0 / static_cast<double>(gaps.size());
  std::size_t done = 0;
  for (FillMethod method : allFillMethods())
    for (const bool past : {false, true}) {
      std::vector<std::size_t> where;
      for (std::size_t i = 0; i < gaps.size(); ++i)
        if (methods[i] == method && pastRules[i] == past)
          where.push_back(i);
      if (where.empty())
        continue;
      const JobControl part =
          job.part(static_cast<double>(done) * share, static_cast<double>(done + where.size()) * share);
      done += where.size();
      fillGroup(take, gaps, where, groupOptions(rules, method, past), part, result);
    }
  std::sort(result.patches.begin(), result.patches.end(), [](const SamplePatch& a, const SamplePatch& b) {
    return std::make_pair(a.marker, a.frames.front()) < std::make_pair(b.marker, b.frames.front());
  });
  return result;
}

} // namespace mocap

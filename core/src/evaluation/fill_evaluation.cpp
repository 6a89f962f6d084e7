#include "mocap/evaluation/fill_evaluation.h"

#include "mocap/base/error.h"
#include "mocap/base/random.h"
#include "mocap/cleaning/fill/per_gap_fill.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mocap {

namespace {

void checkFillEvaluationOptions(const Take& take, const FillEvaluationOptions& options)
{
  if (take.empty())
    throw InvalidArgument("fill evaluation: the take is empty");
  if (take.markerCount() < 4)
    throw InvalidArgument("fill evaluation needs at least four markers (at most a quarter may be missing)");
  if (options.copies < 1 || options.copies > 100000)
    throw InvalidArgument("fill evaluation: copies must be in 1..100000");
  if (options.gapLengths.empty() || options.methods.empty())
    throw InvalidArgument("fill evaluation: give at least one gap length and one method");
  for (const Eigen::Index length : options.gapLengths)
    if (length < 1 || length > take.frameCount() - 2)
      throw InvalidArgument("fill evaluation: a gap of " + std::to_string(length) +
                            " frames does not fit inside " + std::to_string(take.frameCount()) +
                            " frames with a valid sample either side");
  if (options.gapsPerCopy < 0 || options.gapsPerCopy > take.markerCount())
    throw InvalidArgument("fill evaluation: gaps per copy must be in 0..#markers");
  if (options.neighbours < 1 || options.neighbours > 1000)
    throw InvalidArgument("fill evaluation: neighbours must be in 1..1000");
}

// A step this many times a marker's usual large step (95th percentile) is a jump: a label swap
// or a glitch, where the "truth" is a tracking error rather than motion.
constexpr double kJumpFactor = 10.0;

// Per marker, the squared step above which a step is a jump (0: no limit known).
std::vector<double> jumpLimits(const Take& take)
{
  std::vector<double> limits(static_cast<std::size_t>(take.markerCount()), 0.0);
  const auto valid = take.valid();
  std::vector<double> steps;
  for (Eigen::Index m = 0; m < take.markerCount(); ++m) {
    const auto trajectory = take.trajectory(m);
    steps.clear();
    for (Eigen::Index f = 1; f < take.frameCount(); ++f)
      if (valid(f, m) && valid(f - 1, m))
        steps.push_back((trajectory.row(f) - trajectory.row(f - 1)).squaredNorm());
    if (steps.size() < 10)
      continue;
    const auto rank = steps.begin() + static_cast<std::ptrdiff_t>(steps.size() * 95 / 100);
    std::nth_element(steps.begin(), rank, steps.end());
    limits[static_cast<std::size_t>(m)] = kJumpFactor * kJumpFactor * *rank;
  }
  return limits;
}

// Whether marker m jumps between consecutive valid samples of frames from `first` to `last`.
bool jumpsWithin(const Take& take, Eigen::Index m, Eigen::Index first, Eigen::Index last, double limit)
{
  if (!(limit > 0.0))
    return false;
  const auto trajectory = take.trajectory(m);
  for (Eigen::Index f = std::max<Eigen::Index>(1, first); f <= std::min(last, take.frameCount() - 1); ++f)
    if (take.isValid(f, m) && take.isValid(f - 1, m) &&
        (trajectory.row(f) - trajectory.row(f - 1)).squaredNorm() > limit)
      return true;
  return false;
}

// Hides gaps of `length` in one copy (possibly fewer than wanted when the take's own gaps leave
// no room): all overlap one random frame, each keeps a valid sample either side, no frame loses
// more than a quarter of the markers (counting the take's own gaps), and with `limits` no hidden
// stretch or its borders jumps.
std::vector<Gap> placeGaps(const Take& take, Eigen::Index length, Eigen::Index wanted, Random& random,
                           const std::vector<double>& limits)
{
  const Eigen::Index frames = take.frameCount();
  const Eigen::Index markers = take.markerCount();
  const Eigen::Index maxMissing = markers / 4;
  const auto valid = take.valid();
  Eigen::ArrayXi missing(frames);
  for (Eigen::Index f = 0; f < frames; ++f)
    missing(f) = static_cast<int>(markers - valid.row(f).count());
  SampleMask hidden = SampleMask::Constant(frames, markers, false);
  std::vector<Gap> gaps;
  const Eigen::Index centre = random.below(frames);
  for (Eigen::Index attempt = 0; attempt < 40 * wanted && static_cast<Eigen::Index>(gaps.size()) < wanted;
       ++attempt) {
    const Eigen::Index marker = random.below(markers);
    const Eigen::Index start =
        std::clamp<Eigen::Index>(centre - random.below(length), 1, frames - 1 - length);
    bool fits = true;
    for (Eigen::Index f = start - 1; f <= start + length && fits; ++f)
      fits = valid(f, marker) && !hidden(f, marker);
    for (Eigen::Index f = start; f < start + length && fits; ++f)
      fits = missing(f) < maxMissing;
    if (!fits || (!limits.empty() && jumpsWithin(take, marker, start - 1, start + length + 1,
                                                 limits[static_cast<std::size_t>(marker)])))
      continue;
    for (Eigen::Index f = start; f < start + length; ++f) {
      hidden(f, marker) = true;
      ++missing(f);
    }
    gaps.push_back({marker, start, length, false});
  }
  return gaps;
}

struct Accumulator
{
  std::vector<double> errors;
  double borderJump = 0.0;
  double trueBorderJump = 0.0;
  Eigen::Index borders = 0;
  Eigen::Index gaps = 0;
  Eigen::Index unfilled = 0;
};

void scoreGap(const Take& truth, const Take& corrupted, const Gap& gap, const SamplePatch& patch, double toMm,
              Accumulator& acc)
{
  const auto real = truth.trajectory(gap.marker);
  const auto seen = corrupted.trajectory(gap.marker);
  for (Eigen::Index i = 0; i < gap.length; ++i)
    acc.errors.push_back(toMm * (patch.positions.row(i) - real.row(gap.firstFrame + i)).norm());
  const double perSecond = toMm * truth.frameRate();
  const Eigen::Index a = gap.firstFrame;
  const Eigen::Index b = gap.firstFrame + gap.length - 1;
  if (a >= 2 && corrupted.isValid(a - 2, gap.marker)) {
    const Eigen::RowVector3d outside = seen.row(a - 1) - seen.row(a - 2);
    acc.borderJump += perSecond * (patch.positions.row(0) - seen.row(a - 1) - outside).norm();
    acc.trueBorderJump += perSecond * (real.row(a) - seen.row(a - 1) - outside).norm();
    ++acc.borders;
  }
  if (b + 2 < truth.frameCount() && corrupted.isValid(b + 2, gap.marker)) {
    const Eigen::RowVector3d outside = seen.row(b + 2) - seen.row(b + 1);
    acc.borderJump += perSecond * (seen.row(b + 1) - patch.positions.row(gap.length - 1) - outside).norm();
    acc.trueBorderJump += perSecond * (seen.row(b + 1) - real.row(b) - outside).norm();
    ++acc.borders;
  }
}

FillScore summarise(FillMethod method, Eigen::Index length, Accumulator& acc)
{
  FillScore score;
  score.method = method;
  score.gapLength = length;
  score.gaps = acc.gaps;
  score.unfilled = acc.unfilled;
  score.samples = static_cast<Eigen::Index>(acc.errors.size());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (acc.errors.empty()) {
    score.meanError = score.rmse = score.p95 = score.max = nan;
    score.borderVelocityJump = score.trueBorderVelocityJump = nan;
    return score;
  }
  double sum = 0.0;
  double squares = 0.0;
  for (const double e : acc.errors) {
    sum += e;
    squares += e * e;
  }
  const auto n = static_cast<double>(acc.errors.size());
  score.meanError = sum / n;
  score.rmse = std::sqrt(squares / n);
  score.max = *std::max_element(acc.errors.begin(), acc.errors.end());
  const auto rank = static_cast<std::size_t>(std::ceil(0.95 * n)) - 1;
  std::nth_element(acc.errors.begin(), acc.errors.begin() + static_cast<std::ptrdiff_t>(rank),
                   acc.errors.end());
  score.p95 = acc.errors[rank];
  score.borderVelocityJump = acc.borders > 0 ? acc.borderJump / static_cast<double>(acc.borders) : nan;
  score.trueBorderVelocityJump =
      acc.borders > 0 ? acc.trueBorderJump / static_cast<double>(acc.borders) : nan;
  return score;
}

} // namespace

namespace {

std::vector<Gap> hiddenGaps(const Take& take, Eigen::Index length, int copy,
                            const FillEvaluationOptions& options, const std::vector<double>& limits)
{
  const Eigen::Index markers = take.markerCount();
  const Eigen::Index wanted =
      std::min(markers / 4, options.gapsPerCopy > 0 ? Eigen::Index{options.gapsPerCopy}
                                                    : std::max<Eigen::Index>(1, markers / 8));
  // One generator per (length, copy): a copy's gaps depend on neither the other lengths nor the methods.
  const std::uint64_t lengthKey = std::uint64_t{0x51ed27f} * static_cast<std::uint64_t>(length);
  const std::uint64_t copyKey = std::uint64_t{0x2545f4914f6cdd1d} * static_cast<std::uint64_t>(copy + 1);
  Random random(options.seed ^ lengthKey ^ copyKey);
  return placeGaps(take, length, wanted, random, limits);
}

} // namespace

std::vector<Gap> evaluationGaps(const Take& take, Eigen::Index length, int copy,
                                const FillEvaluationOptions& options)
{
  checkFillEvaluationOptions(take, options);
  if (length < 1 || length > take.frameCount() - 2)
    throw InvalidArgument("fill evaluation: a gap of " + std::to_string(length) +
                          " frames does not fit inside " + std::to_string(take.frameCount()) +
                          " frames with a valid sample either side");
  if (copy < 0)
    throw InvalidArgument("fill evaluation: copy numbers start at 0");
  return hiddenGaps(take, length, copy, options,
                    options.skipJumps ? jumpLimits(take) : std::vector<double>{});
}

FillEvaluation evaluateFill(const Take& take, const FillEvaluationOptions& options)
{
  checkFillEvaluationOptions(take, options);
  const double toMm = millimetresPer(take.units());
  const std::vector<double> limits = options.skipJumps ? jumpLimits(take) : std::vector<double>{};
  FillEvaluation evaluation;
  evaluation.copies = options.copies;
  evaluation.seed = options.seed;
  for (const Eigen::Index length : options.gapLengths) {
    std::vector<Accumulator> acc(options.methods.size());
    for (int copy = 0; copy < options.copies; ++copy) {
      const auto gaps = hiddenGaps(take, length, copy, options, limits);
      if (gaps.empty())
        continue;
      Take corrupted = take;
      for (const Gap& gap : gaps)
        for (Eigen::Index f = gap.firstFrame; f < gap.firstFrame + gap.length; ++f) {
          corrupted.valid()(f, gap.marker) = false;
          corrupted.residuals()(f, gap.marker) = -1.0;
          corrupted.setPosition(f, gap.marker,
                                Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN()));
        }
      for (std::size_t k = 0; k < options.methods.size(); ++k) {
        // The methods are measured, not the defaults that leave gaps open: every hidden gap is
        // filled whatever its length, place or marker.
        const FillOptions measured = withoutFillRules(FillOptions{options.methods[k], 0, options.neighbours});
        const FillResult result = fillGaps(corrupted, gaps, measured);
        std::size_t patch = 0;
        for (const GapFillReport& report : result.gaps) {
          ++acc[k].gaps;
          if (!report.filled) {
            ++acc[k].unfilled;
            continue;
          }
          scoreGap(take, corrupted, report.gap, result.patches[patch++], toMm, acc[k]);
        }
      }
    }
    for (std::size_t k = 0; k < options.methods.size(); ++k)
      evaluation.scores.push_back(summarise(options.methods[k], length, acc[k]));
  }
  return evaluation;
}

} // namespace mocap

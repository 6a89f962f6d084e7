#include "mocap/math/key_reduction.h"

#include "mocap/base/error.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace mocap {

namespace {

void checkCurve(const Eigen::Ref<const Eigen::VectorXd>& times, const Eigen::Ref<const Eigen::MatrixXd>& values)
{
  if (values.rows() != times.size())
    throw InvalidArgument("key reduction: " + std::to_string(values.rows()) + " samples for " +
                          std::to_string(times.size()) + " times");
  if (!times.allFinite() || !values.allFinite())
    throw InvalidArgument("key reduction: a time or value is not finite");
  for (Eigen::Index i = 1; i < times.size(); ++i)
    if (!(times(i) > times(i - 1)))
      throw InvalidArgument("key reduction: times must increase (sample " + std::to_string(i) + ")");
}

/// Samples that must stay keys: the first, the last, and where a channel's held run (a value
/// repeated) starts or ends.
std::vector<bool> forcedKeys(const Eigen::Ref<const Eigen::MatrixXd>& values)
{
  const Eigen::Index n = values.rows();
  std::vector<bool> forced(static_cast<std::size_t>(n), false);
  if (n == 0)
    return forced;
  forced.front() = forced.back() = true;
  for (Eigen::Index k = 1; k + 1 < n; ++k)
    for (Eigen::Index c = 0; c < values.cols(); ++c) {
      const bool asBefore = values(k, c) == values(k - 1, c);
      const bool asAfter = values(k, c) == values(k + 1, c);
      if (asBefore != asAfter) {
        forced[static_cast<std::size_t>(k)] = true;
        break;
      }
    }
  return forced;
}

/// Walks the keys reachable from key `from` (the line to them stays within `tolerance` of every
/// sample between), nearest first, calling `reached(j)` for each; stops at the first forced key.
/// Each channel's admissible slopes from `from` narrow with every sample passed; once one is
/// empty, no farther key is reachable.
template <typename Reached>
void walkReach(const Eigen::Ref<const Eigen::VectorXd>& times, const Eigen::Ref<const Eigen::MatrixXd>& values,
               double tolerance, const std::vector<bool>& forced, Eigen::Index from, Reached&& reached)
{
  const Eigen::Index channels = values.cols();
  Eigen::ArrayXd low = Eigen::ArrayXd::Constant(channels, -std::numeric_limits<double>::infinity());
  Eigen::ArrayXd high = Eigen::ArrayXd::Constant(channels, std::numeric_limits<double>::infinity());
  const Eigen::ArrayXd start = values.row(from).transpose().array();
  Eigen::ArrayXd rise(channels);
  for (Eigen::Index j = from + 1; j < values.rows(); ++j) {
    const double dt = times(j) - times(from);
    rise = values.row(j).transpose().array() - start;
    if ((rise / dt >= low).all() && (rise / dt <= high).all())
      reached(j);
    if (forced[static_cast<std::size_t>(j)])
      return;
    // Sample j now lies between `from` and any farther key.
    if (tolerance == 0.0) {
      if ((rise != 0.0).any())
        return;
      continue;
    }
    low = low.max((rise - tolerance) / dt);
    high = high.min((rise + tolerance) / dt);
    if ((low > high).any())
      return;
  }
}

} // namespace

KeyReduction reduceKeys(const Eigen::Ref<const Eigen::VectorXd>& times, const Eigen::Ref<const Eigen::MatrixXd>& values,
                        double tolerance)
{
  if (!(tolerance >= 0.0) || !std::isfinite(tolerance))
    throw InvalidArgument("key reduction: the tolerance must be finite and ≥ 0");
  checkCurve(times, values);
  KeyReduction result;
  const Eigen::Index n = values.rows();
  if (n == 0)
    return result;
  // A hair under the tolerance, so rounding in the slopes never lets a sample stray past it.
  const double margin = tolerance * (1.0 - 1e-9);
  const std::vector<bool> forced = forcedKeys(values);
  // Shortest path from the first sample to the last over the reachable steps: keysTo[j] is the
  // fewest keys ending at j, previous[j] the key before j on such a path.
  std::vector<Eigen::Index> keysTo(static_cast<std::size_t>(n), std::numeric_limits<Eigen::Index>::max());
  std::vector<Eigen::Index> previous(static_cast<std::size_t>(n), -1);
  keysTo[0] = 1;
  for (Eigen::Index i = 0; i + 1 < n; ++i) {
    const Eigen::Index here = keysTo[static_cast<std::size_t>(i)];
    if (here == std::numeric_limits<Eigen::Index>::max())
      continue;
    walkReach(times, values, margin, forced, i, [&](Eigen::Index j) {
      auto& best = keysTo[static_cast<std::size_t>(j)];
      if (here + 1 < best) {
        best = here + 1;
        previous[static_cast<std::size_t>(j)] = i;
      }
    });
  }
  for (Eigen::Index k = n - 1; k >= 0; k = previous[static_cast<std::size_t>(k)])
    result.keys.push_back(k);
  std::reverse(result.keys.begin(), result.keys.end());
  result.maxError = keyInterpolationError(times, values, result.keys);
  return result;
}

KeyReduction reduceFrameKeys(const Eigen::Ref<const Eigen::MatrixXd>& values, double tolerance)
{
  const Eigen::Index n = values.rows();
  return reduceKeys(Eigen::VectorXd::LinSpaced(n, 0.0, static_cast<double>(n - 1)), values, tolerance);
}

void KeyCount::add(Eigen::Index samples, Eigen::Index keys, double error)
{
  before += samples;
  after += keys;
  maxError = std::max(maxError, error);
}

Eigen::MatrixXd interpolateKeys(const Eigen::Ref<const Eigen::VectorXd>& times,
                                const Eigen::Ref<const Eigen::MatrixXd>& values, const std::vector<Eigen::Index>& keys)
{
  checkCurve(times, values);
  if (values.rows() == 0)
    return values;
  if (keys.empty() || keys.front() != 0 || keys.back() != values.rows() - 1 ||
      !std::is_sorted(keys.begin(), keys.end()))
    throw InvalidArgument("key reduction: keys must ascend from the first sample to the last");
  Eigen::MatrixXd line = values;
  for (std::size_t s = 0; s + 1 < keys.size(); ++s) {
    const Eigen::Index a = keys[s], b = keys[s + 1];
    const double span = times(b) - times(a);
    for (Eigen::Index k = a + 1; k < b; ++k) {
      const double t = (times(k) - times(a)) / span;
      line.row(k) = (1.0 - t) * values.row(a) + t * values.row(b);
    }
  }
  return line;
}

double keyInterpolationError(const Eigen::Ref<const Eigen::VectorXd>& times,
                             const Eigen::Ref<const Eigen::MatrixXd>& values, const std::vector<Eigen::Index>& keys)
{
  const Eigen::MatrixXd line = interpolateKeys(times, values, keys);
  return values.size() == 0 ? 0.0 : (line - values).cwiseAbs().maxCoeff();
}

} // namespace mocap

#pragma once

#include <Eigen/Core>

#include <vector>

namespace mocap {

/// The keys kept of a sampled curve, and how far their interpolation strays from the samples.
struct KeyReduction
{
  std::vector<Eigen::Index> keys;  // sample indices, ascending; the first and last sample always
  double maxError = 0.0;           // largest |interpolated − sample| over every channel and sample
};

/// Keys over many curves reduced one by one: the samples they had, the keys kept, the largest
/// error of any of them.
struct KeyCount
{
  Eigen::Index before = 0;
  Eigen::Index after = 0;
  double maxError = 0.0;

  /// Counts one curve of `samples` samples reduced to `keys` keys straying up to `error`.
  void add(Eigen::Index samples, Eigen::Index keys, double error);
};

/// The fewest keys, taken from the samples with their values unchanged, whose linear
/// interpolation stays within `tolerance` of every sample of every channel. `values` holds one
/// column per channel and one row per sample at `times` (strictly increasing); all channels share
/// the keys, as a glTF sampler's morph weights or an FBX node's X, Y and Z do.
///
/// Fewest, not merely few: from each key, the slopes that keep every sample after it within the
/// tolerance form an interval per channel that only narrows as the next key moves on, so every
/// key reachable from it is found in one pass that stops when an interval empties, and a
/// shortest path over those reaches picks the fewest keys (Ramer–Douglas–Peucker, the usual
/// method, splits at the farthest sample and keeps more). Held runs (a channel repeating a value)
/// keep their first and last sample as keys, so an animator sees the hold. A zero tolerance keeps
/// every sample except the inside of held runs.
///
/// O(n · r · c) for n samples, c channels and r the longest reach of a key (n² · c at worst, n · c
/// when the curve is noisy against the tolerance). Throws InvalidArgument on a negative or
/// non-finite tolerance, non-finite values, times that do not increase or a size mismatch.
[[nodiscard]] KeyReduction reduceKeys(const Eigen::Ref<const Eigen::VectorXd>& times,
                                      const Eigen::Ref<const Eigen::MatrixXd>& values, double tolerance);

/// reduceKeys of curves sampled once per frame (times 0, 1, 2, …): the key frames all columns of
/// `values` share (glTF's one weights sampler). O(reduceKeys).
[[nodiscard]] KeyReduction reduceFrameKeys(const Eigen::Ref<const Eigen::MatrixXd>& values, double tolerance);

/// The linear interpolation of `keys` (ascending sample indices from the first sample to the
/// last) at every sample: `values` where a key is, the line between the keys around it elsewhere.
/// Throws InvalidArgument as keyInterpolationError. O(n · c).
[[nodiscard]] Eigen::MatrixXd interpolateKeys(const Eigen::Ref<const Eigen::VectorXd>& times,
                                              const Eigen::Ref<const Eigen::MatrixXd>& values,
                                              const std::vector<Eigen::Index>& keys);

/// The largest |linear interpolation of `keys` − sample| over every channel and sample.
/// O(n · c).
[[nodiscard]] double keyInterpolationError(const Eigen::Ref<const Eigen::VectorXd>& times,
                                           const Eigen::Ref<const Eigen::MatrixXd>& values,
                                           const std::vector<Eigen::Index>& keys);

} // namespace mocap

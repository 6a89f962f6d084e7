#pragma once

#include <Eigen/Core>

#include <vector>

namespace mocap {

/// A motion-capture blendshape basis, the analysis model of Curio et al. 2006 used by Wellein et
/// al. 2007 §1: a face is neutral + Σⱼ wⱼ·(keyPoseⱼ − neutral) with 0 ≤ wⱼ ≤ 1. Frames are rows
/// of 3·#markers values (x, y, z of marker 0, then marker 1, …).
struct BlendshapeBasis
{
  Eigen::RowVectorXd neutral;           ///< 1 × 3·#markers
  Eigen::MatrixXd deltas;               ///< 3·#markers × #key poses: key pose j − neutral
  Eigen::Index neutralFrame = -1;       ///< row of the frames the neutral came from
  std::vector<Eigen::Index> keyFrames;  ///< rows the key poses came from

  [[nodiscard]] Eigen::Index keyPoseCount() const { return deltas.cols(); }
};

/// The resting face: among `candidates` (rows of `frames`; all when empty), the frame nearest
/// the per-coordinate median of those frames (a face rests most of the time, so the median is a
/// rest shape without the mean's smear of expressions). O(#frames · #coordinates · log #frames).
/// Throws InvalidArgument for no frames or a candidate out of range.
[[nodiscard]] Eigen::Index findNeutralFrame(const Eigen::Ref<const Eigen::MatrixXd>& frames,
                                            const std::vector<Eigen::Index>& candidates = {});

/// `count` key poses chosen automatically as extreme frames: farthest-point sampling among
/// `candidates` (all rows when empty) of the distance to the neutral frame and every pose chosen
/// so far, so the poses span the captured motion and blend weights stay in [0, 1]. Stops early
/// when every remaining frame coincides with a chosen one. O(#candidates · #coordinates · count).
/// Throws InvalidArgument for count < 1 or a frame out of range.
[[nodiscard]] std::vector<Eigen::Index> chooseKeyPoses(const Eigen::Ref<const Eigen::MatrixXd>& frames,
                                                       Eigen::Index neutralFrame, Eigen::Index count,
                                                       const std::vector<Eigen::Index>& candidates = {});

/// The basis of the given neutral and key-pose rows. O(#coordinates · #key poses).
/// Throws InvalidArgument for no key poses, a row out of range, the neutral among the key poses
/// or a key pose given twice.
[[nodiscard]] BlendshapeBasis buildBlendshapeBasis(const Eigen::Ref<const Eigen::MatrixXd>& frames,
                                                   Eigen::Index neutralFrame,
                                                   const std::vector<Eigen::Index>& keyFrames);

/// Blendshape weights of each of `rows` (all when empty) of `frames` estimated from the
/// coordinates of `markers` only (all when empty): per frame, bounded least squares with
/// 0 ≤ w ≤ 1 (Curio et al. 2006; Wellein et al. 2007 §1 "finding the optimal linear combination of
/// blendshapes with minimal least-square error"), warm-started from the previous frame.
/// Returns #rows × #key poses. O(#rows · #key poses · (3·#markers + steps · #key poses²)).
/// Throws InvalidArgument when the frame width does not match the basis, a marker or row is out
/// of range, or a used coordinate is not finite.
[[nodiscard]] Eigen::MatrixXd solveBlendshapeWeights(const BlendshapeBasis& basis,
                                                     const Eigen::Ref<const Eigen::MatrixXd>& frames,
                                                     const std::vector<Eigen::Index>& markers = {},
                                                     const std::vector<Eigen::Index>& rows = {});

} // namespace mocap

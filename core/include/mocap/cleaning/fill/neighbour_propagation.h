#pragma once

#include "mocap/cleaning/fill/gap_prediction.h"

namespace mocap {

/// How a missing marker's displacement from frame t−1 to t is made of its neighbours'.
enum class PropagationRule
{
  Guenter,      ///< Guenter et al. [2]: the plain average of the n nearest neighbours' displacements
  LinOuhyoung,  ///< Lin & Ouhyoung [1]: displacements weighted by inverse distance, normalised
  Zhang3,       ///< eqs 3-5: the three nearest, ω = [(1 + cos(π d/d_all))/2]⁴, not normalised
  ZhangN,       ///< eqs 6-7: the n nearest, ω = cos((d − R_s)/(R_f − R_s) · π/2.5), normalised
};

/// Eqs 3-4: ωᵢ = [(1 + cos(π dᵢ/d_all))/2]⁴ with d_all = d₁ + d₂ + d₃. When d_all is 0 (all
/// three neighbours on the missing point) every ratio is taken as 1/3. O(1).
[[nodiscard]] Eigen::Vector3d zhang3Weights(const Eigen::Vector3d& distances);

/// Eq 6: ωᵢ = cos((dᵢ − R_s)/(R_f − R_s) · π/2.5) with R_s, R_f the nearest and farthest of the
/// distances; all weights are 1 when R_f = R_s. Normalised by eq 7's Σω, not here. O(n).
[[nodiscard]] Eigen::VectorXd zhangNWeights(const Eigen::VectorXd& distances);

/// Lin & Ouhyoung [1]: ωᵢ = (1/dᵢ) / Σⱼ 1/dⱼ; neighbours at distance 0 share all the weight. O(n).
[[nodiscard]] Eigen::VectorXd linOuhyoungWeights(const Eigen::VectorXd& distances);

/// The paper's recovery loop (§3.2.1), used by `guenter`, `lin-ouhyoung`, `zhang3` and `zhang-n`:
/// starting from the valid sample before the gap, for each missing frame t in order, take the
/// neighbours nearest to the marker's position P_t in frame t−1 (the recovered one inside the gap)
/// among markers valid in both t−1 and t, their displacements Vᵢ from t−1 to t and distances dᵢ,
/// and set P'_t = P_t + Σ ωᵢVᵢ (eq 5; eq 7 divides by Σωᵢ; Guenter's average and Lin & Ouhyoung's
/// weights are normalised too). `neighbours` is n (Zhang3 always uses 3). A gap that starts at
/// frame 0 is recovered the same way backwards in time from the sample after it. Not filled (reason
/// given) when the marker is never valid, or a frame has fewer than 3 (Zhang3) or 1 (the others)
/// usable neighbours. O(length · #markers).
[[nodiscard]] GapPrediction propagateFromNeighbours(const GapQuery& gap, PropagationRule rule,
                                                    int neighbours);

} // namespace mocap

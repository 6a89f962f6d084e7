#pragma once

#include "mocap/cleaning/fill/gap_prediction.h"

namespace mocap {

/// `rigid`: the marker rides on the rigid motion of nearby markers. Takes the max(3, `neighbours`)
/// markers nearest to it at the gap's borders among those valid through the whole gap and at its
/// borders, and for each missing frame t the Kabsch fit T_t (kabsch.h, weights 1/d²) of that
/// cluster from the first border frame to t. The forward estimate is T_t applied to the border
/// sample before the gap; with a border after the gap too, the backward estimate is
/// T_t · T_after⁻¹ applied to the sample after it, and the two are blended linearly in time so the
/// fill meets both border samples. A gap touching the take's edge is extrapolated from its one
/// border. A rigidly moving cluster is reproduced exactly. Not a paper equation (the paper's
/// neighbours act through displacements, eqs 5 and 7). Not filled (reason given) with fewer than
/// three such markers or when the marker is never valid. `step` > 1 returns only the rows of
/// frames first, first + step, … (to score the method cheaply). Throws InvalidArgument for
/// step < 1. O(#markers · length).
[[nodiscard]] GapPrediction predictRigid(const GapQuery& gap, int neighbours, Eigen::Index step = 1);

} // namespace mocap

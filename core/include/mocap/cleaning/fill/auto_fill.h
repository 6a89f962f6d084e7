#pragma once

#include "mocap/cleaning/fill/gap_prediction.h"

namespace mocap {

class FillContext;

struct AutoFillOptions
{
  int neighbours = 6;                    ///< neighbours of the rigid ingredient, 1..1000
  const FillContext* context = nullptr;  ///< shared per-take data (fill_context.h); built per call if null
};

/// `auto`, the default: three predictions that use both ends of the gap, blended by how well each
/// explains the marker's own data next to the gap.
///  - regression (regression_fill.h) of the marker on the 6 and on the 12 markers that moved most
///    like it within 1500 frames of the gap (one system, two ridge weights), valid and free of
///    jumps through the gap;
///  - rigid (rigid_fill.h): the motion of the nearest markers valid through the gap, carried from
///    both borders;
/// each shifted onto the border samples with a smooth ramp (blendBorders), so position and
/// velocity stay continuous. Leave-out validation: gaps as long as the real one are cut from the
/// marker's valid samples just before and just after it (kept out of the regression's training),
/// each ingredient fills them, and the weights are 1/MSE against the hidden samples. Edge gaps
/// use the one side there is. Not a paper equation: it replaces the forward-only recursion of
/// eqs 3-7, whose error grows through a gap, by predictions anchored at both ends; the evaluation
/// (fill_evaluation.h) measures it against them. Not filled (reason given) when no ingredient can
/// fill the gap. Per gap O(#markers · (100 + 3 · length) + T · K² + K³ + length · (K + neighbours)),
/// T = 150 training frames, K = 12; `context` (of gap.take) saves O(#frames · #markers) per call.
[[nodiscard]] GapPrediction predictAuto(const GapQuery& gap, const AutoFillOptions& options = {});

} // namespace mocap

#include "mocap/cleaning/fill/auto_fill.h"

#include "mocap/cleaning/border_blend.h"
#include "mocap/base/error.h"
#include "mocap/cleaning/fill/fill_context.h"
#include "mocap/cleaning/fill/regression_fill.h"
#include "mocap/cleaning/fill/rigid_fill.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>

namespace mocap {

namespace {

// Two regressions from one system: few predictors with a strong ridge (robust where little is
// known), many with a weak one (expressive where the take has much to learn from). Validation
// decides per gap which the take rewards; tuned on the three evaluation takes.
struct ModelChoice
{
  const char* name;
  Eigen::Index predictors;
  double ridge;
};
constexpr std::array<ModelChoice, 2> kModels{{{"regression-6", 6, 1e-1}, {"regression-12", 12, 1e-3}}};
// Rigid validation scores every third frame: the error estimate barely changes, its cost drops.
constexpr Eigen::Index kRigidValidationStep = 3;

// A validation gap cut from the marker's valid run that ends at (side −1) or starts at (side +1)
// the real gap's border sample: as long as the real gap, but keeping a valid sample beyond it.
std::optional<FrameRange> validationGap(const GapQuery& gap, Eigen::Index border, int side)
{
  if (border < 0)
    return std::nullopt;
  Eigen::Index run = 1;
  const Eigen::Index frames = gap.take.frameCount();
  for (Eigen::Index f = border + side; f >= 0 && f < frames && gap.markerValid(f) && run < gap.length + 2;
       f += side)
    ++run;
  const Eigen::Index length = std::min(gap.length, run - 2);
  if (length < 1)
    return std::nullopt;
  const Eigen::Index first = side < 0 ? border - length : border + 1;
  return FrameRange{first, first + length - 1};
}

// Σ‖p − truth‖² over the rows of `p`, row i being frame truth.first + i · step.
double squaredError(const GapQuery& truth, const Eigen::Matrix<double, Eigen::Dynamic, 3>& p,
                    Eigen::Index step = 1)
{
  double sum = 0.0;
  for (Eigen::Index i = 0; i < p.rows(); ++i)
    sum += (p.row(i) - truth.at(truth.first + i * step)).squaredNorm();
  return sum;
}

struct Candidate
{
  const char* name;
  Eigen::Matrix<double, Eigen::Dynamic, 3> positions;  // for the real gap
  double squaredError = 0.0;                           // over the validation samples it scored
  Eigen::Index samples = 0;
};

void addRegressions(const GapQuery& real, const std::vector<GapQuery>& trials, const FillContext& context,
                    std::vector<Candidate>& candidates, std::string& reason)
{
  // One system for predictors valid through the real and the validation gaps; the validation
  // fits leave the validation gaps' frames out, the real fit uses every frame.
  Eigen::Index from = real.before() >= 0 ? real.before() : real.first;
  Eigen::Index to = real.after() >= 0 ? real.after() : real.last();
  std::vector<FrameRange> heldOut;
  for (const GapQuery& trial : trials) {
    from = std::min(from, trial.first - 1);
    to = std::max(to, trial.last() + 1);
    heldOut.emplace_back(trial.first, trial.last());
  }
  RegressionFillOptions options;
  options.neighbours = static_cast<int>(std::max(kModels[0].predictors, kModels[1].predictors));
  RegressionSystem system =
      buildRegression(context, real.marker, real.markerValid, from, to, options, heldOut);
  bool validated = !trials.empty();
  if (!system.usable() && !trials.empty()) {
    // Too few predictors are valid through the validation gaps as well: fit the real gap alone.
    system = buildRegression(context, real.marker, real.markerValid,
                             real.before() >= 0 ? real.before() : real.first,
                             real.after() >= 0 ? real.after() : real.last(), options);
    validated = false;
  }
  if (!system.usable()) {
    reason = system.reason;
    return;
  }
  // Both models use leading predictors of the same ranking: one coordinate track per gap serves both.
  const Eigen::MatrixXd realTrack = predictorTrack(real.take, system.predictors, real.first, real.length);
  std::vector<Eigen::MatrixXd> trialTracks;
  if (validated)
    for (const GapQuery& trial : trials)
      trialTracks.push_back(predictorTrack(trial.take, system.predictors, trial.first, trial.length));
  for (const ModelChoice& model : kModels) {
    const RegressionFit fit = system.solve(model.predictors, model.ridge);
    if (fit.predictors.empty())
      continue;
    Candidate candidate{model.name, blendBorders(real, fit.apply(realTrack)), 0.0, 0};
    const RegressionFit check =
        validated ? system.solve(model.predictors, model.ridge, true) : RegressionFit{};
    if (!check.predictors.empty())
      for (std::size_t t = 0; t < trials.size(); ++t) {
        candidate.squaredError +=
            squaredError(trials[t], blendBorders(trials[t], check.apply(trialTracks[t])));
        candidate.samples += trials[t].length;
      }
    candidates.push_back(std::move(candidate));
  }
}

void addRigid(const GapQuery& real, const std::vector<GapQuery>& trials, int neighbours,
              std::vector<Candidate>& candidates, std::string& reason)
{
  GapPrediction rigid = predictRigid(real, neighbours);
  if (!rigid.filled()) {
    if (reason.empty())
      reason = rigid.reason;
    return;
  }
  Candidate candidate{"rigid", std::move(rigid.positions), 0.0, 0};
  for (const GapQuery& trial : trials) {
    const GapPrediction p = predictRigid(trial, neighbours, kRigidValidationStep);
    if (!p.filled())
      continue;
    candidate.squaredError += squaredError(trial, p.positions, kRigidValidationStep);
    candidate.samples += p.positions.rows();
  }
  candidates.push_back(std::move(candidate));
}

} // namespace

GapPrediction predictAuto(const GapQuery& gap, const AutoFillOptions& options)
{
  if (options.neighbours < 1 || options.neighbours > 1000)
    throw InvalidArgument("auto fill: neighbours must be in 1..1000");
  if (options.context != nullptr && &options.context->take() != &gap.take)
    throw InvalidArgument("auto fill: the context belongs to another take");
  if (gap.before() < 0 && gap.after() < 0)
    return GapPrediction::failure("the marker has no valid sample");
  std::unique_ptr<FillContext> ownContext;
  const FillContext* context = options.context;
  if (context == nullptr) {
    ownContext = std::make_unique<FillContext>(gap.take);
    context = ownContext.get();
  }

  // Validation gaps either side, hidden (in `mask`) from every ingredient's validation run.
  std::vector<FrameRange> cuts;
  for (const auto& [border, side] : {std::pair<Eigen::Index, int>{gap.before(), -1}, {gap.after(), +1}})
    if (const auto cut = validationGap(gap, border, side))
      cuts.push_back(*cut);
  ValidMask mask = gap.markerValid;
  for (const auto& [first, last] : cuts)
    mask.segment(first, last - first + 1).setConstant(false);
  std::vector<GapQuery> trials;
  for (const auto& [first, last] : cuts)
    trials.emplace_back(gap.take, gap.marker, first, last - first + 1, &mask);

  std::vector<Candidate> candidates;
  std::string reason;
  addRegressions(gap, trials, *context, candidates, reason);
  addRigid(gap, trials, options.neighbours, candidates, reason);
  if (candidates.empty())
    return GapPrediction::failure(reason.empty() ? "no ingredient could fill the gap" : reason);

  // Weights 1/MSE on the validation samples; an ingredient that could not be scored gets the
  // worst score of the others (all weigh the same when none could).
  double worst = 0.0;
  for (const Candidate& c : candidates)
    if (c.samples > 0)
      worst = std::max(worst, c.squaredError / static_cast<double>(c.samples));
  std::vector<double> weights;
  double total = 0.0;
  for (const Candidate& c : candidates) {
    const double mse = c.samples > 0 ? c.squaredError / static_cast<double>(c.samples) : worst;
    weights.push_back(1.0 / (mse + 1e-12 * (1.0 + worst)));
    total += weights.back();
  }
  GapPrediction result;
  result.positions.setZero(gap.length, 3);
  result.method = "auto:";
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    const double share = weights[c] / total;
    result.positions += share * candidates[c].positions;
    char text[64];
    std::snprintf(text, sizeof text, "%s %s %.0f%%", c == 0 ? "" : ",", candidates[c].name, 100.0 * share);
    result.method += text;
  }
  return result;
}

} // namespace mocap

#include "mocap/tracking/template_labelling.h"

#include "mocap/base/error.h"
#include "mocap/math/hungarian_assignment.h"
#include "mocap/math/registration.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace mocap {

namespace {

constexpr int kIcpIterations = 40;
constexpr double kIcpInlierFactor = 2.5;
constexpr double kTrimmedFraction = 0.75;
constexpr Eigen::Index kMaxLookback = 2000;  // frames searched for a label's last sample
constexpr double kOverGate = 2.0;            // normalised cost of a pair that may not be assigned

void checkPoints(const Eigen::Ref<const PointSet>& points, const char* what)
{
  if (points.rows() == 0)
    throw InvalidArgument(std::string("template alignment: no ") + what);
  if (!points.allFinite())
    throw InvalidArgument(std::string("template alignment: ") + what + " not finite");
}

double quantile(Eigen::VectorXd values, double fraction)
{
  const auto k = static_cast<Eigen::Index>(fraction * static_cast<double>(values.size() - 1));
  std::nth_element(values.data(), values.data() + k, values.data() + values.size());
  return values(k);
}

double trimmedMean(Eigen::VectorXd values)
{
  std::sort(values.data(), values.data() + values.size());
  const auto keep = std::max<Eigen::Index>(1, static_cast<Eigen::Index>(kTrimmedFraction * static_cast<double>(values.size())));
  return values.head(keep).mean();
}

// ICP options for a template against one frame's points: each data point pulls its closest
// template point (the data may miss markers and hold strays), far pairs trimmed.
IcpOptions templateIcp()
{
  IcpOptions options;
  options.pairing = IcpPairing::EachTarget;
  options.maxIterations = kIcpIterations;
  options.inlierFactor = kIcpInlierFactor;
  options.changeTolerance = 1e-10;
  return options;
}

void checkLabellingInputs(const Take& take, const std::vector<Fragment>& fragments, const MarkerSet& set,
                          const LabellingOptions& options)
{
  validateMarkerSet(set);
  if (take.markerCount() < set.size())
    throw InvalidArgument("labelling: the take has fewer markers than the marker set has labels");
  if (!(options.gateFactor > 0.0 && options.gateFactor <= 2.0))
    throw InvalidArgument("labelling: the gate factor must be in (0, 2]");
  if (options.neighbours < 3 || options.neighbours > 100)
    throw InvalidArgument("labelling: neighbours must be in 3..100");
  if (options.anchorFrame < -1 || options.anchorFrame >= std::max<Eigen::Index>(take.frameCount(), 1))
    throw InvalidArgument("labelling: the anchor frame is out of range");
  for (const Fragment& fragment : fragments) {
    if (fragment.length() == 0 || fragment.first < 0 || fragment.last() >= take.frameCount())
      throw InvalidArgument("labelling: a fragment lies outside the take");
    for (const Eigen::Vector3d& p : fragment.positions)
      if (!p.allFinite())
        throw InvalidArgument("labelling: a fragment position is not finite");
  }
}

class Labeller
{
public:
  Labeller(Take& take, const std::vector<Fragment>& fragments, const MarkerSet& set, const LabellingOptions& options)
      : m_take(take), m_fragments(fragments), m_set(set), m_options(options), m_labels(set.size())
  {
    m_result.labelOf.assign(fragments.size(), -1);
    sortNeighbours();
  }

  LabellingResult run()
  {
    if (m_take.frameCount() == 0 || m_fragments.empty())
      return m_result;
    const Eigen::Index anchor = m_options.anchorFrame >= 0 ? m_options.anchorFrame : busiestFrame();
    m_result.anchorFrame = anchor;
    measureScale(anchor);
    std::vector<Eigen::Index> atAnchor;
    std::vector<Eigen::Index> later;
    std::vector<Eigen::Index> earlier;
    for (std::size_t k = 0; k < m_fragments.size(); ++k) {
      const Fragment& fragment = m_fragments[k];
      auto& group = fragment.first > anchor ? later : fragment.last() < anchor ? earlier : atAnchor;
      group.push_back(static_cast<Eigen::Index>(k));
    }
    labelBatch(anchor, atAnchor, +1);
    sweep(later, +1);
    sweep(earlier, -1);
    return m_result;
  }

private:
  [[nodiscard]] const Fragment& fragment(Eigen::Index k) const { return m_fragments[static_cast<std::size_t>(k)]; }

  void sortNeighbours()
  {
    m_byDistance.resize(static_cast<std::size_t>(m_labels));
    m_gate = Eigen::VectorXd::Zero(m_labels);
    for (Eigen::Index l = 0; l < m_labels; ++l) {
      auto& order = m_byDistance[static_cast<std::size_t>(l)];
      for (Eigen::Index j = 0; j < m_labels; ++j)
        if (j != l)
          order.push_back(j);
      const auto distance = [&](Eigen::Index j) { return (m_set.neutral.row(j) - m_set.neutral.row(l)).squaredNorm(); };
      std::sort(order.begin(), order.end(), [&](Eigen::Index a, Eigen::Index b) { return distance(a) < distance(b); });
      m_gate(l) = order.empty() ? 0.0 : std::sqrt(distance(order.front()));
    }
    // Coincident template points would give a zero gate: use the typical spacing instead.
    const double typical = m_gate.maxCoeff() > 0.0 ? quantile(m_gate, 0.5) : 1.0;
    for (Eigen::Index l = 0; l < m_labels; ++l)
      if (!(m_gate(l) > 0.0))
        m_gate(l) = typical > 0.0 ? typical : 1.0;
  }

  // The frame with the most labelled samples and live fragments.
  Eigen::Index busiestFrame() const
  {
    const Eigen::Index frames = m_take.frameCount();
    std::vector<Eigen::Index> change(static_cast<std::size_t>(frames) + 1, 0);
    for (const Fragment& f : m_fragments) {
      ++change[static_cast<std::size_t>(f.first)];
      --change[static_cast<std::size_t>(f.last()) + 1];
    }
    const auto valid = m_take.valid();
    Eigen::Index best = 0;
    Eigen::Index bestCount = -1;
    Eigen::Index live = 0;
    for (Eigen::Index f = 0; f < frames; ++f) {
      live += change[static_cast<std::size_t>(f)];
      const Eigen::Index count = live + valid.row(f).head(m_labels).count();
      if (count > bestCount) {
        best = f;
        bestCount = count;
      }
    }
    return best;
  }

  std::vector<Eigen::Index> presentLabels(Eigen::Index frame) const
  {
    std::vector<Eigen::Index> present;
    const auto valid = m_take.valid();
    for (Eigen::Index l = 0; l < m_labels; ++l)
      if (valid(frame, l))
        present.push_back(l);
    return present;
  }

  PointSet positionsAt(const std::vector<Eigen::Index>& labels, Eigen::Index frame) const
  {
    PointSet out(static_cast<Eigen::Index>(labels.size()), 3);
    for (std::size_t i = 0; i < labels.size(); ++i)
      out.row(static_cast<Eigen::Index>(i)) = m_take.trajectory(labels[i]).row(frame);
    return out;
  }

  PointSet templateRows(const std::vector<Eigen::Index>& labels) const
  {
    PointSet out(static_cast<Eigen::Index>(labels.size()), 3);
    for (std::size_t i = 0; i < labels.size(); ++i)
      out.row(static_cast<Eigen::Index>(i)) = m_set.neutral.row(labels[i]);
    return out;
  }

  // Every point of the frame: labelled samples and live fragments.
  PointSet allPointsAt(Eigen::Index frame) const
  {
    std::vector<Eigen::Vector3d> points;
    for (const Eigen::Index l : presentLabels(frame))
      points.push_back(m_take.position(frame, l));
    for (const Fragment& f : m_fragments)
      if (f.first <= frame && frame <= f.last())
        points.push_back(f.at(frame));
    PointSet out(static_cast<Eigen::Index>(points.size()), 3);
    for (std::size_t i = 0; i < points.size(); ++i)
      out.row(static_cast<Eigen::Index>(i)) = points[i].transpose();
    return out;
  }

  std::optional<Similarity> globalAlignment(Eigen::Index frame, double* residual = nullptr) const
  {
    const PointSet points = allPointsAt(frame);
    if (points.rows() == 0)
      return std::nullopt;
    return alignTemplate(m_set.neutral, points, residual);
  }

  void measureScale(Eigen::Index anchor)
  {
    const std::vector<Eigen::Index> present = presentLabels(anchor);
    if (present.size() >= 3) {
      m_result.scale = fitSimilarityLoose(templateRows(present), positionsAt(present, anchor)).scale;
    } else if (const auto s = globalAlignment(anchor, &m_result.anchorResidual)) {
      m_result.scale = s->scale;
    }
    if (!(m_result.scale > 0.0) || !std::isfinite(m_result.scale))
      m_result.scale = 1.0;
  }

  // The last frame before `frame` (in the sweep's direction) where `label` has a sample, or −1.
  Eigen::Index lastSample(Eigen::Index label, Eigen::Index frame, int direction) const
  {
    const auto valid = m_take.valid();
    for (Eigen::Index k = 1; k <= kMaxLookback; ++k) {
      const Eigen::Index f = frame - direction * k;
      if (f < 0 || f >= m_take.frameCount())
        return -1;
      if (valid(f, label))
        return f;
    }
    return -1;
  }

  // Up to `neighbours` labels nearest `label` in the template with a sample in both frames.
  std::vector<Eigen::Index> neighboursIn(Eigen::Index label, Eigen::Index frame, Eigen::Index other) const
  {
    std::vector<Eigen::Index> chosen;
    const auto valid = m_take.valid();
    for (const Eigen::Index j : m_byDistance[static_cast<std::size_t>(label)]) {
      if (valid(frame, j) && valid(other, j))
        chosen.push_back(j);
      if (static_cast<Eigen::Index>(chosen.size()) == m_options.neighbours)
        break;
    }
    return chosen;
  }

  std::optional<Eigen::Vector3d> predict(Eigen::Index label, Eigen::Index frame, int direction,
                                         const std::optional<Similarity>& global) const
  {
    if (global)
      return global->apply(m_set.neutral.row(label).transpose());
    const Eigen::Index before = lastSample(label, frame, direction);
    if (before >= 0) {
      const auto near = neighboursIn(label, frame, before);
      if (near.size() >= 3)
        return kabsch(positionsAt(near, before), positionsAt(near, frame)) * m_take.position(before, label);
    }
    const auto near = neighboursIn(label, frame, frame);
    if (near.size() < 3)
      return std::nullopt;
    return fitSimilarityLoose(templateRows(near), positionsAt(near, frame)).apply(m_set.neutral.row(label).transpose());
  }

  bool freeThroughout(Eigen::Index label, const Fragment& f) const
  {
    return !m_take.valid().col(label).segment(f.first, f.length()).any();
  }

  void write(Eigen::Index k, Eigen::Index label)
  {
    const Fragment& f = fragment(k);
    auto trajectory = m_take.trajectory(label);
    auto valid = m_take.valid();
    auto residuals = m_take.residuals();
    for (Eigen::Index frame = f.first; frame <= f.last(); ++frame) {
      trajectory.row(frame) = f.at(frame).transpose();
      valid(frame, label) = true;
      residuals(frame, label) = 0.0;
      m_take.setState(frame, label, SampleOrigin::Measured);
    }
    m_result.labelOf[static_cast<std::size_t>(k)] = label;
  }

  void labelBatch(Eigen::Index frame, const std::vector<Eigen::Index>& batch, int direction)
  {
    if (batch.empty())
      return;
    const std::vector<Eigen::Index> present = presentLabels(frame);
    std::vector<Eigen::Index> free;
    for (Eigen::Index l = 0; l < m_labels; ++l)
      if (!m_take.isValid(frame, l))
        free.push_back(l);
    if (free.empty())
      return;
    const std::optional<Similarity> global = present.size() < 3 ? globalAlignment(frame) : std::nullopt;
    Eigen::MatrixXd cost = Eigen::MatrixXd::Constant(static_cast<Eigen::Index>(batch.size()),
                                                     static_cast<Eigen::Index>(free.size()), kOverGate);
    for (std::size_t c = 0; c < free.size(); ++c) {
      const Eigen::Index label = free[c];
      const auto predicted = predict(label, frame, direction, global);
      if (!predicted || !predicted->allFinite())
        continue;
      const double gate = m_options.gateFactor * m_gate(label) * m_result.scale;
      for (std::size_t r = 0; r < batch.size(); ++r) {
        const Fragment& f = fragment(batch[r]);
        const double normalised = (f.at(frame) - *predicted).squaredNorm() / (gate * gate);
        if (normalised <= 1.0 && freeThroughout(label, f))
          cost(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)) = normalised;
      }
    }
    const std::vector<Eigen::Index> column = assignMinimumCost(cost, 1.0);
    for (std::size_t r = 0; r < batch.size(); ++r)
      if (column[r] != kUnassigned)
        write(batch[r], free[static_cast<std::size_t>(column[r])]);
  }

  // Labels `group` batch by batch at each fragment's first frame (forward) or last (backward).
  void sweep(std::vector<Eigen::Index> group, int direction)
  {
    const auto start = [&](Eigen::Index k) { return direction > 0 ? fragment(k).first : fragment(k).last(); };
    std::stable_sort(group.begin(), group.end(),
                     [&](Eigen::Index a, Eigen::Index b) { return direction > 0 ? start(a) < start(b) : start(a) > start(b); });
    std::vector<Eigen::Index> batch;
    for (std::size_t i = 0; i < group.size();) {
      const Eigen::Index frame = start(group[i]);
      batch.clear();
      for (; i < group.size() && start(group[i]) == frame; ++i)
        batch.push_back(group[i]);
      labelBatch(frame, batch, direction);
    }
  }

  Take& m_take;
  const std::vector<Fragment>& m_fragments;
  const MarkerSet& m_set;
  const LabellingOptions& m_options;
  Eigen::Index m_labels;
  std::vector<std::vector<Eigen::Index>> m_byDistance;  // per label, the others nearest first
  Eigen::VectorXd m_gate;                               // per label, nearest template neighbour distance
  LabellingResult m_result;
};

} // namespace

Similarity alignTemplate(const Eigen::Ref<const PointSet>& templ, const Eigen::Ref<const PointSet>& points,
                         double* residual)
{
  checkPoints(templ, "template points");
  checkPoints(points, "data points");
  const PrincipalFrame from = principalFrame(templ);
  const PrincipalFrame to = principalFrame(points);
  const double scale = from.radius > 0.0 && to.radius > 0.0 ? to.radius / from.radius : 1.0;
  std::vector<Similarity> starts{similarityThrough(Eigen::Matrix3d::Identity(), 1.0, from.centre, to.centre)};
  for (const auto& flip : {Eigen::Vector3d(1, 1, 1), Eigen::Vector3d(-1, -1, 1), Eigen::Vector3d(-1, 1, -1),
                           Eigen::Vector3d(1, -1, -1)})
    starts.push_back(similarityThrough(to.axes * flip.asDiagonal() * from.axes.transpose(), scale, from.centre, to.centre));
  Similarity best;
  double bestResidual = std::numeric_limits<double>::infinity();
  const IcpOptions options = templateIcp();
  for (const Similarity& start : starts) {
    const Similarity s = icp(templ, points, start, options).transform;
    // Trimmed mean distance of the data points to their closest template point.
    const double r = trimmedMean(closestPointDistances(templ, points, s, options));
    if (r < bestResidual) {
      best = s;
      bestResidual = r;
    }
  }
  if (residual)
    *residual = bestResidual;
  return best;
}

LabellingResult labelFragments(Take& take, const std::vector<Fragment>& fragments, const MarkerSet& set,
                               const LabellingOptions& options)
{
  checkLabellingInputs(take, fragments, set, options);
  return Labeller(take, fragments, set, options).run();
}

} // namespace mocap

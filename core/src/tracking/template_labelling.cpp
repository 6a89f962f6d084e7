#include "mocap/tracking/template_labelling.h"

#include "mocap/base/error.h"
#include "mocap/math/hungarian_assignment.h"

#include <Eigen/Eigenvalues>

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

// Distance from each row of `moved` to its closest row of `points`, and that row.
void closestPoints(const Eigen::Ref<const PointSet>& moved, const Eigen::Ref<const PointSet>& points,
                   Eigen::VectorXd& distance, std::vector<Eigen::Index>& closest)
{
  distance.resize(moved.rows());
  closest.resize(static_cast<std::size_t>(moved.rows()));
  for (Eigen::Index i = 0; i < moved.rows(); ++i) {
    Eigen::Index best = 0;
    (points.rowwise() - moved.row(i)).rowwise().squaredNorm().minCoeff(&best);
    closest[static_cast<std::size_t>(i)] = best;
    distance(i) = (points.row(best) - moved.row(i)).norm();
  }
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

PointSet transformed(const Similarity& s, const Eigen::Ref<const PointSet>& points)
{
  PointSet out(points.rows(), 3);
  for (Eigen::Index i = 0; i < points.rows(); ++i)
    out.row(i) = s.apply(points.row(i).transpose()).transpose();
  return out;
}

// ICP from `start`: each data point pulls its closest template point (the data may miss markers
// and hold strays, so correspondences go from the data); returns the transform and the trimmed
// mean distance of the data points to their closest template point.
std::pair<Similarity, double> refineIcp(const Eigen::Ref<const PointSet>& templ, const Eigen::Ref<const PointSet>& points,
                                        Similarity s)
{
  Eigen::VectorXd distance;
  std::vector<Eigen::Index> closest;
  for (int iteration = 0; iteration < kIcpIterations; ++iteration) {
    closestPoints(points, transformed(s, templ), distance, closest);
    const double limit = kIcpInlierFactor * quantile(distance, 0.5) + 1e-12;
    std::vector<Eigen::Index> inliers;
    for (Eigen::Index i = 0; i < points.rows(); ++i)
      if (distance(i) <= limit)
        inliers.push_back(i);
    if (inliers.size() < 3)
      break;
    PointSet from(static_cast<Eigen::Index>(inliers.size()), 3);
    PointSet to(from.rows(), 3);
    for (std::size_t k = 0; k < inliers.size(); ++k) {
      from.row(static_cast<Eigen::Index>(k)) = templ.row(closest[static_cast<std::size_t>(inliers[k])]);
      to.row(static_cast<Eigen::Index>(k)) = points.row(inliers[k]);
    }
    const Similarity next = fitSimilarityLoose(from, to);
    const double change = (next.rotation - s.rotation).norm() + std::abs(next.scale - s.scale) +
                          (next.translation - s.translation).norm() / (limit + 1.0);
    s = next;
    if (change < 1e-10)
      break;
  }
  closestPoints(points, transformed(s, templ), distance, closest);
  return {s, trimmedMean(distance)};
}

// Principal axes (columns, largest variance first) and the RMS radius of a point set.
std::pair<Eigen::Matrix3d, double> principalAxes(const Eigen::Ref<const PointSet>& points)
{
  const PointSet centred = points.rowwise() - points.colwise().mean();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(centred.transpose() * centred);
  Eigen::Matrix3d axes = eigen.eigenvectors().rowwise().reverse();
  if (axes.determinant() < 0.0)
    axes.col(2) = -axes.col(2);
  return {axes, std::sqrt(centred.squaredNorm() / static_cast<double>(points.rows()))};
}

Similarity startAt(const Eigen::Matrix3d& rotation, double scale, const Eigen::Vector3d& fromCentre,
                   const Eigen::Vector3d& toCentre)
{
  Similarity s;
  s.rotation = rotation;
  s.scale = scale;
  s.translation = toCentre - scale * (rotation * fromCentre);
  return s;
}

void checkOptions(const Take& take, const std::vector<Fragment>& fragments, const MarkerSet& set,
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
      m_take.setState(frame, label, SampleState::Original);
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
  const Eigen::Vector3d fromCentre = templ.colwise().mean().transpose();
  const Eigen::Vector3d toCentre = points.colwise().mean().transpose();
  const auto [fromAxes, fromRadius] = principalAxes(templ);
  const auto [toAxes, toRadius] = principalAxes(points);
  const double scale = fromRadius > 0.0 && toRadius > 0.0 ? toRadius / fromRadius : 1.0;
  std::vector<Similarity> starts{startAt(Eigen::Matrix3d::Identity(), 1.0, fromCentre, toCentre)};
  for (const auto& flip : {Eigen::Vector3d(1, 1, 1), Eigen::Vector3d(-1, -1, 1), Eigen::Vector3d(-1, 1, -1),
                           Eigen::Vector3d(1, -1, -1)})
    starts.push_back(startAt(toAxes * flip.asDiagonal() * fromAxes.transpose(), scale, fromCentre, toCentre));
  Similarity best;
  double bestResidual = std::numeric_limits<double>::infinity();
  for (const Similarity& start : starts) {
    const auto [s, r] = refineIcp(templ, points, start);
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
  checkOptions(take, fragments, set, options);
  return Labeller(take, fragments, set, options).run();
}

} // namespace mocap

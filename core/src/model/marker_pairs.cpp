#include "mocap/model/marker_pairs.h"

#include "mocap/base/error.h"
#include "mocap/base/text.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <map>
#include <optional>

namespace mocap {

MarkerSymmetry::MarkerSymmetry(Eigen::Index markerCount)
{
  if (markerCount < 0)
    throw InvalidArgument("marker symmetry: negative marker count");
  m_mirror.resize(static_cast<std::size_t>(markerCount));
  for (Eigen::Index m = 0; m < markerCount; ++m)
    m_mirror[static_cast<std::size_t>(m)] = m;
  buildUnits();
}

MarkerSymmetry::MarkerSymmetry(Eigen::Index markerCount,
                               const std::vector<std::pair<Eigen::Index, Eigen::Index>>& pairs)
    : MarkerSymmetry(markerCount)
{
  for (const auto& [a, b] : pairs) {
    if (a < 0 || b < 0 || a >= markerCount || b >= markerCount)
      throw InvalidArgument("marker symmetry: pair (" + std::to_string(a) + ", " + std::to_string(b) +
                            ") is out of range for " + std::to_string(markerCount) + " markers");
    if (a == b)
      throw InvalidArgument("marker symmetry: marker " + std::to_string(a) + " is paired with itself");
    for (const Eigen::Index m : {a, b})
      if (m_mirror[static_cast<std::size_t>(m)] != m)
        throw InvalidArgument("marker symmetry: marker " + std::to_string(m) + " is in two pairs");
    m_mirror[static_cast<std::size_t>(a)] = b;
    m_mirror[static_cast<std::size_t>(b)] = a;
  }
  buildUnits();
}

void MarkerSymmetry::buildUnits()
{
  m_units.clear();
  m_unitOf.assign(m_mirror.size(), -1);
  for (Eigen::Index m = 0; m < markerCount(); ++m) {
    if (m_unitOf[static_cast<std::size_t>(m)] >= 0)
      continue;
    const Eigen::Index partner = m_mirror[static_cast<std::size_t>(m)];
    const auto unit = static_cast<Eigen::Index>(m_units.size());
    m_units.push_back(partner == m ? std::vector<Eigen::Index>{m} : std::vector<Eigen::Index>{m, partner});
    m_unitOf[static_cast<std::size_t>(m)] = unit;
    m_unitOf[static_cast<std::size_t>(partner)] = unit;
  }
}

Eigen::Index MarkerSymmetry::mirror(Eigen::Index marker) const
{
  if (marker < 0 || marker >= markerCount())
    throw InvalidArgument("marker symmetry: marker " + std::to_string(marker) + " out of range");
  return m_mirror[static_cast<std::size_t>(marker)];
}

Eigen::Index MarkerSymmetry::unitOf(Eigen::Index marker) const
{
  if (marker < 0 || marker >= markerCount())
    throw InvalidArgument("marker symmetry: marker " + std::to_string(marker) + " out of range");
  return m_unitOf[static_cast<std::size_t>(marker)];
}

std::vector<std::pair<Eigen::Index, Eigen::Index>> MarkerSymmetry::pairs() const
{
  std::vector<std::pair<Eigen::Index, Eigen::Index>> result;
  for (const auto& unit : m_units)
    if (unit.size() == 2)
      result.emplace_back(unit[0], unit[1]);
  return result;
}

std::vector<Eigen::Index> MarkerSymmetry::symmetricClosure(const std::vector<Eigen::Index>& markers) const
{
  std::vector<Eigen::Index> result;
  result.reserve(2 * markers.size());
  for (const Eigen::Index m : markers) {
    result.push_back(m);
    result.push_back(mirror(m));
  }
  std::sort(result.begin(), result.end());
  result.erase(std::unique(result.begin(), result.end()), result.end());
  return result;
}

MarkerSymmetry parseMarkerPairs(std::string_view text, const std::vector<std::string>& labels,
                                const std::string& sourceName)
{
  std::map<std::string, Eigen::Index, std::less<>> index;
  for (std::size_t m = 0; m < labels.size(); ++m)
    index.emplace(labels[m], static_cast<Eigen::Index>(m));
  std::vector<std::pair<Eigen::Index, Eigen::Index>> pairs;
  std::vector<bool> paired(labels.size(), false);
  int lineNumber = 0;
  for (std::string_view line : split(text, '\n')) {
    ++lineNumber;
    const std::string where = "line " + std::to_string(lineNumber) + ": ";
    line = line.substr(0, line.find('#'));
    std::vector<std::string_view> fields;
    std::size_t start = 0;
    for (std::size_t i = 0; i <= line.size(); ++i) {
      const bool separator =
          i == line.size() || line[i] == ' ' || line[i] == '\t' || line[i] == ',' || line[i] == '\r';
      if (!separator)
        continue;
      if (i > start)
        fields.push_back(line.substr(start, i - start));
      start = i + 1;
    }
    if (fields.empty())
      continue;
    if (fields.size() != 2)
      throw FormatError(sourceName,
                        where + "expected two marker labels, got " + std::to_string(fields.size()));
    Eigen::Index ends[2] = {0, 0};
    for (int e = 0; e < 2; ++e) {
      const auto it = index.find(fields[static_cast<std::size_t>(e)]);
      if (it == index.end())
        throw FormatError(sourceName,
                          where + "no marker '" + std::string(fields[static_cast<std::size_t>(e)]) + "'");
      ends[e] = it->second;
    }
    if (ends[0] == ends[1])
      throw FormatError(sourceName, where + "marker '" + std::string(fields[0]) + "' is paired with itself");
    for (const Eigen::Index m : ends) {
      if (paired[static_cast<std::size_t>(m)])
        throw FormatError(sourceName,
                          where + "marker '" + labels[static_cast<std::size_t>(m)] + "' is in two pairs");
      paired[static_cast<std::size_t>(m)] = true;
    }
    pairs.emplace_back(ends[0], ends[1]);
  }
  return MarkerSymmetry(static_cast<Eigen::Index>(labels.size()), pairs);
}


std::vector<std::string> mirroredLabelCandidates(std::string_view label)
{
  std::vector<std::string> candidates;
  const auto isAlpha = [](char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; };
  const auto isLower = [](char c) { return std::islower(static_cast<unsigned char>(c)) != 0; };
  for (std::size_t i = 0; i < label.size(); ++i) {
    const char c = label[i];
    const bool upper = c == 'L' || c == 'R';
    const bool lower = c == 'l' || c == 'r';
    if (!upper && !lower)
      continue;
    const bool wordStart = i == 0 || !isAlpha(label[i - 1]) || (upper && isLower(label[i - 1]));
    // A lower-case side letter must stand alone ("l_eye", "r1"), or it is part of a word.
    const bool alone = i + 1 == label.size() || !isLower(label[i + 1]);
    if (!wordStart || (lower && !alone))
      continue;
    std::string swapped(label);
    swapped[i] = c == 'L' ? 'R' : c == 'R' ? 'L' : c == 'l' ? 'r' : 'l';
    candidates.push_back(swapped);
  }
  // Whole words, in whatever case the label uses.
  const std::string lowered = toLower(label);
  for (const auto& [from, to] : {std::pair<std::string, std::string>{"left", "right"}, {"right", "left"}}) {
    for (std::size_t at = lowered.find(from); at != std::string::npos; at = lowered.find(from, at + 1)) {
      std::string replacement = to;
      const std::string_view original = label.substr(at, from.size());
      if (std::all_of(original.begin(), original.end(),
                      [](char ch) { return std::isupper(static_cast<unsigned char>(ch)); }))
        replacement = toUpper(replacement);
      else if (std::isupper(static_cast<unsigned char>(original[0])))
        replacement[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(replacement[0])));
      candidates.push_back(std::string(label.substr(0, at)) + replacement +
                           std::string(label.substr(at + from.size())));
    }
  }
  return candidates;
}

namespace {

struct Plane
{
  Eigen::Vector3d normal = Eigen::Vector3d::UnitX();
  double offset = 0.0;  // n·x = offset on the plane

  [[nodiscard]] Eigen::RowVector3d reflect(const Eigen::RowVector3d& p) const
  {
    return p - 2.0 * (p.dot(normal) - offset) * normal.transpose();
  }
};

// For each marker, the nearest marker to its mirror image among `candidates` (all when empty).
struct Matching
{
  std::vector<Eigen::Index> nearest;
  std::vector<double> distance;
};

Matching matchMirrors(const Eigen::MatrixX3d& points, const Plane& plane, const std::vector<bool>& usable)
{
  const Eigen::Index n = points.rows();
  Matching matching{
      std::vector<Eigen::Index>(static_cast<std::size_t>(n), -1),
      std::vector<double>(static_cast<std::size_t>(n), std::numeric_limits<double>::infinity())};
  for (Eigen::Index i = 0; i < n; ++i) {
    if (!usable[static_cast<std::size_t>(i)])
      continue;
    const Eigen::RowVector3d image = plane.reflect(points.row(i));
    for (Eigen::Index j = 0; j < n; ++j) {
      if (!usable[static_cast<std::size_t>(j)])
        continue;
      const double d = (points.row(j) - image).norm();
      if (d < matching.distance[static_cast<std::size_t>(i)]) {
        matching.distance[static_cast<std::size_t>(i)] = d;
        matching.nearest[static_cast<std::size_t>(i)] = j;
      }
    }
  }
  return matching;
}

// Plane through the midpoints of `pairs` and the `midline` points, normal along the pair differences.
std::optional<Plane> fitPlane(const Eigen::MatrixX3d& points,
                              const std::vector<std::pair<Eigen::Index, Eigen::Index>>& pairs,
                              const std::vector<Eigen::Index>& midline, const Eigen::Vector3d& previousNormal)
{
  if (pairs.empty())
    return std::nullopt;
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const auto& [a, b] : pairs) {
    const Eigen::Vector3d d = (points.row(a) - points.row(b)).transpose();
    scatter += d * d.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(scatter);
  Plane plane;
  plane.normal = solver.eigenvectors().col(2);
  if (plane.normal.dot(previousNormal) < 0.0)
    plane.normal = -plane.normal;
  double sum = 0.0;
  for (const auto& [a, b] : pairs)
    sum += 0.5 * (points.row(a) + points.row(b)).dot(plane.normal);
  for (const Eigen::Index m : midline)
    sum += points.row(m).dot(plane.normal);
  plane.offset = sum / static_cast<double>(pairs.size() + midline.size());
  return plane;
}

struct Refined
{
  Plane plane;
  double score = std::numeric_limits<double>::infinity();
};

// Alternates mutual-nearest matching with a plane fit; label pairs always take part in the fit.
Refined refinePlane(const Eigen::MatrixX3d& points, Plane plane,
                    const std::vector<std::pair<Eigen::Index, Eigen::Index>>& labelPairs)
{
  const Eigen::Index n = points.rows();
  const std::vector<bool> all(static_cast<std::size_t>(n), true);
  for (int iteration = 0; iteration < 20; ++iteration) {
    const Matching matching = matchMirrors(points, plane, all);
    std::vector<std::pair<Eigen::Index, Eigen::Index>> pairs = labelPairs;
    std::vector<Eigen::Index> midline;
    for (Eigen::Index i = 0; i < n; ++i) {
      const Eigen::Index j = matching.nearest[static_cast<std::size_t>(i)];
      if (j == i)
        midline.push_back(i);
      else if (i < j && matching.nearest[static_cast<std::size_t>(j)] == i)
        pairs.emplace_back(i, j);
    }
    const auto fitted = fitPlane(points, pairs, midline, plane.normal);
    if (!fitted)
      break;
    const bool settled =
        fitted->normal.dot(plane.normal) > 1.0 - 1e-14 && std::abs(fitted->offset - plane.offset) < 1e-12;
    plane = *fitted;
    if (settled)
      break;
  }
  const Matching matching = matchMirrors(points, plane, all);
  double total = 0.0;
  for (const double d : matching.distance)
    total += d;
  return {plane, total / static_cast<double>(n)};
}

} // namespace

PairDetection detectMarkerPairs(const Eigen::Ref<const Eigen::MatrixX3d>& neutral,
                                const std::vector<std::string>& labels, const PairDetectionOptions& options)
{
  const Eigen::Index n = neutral.rows();
  if (static_cast<std::size_t>(n) != labels.size())
    throw InvalidArgument("pair detection: " + std::to_string(n) + " positions for " +
                          std::to_string(labels.size()) + " labels");
  if (!neutral.allFinite())
    throw InvalidArgument("pair detection: a neutral position is not finite");
  if (!(options.tolerance >= 0.0) || !std::isfinite(options.tolerance))
    throw InvalidArgument("pair detection: the tolerance must be finite and ≥ 0");
  const Eigen::MatrixX3d points = neutral;
  PairDetection detection;
  detection.symmetry = MarkerSymmetry(n);
  if (n < 2) {
    for (Eigen::Index m = 0; m < n; ++m)
      detection.midline.push_back(m);
    return detection;
  }

  // Pairs named by convention, when exactly one candidate label exists and the naming is mutual.
  std::vector<std::pair<Eigen::Index, Eigen::Index>> labelPairs;
  std::vector<bool> labelled(static_cast<std::size_t>(n), false);
  if (options.useLabels) {
    std::map<std::string, Eigen::Index, std::less<>> index;
    for (Eigen::Index m = 0; m < n; ++m)
      index.emplace(labels[static_cast<std::size_t>(m)], m);
    const auto partnerOf = [&](Eigen::Index m) -> Eigen::Index {
      Eigen::Index found = -1;
      for (const std::string& candidate : mirroredLabelCandidates(labels[static_cast<std::size_t>(m)])) {
        const auto it = index.find(candidate);
        if (it == index.end() || it->second == m || it->second == found)
          continue;
        if (found >= 0)
          return -1;  // ambiguous
        found = it->second;
      }
      return found;
    };
    for (Eigen::Index a = 0; a < n; ++a) {
      const Eigen::Index b = partnerOf(a);
      if (b > a && partnerOf(b) == a && !labelled[static_cast<std::size_t>(a)] &&
          !labelled[static_cast<std::size_t>(b)]) {
        labelPairs.emplace_back(a, b);
        labelled[static_cast<std::size_t>(a)] = labelled[static_cast<std::size_t>(b)] = true;
      }
    }
  }

  // Spacing of the layout sets the default tolerance.
  std::vector<double> spacing;
  for (Eigen::Index i = 0; i < n; ++i) {
    double nearest = std::numeric_limits<double>::infinity();
    for (Eigen::Index j = 0; j < n; ++j)
      if (j != i)
        nearest = std::min(nearest, (points.row(i) - points.row(j)).norm());
    spacing.push_back(nearest);
  }
  std::nth_element(spacing.begin(), spacing.begin() + static_cast<std::ptrdiff_t>(spacing.size() / 2),
                   spacing.end());
  detection.tolerance = options.tolerance > 0.0 ? options.tolerance : 0.5 * spacing[spacing.size() / 2];

  // Plane guesses: from the named pairs, and each principal axis through the centroid.
  std::vector<Plane> guesses;
  if (labelPairs.size() >= 2)
    if (const auto plane = fitPlane(points, labelPairs, {}, Eigen::Vector3d::UnitX()))
      guesses.push_back(*plane);
  const Eigen::RowVector3d centroid = points.colwise().mean();
  const Eigen::MatrixX3d centred = points.rowwise() - centroid;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> axes(centred.transpose() * centred);
  for (int axis = 2; axis >= 0; --axis) {
    Plane plane;
    plane.normal = axes.eigenvectors().col(axis);
    plane.offset = centroid.dot(plane.normal);
    guesses.push_back(plane);
  }
  Refined best;
  for (const Plane& guess : guesses) {
    const Refined refined = refinePlane(points, guess, labelPairs);
    if (refined.score < best.score)
      best = refined;
  }
  const Plane& plane = best.plane;
  detection.planeNormal = plane.normal;
  detection.planePoint = plane.offset * plane.normal;

  std::vector<std::pair<Eigen::Index, Eigen::Index>> pairs = labelPairs;
  for (const auto& [a, b] : labelPairs)
    detection.pairs.push_back({a, b, (plane.reflect(points.row(a)) - points.row(b)).norm(), true});
  std::vector<bool> usable(static_cast<std::size_t>(n));
  for (Eigen::Index m = 0; m < n; ++m)
    usable[static_cast<std::size_t>(m)] = !labelled[static_cast<std::size_t>(m)];
  const Matching matching = matchMirrors(points, plane, usable);
  for (Eigen::Index i = 0; i < n; ++i) {
    if (labelled[static_cast<std::size_t>(i)])
      continue;
    const Eigen::Index j = matching.nearest[static_cast<std::size_t>(i)];
    const double d = matching.distance[static_cast<std::size_t>(i)];
    if (j == i && d <= detection.tolerance) {
      detection.midline.push_back(i);
    } else if (j != i && j >= 0 && matching.nearest[static_cast<std::size_t>(j)] == i &&
               d <= detection.tolerance) {
      if (i < j) {
        pairs.emplace_back(i, j);
        detection.pairs.push_back({i, j, d, false});
      }
    } else {
      detection.unpaired.push_back(i);
    }
  }
  std::sort(detection.pairs.begin(), detection.pairs.end(),
            [](const DetectedPair& x, const DetectedPair& y) { return x.first < y.first; });
  detection.symmetry = MarkerSymmetry(n, pairs);
  return detection;
}

} // namespace mocap

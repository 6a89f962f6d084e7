#include "mocap/io/take_plausibility.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace mocap {

namespace {

/// A take whose markers span less than this many millimetres, or more than this many metres, is
/// in another unit than it says: no marker set is smaller than a fingertip, and no capture volume
/// is a hundred metres across.
constexpr double kSmallestSpanMm = 10.0;
constexpr double kLargestSpanM = 100.0;
/// Fewer markers than this say nothing about the unit: one marker at rest spans nothing.
constexpr Eigen::Index kMarkersForUnit = 3;

struct MarkerCoordinates
{
  Eigen::Index measuredMarkers = 0;   ///< markers with a valid sample
  Eigen::Index unmeasuredMarkers = 0; ///< markers with no valid sample but non-zero coordinates
  double span = 0.0;                  ///< largest extent on one axis of the samples looked at
};

/// Whether a sample holds a position a writer put there (finite and not the all-zero "no data").
bool holdsCoordinates(const Eigen::Vector3d& p)
{
  return p.allFinite() && !p.isZero();
}

/// The markers' coordinates: valid samples when any marker has one, else every sample that holds
/// coordinates (so the all-invalid file's unit can still be judged). O(#frames × #markers).
MarkerCoordinates markerCoordinates(const Take& take)
{
  MarkerCoordinates out;
  for (Eigen::Index m = 0; m < take.markerCount(); ++m) {
    if (take.pointType(m) != PointType::Marker)
      continue;
    bool valid = false, held = false;
    for (Eigen::Index f = 0; f < take.frameCount() && !valid; ++f) {
      valid = take.isValid(f, m);
      held = held || holdsCoordinates(take.position(f, m));
    }
    out.measuredMarkers += valid ? 1 : 0;
    out.unmeasuredMarkers += !valid && held ? 1 : 0;
  }
  const bool validOnly = out.measuredMarkers > 0;
  Eigen::Vector3d low = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d high = -low;
  for (Eigen::Index m = 0; m < take.markerCount(); ++m) {
    if (take.pointType(m) != PointType::Marker)
      continue;
    for (Eigen::Index f = 0; f < take.frameCount(); ++f) {
      const Eigen::Vector3d p = take.position(f, m);
      if (validOnly ? take.isValid(f, m) && p.allFinite() : holdsCoordinates(p)) {
        low = low.cwiseMin(p);
        high = high.cwiseMax(p);
      }
    }
  }
  out.span = (high - low).allFinite() ? (high - low).maxCoeff() : 0.0;
  return out;
}

std::string numberText(double value)
{
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

/// The unit warning, or "" when the span fits the unit.
std::string unitWarning(const Take& take, double span, bool unitDeclared)
{
  if (!(span > 0.0))
    return {};
  const double mm = millimetresPer(take.units()) * span;
  const std::string unit(unitName(take.units()));
  const std::string source = unitDeclared ? "the file's unit" : "assumed: the file names no unit";
  const auto likely = [&](const char* what, const char* name) {
    return "; the file is likely in " + std::string(what) + ". Positions are read as " + unit +
           "; once you know the unit, name it (studio: Edit > Positions Are In; "
           "mocap convert IN OUT --input-units " + name + ")";
  };
  if (mm < kSmallestSpanMm)
    return "the markers span only " + numberText(span) + " " + unit + " (" + source +
           "), smaller than any marker set" + likely("metres", "m");
  if (mm > kLargestSpanM * 1000.0)
    return "the markers span " + numberText(span) + " " + unit + " (" + source + "), larger than any capture volume" +
           likely("millimetres", "mm");
  return {};
}

} // namespace

std::vector<std::string> takePlausibilityWarnings(const Take& take, bool unitDeclared)
{
  std::vector<std::string> warnings;
  if (take.frameCount() == 0)
    return warnings;
  const MarkerCoordinates seen = markerCoordinates(take);
  if (seen.measuredMarkers == 0 && seen.unmeasuredMarkers > 0)
    warnings.push_back("every sample is marked invalid (a negative residual), yet " +
                       std::to_string(seen.unmeasuredMarkers) +
                       " marker(s) hold coordinates: the writing system marks its points so (some SIMI exports "
                       "do). Nothing is drawn, gap-listed or cleaned, and a saved copy writes them as invalid points are "
                       "written (zero in C3D, blank in TRC): keep this file for its coordinates");
  const Eigen::Index judged = seen.measuredMarkers > 0 ? seen.measuredMarkers : seen.unmeasuredMarkers;
  if (std::string unit = judged >= kMarkersForUnit ? unitWarning(take, seen.span, unitDeclared) : std::string();
      !unit.empty())
    warnings.push_back(std::move(unit));
  return warnings;
}

} // namespace mocap

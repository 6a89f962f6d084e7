#include "mocap/io/weights_csv_writer.h"

#include "mocap/base/error.h"
#include "mocap/base/file_io.h"
#include "mocap/base/number_text.h"
#include "mocap/io/csv_writer.h"

#include <cmath>
#include <cstdio>

namespace mocap {

namespace {

std::string timecode(double seconds, double frameRate)
{
  const long long fps = std::max(1LL, std::llround(frameRate));
  const double frames = seconds * static_cast<double>(fps);
  const auto whole = static_cast<long long>(std::floor(frames + 1e-9));
  const auto thousandths = std::min(999LL, static_cast<long long>(std::llround((frames - static_cast<double>(whole)) * 1000.0)));
  const long long totalSeconds = whole / fps;
  char text[128];
  std::snprintf(text, sizeof text, "%02lld:%02lld:%02lld:%02lld.%03lld", totalSeconds / 3600, totalSeconds / 60 % 60,
                totalSeconds % 60, whole % fps, std::max(0LL, thousandths));
  return text;
}

} // namespace

std::string weightsCsvText(const std::vector<std::string>& names, const Eigen::Ref<const Eigen::MatrixXd>& weights,
                           long long firstFrame, double frameRate, WeightsCsvLayout layout)
{
  if (static_cast<Eigen::Index>(names.size()) != weights.cols())
    throw InvalidArgument("weights CSV: " + std::to_string(names.size()) + " names for " +
                          std::to_string(weights.cols()) + " columns");
  if (!(frameRate > 0.0) || !std::isfinite(frameRate))
    throw InvalidArgument("weights CSV: the frame rate must be positive");
  std::string out = layout == WeightsCsvLayout::LiveLink ? "Timecode,BlendShapeCount" : "Frame,Time";
  for (const std::string& name : names) {
    out += ',';
    appendCsvField(out, name);
  }
  out += '\n';
  for (Eigen::Index f = 0; f < weights.rows(); ++f) {
    const double seconds = static_cast<double>(f) / frameRate;
    if (layout == WeightsCsvLayout::LiveLink) {
      out += timecode(seconds, frameRate);
      out += ',' + std::to_string(weights.cols());
    } else {
      out += std::to_string(firstFrame + f) + ',';
      appendNumber(out, seconds);
    }
    for (Eigen::Index s = 0; s < weights.cols(); ++s) {
      out += ',';
      appendNumber(out, weights(f, s));
    }
    out += '\n';
  }
  return out;
}

void writeWeightsCsv(const std::filesystem::path& path, const std::vector<std::string>& names,
                     const Eigen::Ref<const Eigen::MatrixXd>& weights, long long firstFrame, double frameRate,
                     WeightsCsvLayout layout)
{
  writeFileAtomically(path, weightsCsvText(names, weights, firstFrame, frameRate, layout));
}

} // namespace mocap

#include "mocap/io/weights_csv_writer.h"

#include "mocap/base/error.h"
#include "mocap/base/file_io.h"
#include "mocap/base/number_text.h"
#include "mocap/io/csv_writer.h"

#include <cmath>
#include <cstdio>

namespace mocap {

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
      out += timecodeText(seconds, frameRate);
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

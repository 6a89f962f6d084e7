#include "mocap/io/weights_csv_writer.h"

#include "mocap/base/error.h"
#include "mocap/base/file_io.h"
#include "mocap/base/number_text.h"
#include "mocap/io/csv_writer.h"

#include <cmath>
#include <cstdio>

namespace mocap {

std::string weightsCsvText(const std::vector<std::string>& names, const Eigen::Ref<const Eigen::MatrixXd>& weights,
                           long long firstFrame, double frameRate)
{
  if (static_cast<Eigen::Index>(names.size()) != weights.cols())
    throw InvalidArgument("weights CSV: " + std::to_string(names.size()) + " names for " +
                          std::to_string(weights.cols()) + " columns");
  if (!(frameRate > 0.0) || !std::isfinite(frameRate))
    throw InvalidArgument("weights CSV: the frame rate must be positive");
  std::string out = "Frame,Time";
  for (const std::string& name : names) {
    out += ',';
    appendCsvField(out, name);
  }
  out += '\n';
  for (Eigen::Index f = 0; f < weights.rows(); ++f) {
    out += std::to_string(firstFrame + f) + ',';
    appendNumber(out, static_cast<double>(f) / frameRate);
    for (Eigen::Index s = 0; s < weights.cols(); ++s) {
      out += ',';
      appendNumber(out, weights(f, s));
    }
    out += '\n';
  }
  return out;
}

void writeWeightsCsv(const std::filesystem::path& path, const std::vector<std::string>& names,
                     const Eigen::Ref<const Eigen::MatrixXd>& weights, long long firstFrame, double frameRate)
{
  writeFileAtomically(path, weightsCsvText(names, weights, firstFrame, frameRate));
}

} // namespace mocap

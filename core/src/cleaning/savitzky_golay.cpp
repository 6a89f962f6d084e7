#include "mocap/cleaning/savitzky_golay.h"

#include "mocap/base/error.h"

#include <Eigen/QR>

#include <algorithm>
#include <string>

namespace mocap {

void checkSavitzkyGolayOptions(const SavitzkyGolayOptions& options)
{
  if (options.window < 3 || options.window > 1001 || options.window % 2 == 0)
    throw InvalidArgument("Savitzky-Golay window must be odd and 3..1001 samples, not " +
                          std::to_string(options.window));
  if (options.degree < 0 || options.degree > std::min(options.window - 1, 10))
    throw InvalidArgument("Savitzky-Golay degree must be 0.." +
                          std::to_string(std::min(options.window - 1, 10)) + " for a window of " +
                          std::to_string(options.window) + ", not " + std::to_string(options.degree));
}

Eigen::MatrixXd savitzkyGolayWeights(const SavitzkyGolayOptions& options)
{
  checkSavitzkyGolayOptions(options);
  const Eigen::Index w = options.window;
  const Eigen::Index half = w / 2;
  Eigen::MatrixXd vandermonde(w, options.degree + 1);
  for (Eigen::Index r = 0; r < w; ++r) {
    const double u = static_cast<double>(r - half) / static_cast<double>(half);
    double power = 1.0;
    for (int k = 0; k <= options.degree; ++k) {
      vandermonde(r, k) = power;
      power *= u;
    }
  }
  // The hat matrix is Q Qᵀ for the thin orthonormal factor Q of V.
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(vandermonde);
  const Eigen::MatrixXd q = qr.householderQ() * Eigen::MatrixXd::Identity(w, options.degree + 1);
  return q * q.transpose();
}

Eigen::MatrixXd savitzkyGolay(const Eigen::Ref<const Eigen::MatrixXd>& samples,
                              const SavitzkyGolayOptions& options)
{
  checkSavitzkyGolayOptions(options);
  if (!samples.allFinite())
    throw InvalidArgument("Savitzky-Golay: samples must be finite");
  const Eigen::Index n = samples.rows();
  const Eigen::Index w = options.window;
  if (n < w)
    return samples;
  const Eigen::MatrixXd weights = savitzkyGolayWeights(options);
  const Eigen::Index half = w / 2;
  const Eigen::VectorXd centre = weights.row(half).transpose();
  Eigen::MatrixXd result(n, samples.cols());
  for (Eigen::Index c = 0; c < samples.cols(); ++c) {
    const auto y = samples.col(c);
    auto out = result.col(c);
    for (Eigen::Index i = half; i < n - half; ++i)
      out(i) = centre.dot(y.segment(i - half, w));
    out.head(half) = weights.topRows(half) * y.head(w);
    out.tail(half) = weights.bottomRows(half) * y.tail(w);
  }
  return result;
}

} // namespace mocap

#include "finite_weights.h"

#include "mocap/base/error.h"

#include <cmath>
#include <string>

namespace mocap::python {

void checkFiniteWeights(const Eigen::Ref<const Eigen::MatrixXd>& weights)
{
  for (Eigen::Index f = 0; f < weights.rows(); ++f)
    for (Eigen::Index s = 0; s < weights.cols(); ++s)
      if (!std::isfinite(weights(f, s)))
        throw InvalidArgument("weights[" + std::to_string(f) + ", " + std::to_string(s) + "] is not finite");
}

} // namespace mocap::python

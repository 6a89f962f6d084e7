#include "mocap/head_reference.h"

#include "mocap/text.h"

namespace mocap {

std::vector<std::string> guessHeadReferenceLabels(const Take& take)
{
  std::vector<std::string> labels;
  for (const std::string& label : take.labels()) {
    const std::string lower = toLower(label);
    if (lower.rfind("root", 0) == 0 || lower.rfind("head", 0) == 0)
      labels.push_back(label);
  }
  return labels;
}

} // namespace mocap

#include "mocap/io/c3d_string_lists.h"

#include <algorithm>

namespace mocap {

std::vector<std::string> c3dStringsAcrossParts(const C3dParameterTree& tree, std::string_view group,
                                               const std::string& base)
{
  std::vector<std::string> all = tree.strings(group, base);
  for (int part = 2;; ++part) {
    const C3dParameter* p = tree.find(group, base + std::to_string(part));
    if (!p)
      return all;
    const auto more = p->strings();
    all.insert(all.end(), more.begin(), more.end());
  }
}

void setC3dStringsAcrossParts(C3dParameterTree& tree, std::string_view group, const std::string& base,
                              const std::vector<std::string>& values)
{
  constexpr std::size_t kMaxArrayEntries = 255;  // a C3D dimension is one byte
  std::size_t part = 1;
  for (std::size_t start = 0; start < values.size() || start == 0; start += kMaxArrayEntries, ++part) {
    const auto end = std::min(values.size(), start + kMaxArrayEntries);
    const std::vector<std::string> chunk(values.begin() + static_cast<std::ptrdiff_t>(start),
                                         values.begin() + static_cast<std::ptrdiff_t>(end));
    const std::string name = part == 1 ? base : base + std::to_string(part);
    tree.set(group, C3dParameter::makeStrings(name, chunk));
    if (end == values.size())
      break;
  }
  for (++part; tree.find(group, base + std::to_string(part)); ++part)
    tree.remove(group, base + std::to_string(part));
}

} // namespace mocap

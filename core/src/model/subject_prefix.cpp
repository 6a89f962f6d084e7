#include "mocap/model/subject_prefix.h"

namespace mocap {

std::string_view subjectPrefix(std::string_view label)
{
  const std::size_t colon = label.rfind(':');
  return colon == std::string_view::npos ? std::string_view{} : label.substr(0, colon + 1);
}

std::string_view withoutSubjectPrefix(std::string_view label)
{
  return label.substr(subjectPrefix(label).size());
}

} // namespace mocap

#pragma once

#include <string_view>

namespace mocap {

/// Systems that capture several subjects put the subject before every label
/// (SUBJECTS:LABEL_PREFIXES in C3D): Vicon's "Anna:root-1", ART's "Human3:HEAD". A label's name is
/// what follows its last colon.

/// "Anna:" of "Anna:root-1" (the colon kept); "" when the label has no colon. O(#characters).
[[nodiscard]] std::string_view subjectPrefix(std::string_view label);

/// "root-1" of "Anna:root-1"; the label itself when it has no colon. O(#characters).
[[nodiscard]] std::string_view withoutSubjectPrefix(std::string_view label);

} // namespace mocap

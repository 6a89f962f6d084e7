#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace mocap {

/// Small string helpers shared by the text formats and the C3D parameter tree.

/// `text` without leading and trailing blanks (space, tab, CR, LF, NUL).
[[nodiscard]] std::string_view trim(std::string_view text);

/// ASCII upper/lower case copy.
[[nodiscard]] std::string toUpper(std::string_view text);
[[nodiscard]] std::string toLower(std::string_view text);

/// ASCII case-insensitive equality.
[[nodiscard]] bool equalsIgnoreCase(std::string_view a, std::string_view b);

/// Splits on `separator`, keeping empty fields ("a,,b" gives 3 fields).
[[nodiscard]] std::vector<std::string_view> split(std::string_view text, char separator);

/// Whether `text` matches the glob `pattern`: `*` any run of characters, `?` any one, others
/// themselves. O(|pattern| · |text|) worst case.
[[nodiscard]] bool globMatch(std::string_view pattern, std::string_view text);

} // namespace mocap

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

/// One line of a text file that holds content: its number (from 1) and its text, trimmed.
struct TextLine
{
  std::size_t number = 0;
  std::string_view text;
};

/// The lines of `text` that are neither blank nor comments (first non-blank character `#`), as
/// line-based formats read them (manifests, point-cloud CSV). O(|text|).
[[nodiscard]] std::vector<TextLine> contentLines(std::string_view text);

/// Whether `text` matches the glob `pattern`: `*` any run of characters, `?` any one, others
/// themselves. O(|pattern| · |text|) worst case.
[[nodiscard]] bool globMatch(std::string_view pattern, std::string_view text);

} // namespace mocap

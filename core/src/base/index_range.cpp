#include "mocap/base/index_range.h"

#include "mocap/base/error.h"
#include "mocap/base/text.h"

#include <charconv>
#include <string>

namespace mocap {

namespace {

// One end of the range, `name` FIRST or LAST. O(|part|).
std::int64_t wholeNumber(std::string_view part, const std::string& name)
{
  std::string_view number = trim(part);
  if (number.empty())
    throw InvalidArgument(name + " is empty");
  const std::string quoted = name + " '" + std::string(number) + "'";
  // from_chars takes '-' but not '+', which the ranges' earlier reader (sscanf) took too.
  if (number.size() > 1 && number[0] == '+' && number[1] != '-')
    number.remove_prefix(1);
  std::int64_t value = 0;
  const char* end = number.data() + number.size();
  const auto [stop, error] = std::from_chars(number.data(), end, value);
  if (error == std::errc::result_out_of_range)
    throw InvalidArgument(quoted + " does not fit a 64-bit whole number");
  if (error != std::errc() || stop != end)
    throw InvalidArgument(quoted + " is not a whole number");
  return value;
}

} // namespace

IndexRange parseIndexRange(std::string_view text, std::int64_t lowest, std::int64_t highest)
{
  const std::size_t colon = text.find(':');
  if (colon == std::string_view::npos)
    throw InvalidArgument("no ':' between FIRST and LAST");
  const IndexRange range{wholeNumber(text.substr(0, colon), "FIRST"), wholeNumber(text.substr(colon + 1), "LAST")};
  if (range.last < range.first)
    throw InvalidArgument("LAST " + std::to_string(range.last) + " is before FIRST " + std::to_string(range.first));
  if (range.first < lowest)
    throw InvalidArgument("FIRST " + std::to_string(range.first) + " is less than " + std::to_string(lowest));
  if (range.last > highest)
    throw InvalidArgument("LAST " + std::to_string(range.last) + " is more than " + std::to_string(highest));
  return range;
}

} // namespace mocap

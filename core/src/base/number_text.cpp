#include "mocap/base/number_text.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <system_error>

namespace mocap {

void appendNumber(std::string& out, double value)
{
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, result.ptr);
}

std::string fixedText(double value, int decimals, std::string_view notFinite)
{
  if (!std::isfinite(value))
    return std::string(notFinite);
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

bool parseNumber(std::string_view text, double& value)
{
  if (!text.empty() && text.front() == '+')
    text.remove_prefix(1);
  if (text.empty())
    return false;
  const char* end = text.data() + text.size();
  const auto result = std::from_chars(text.data(), end, value);
  return result.ec == std::errc() && result.ptr == end;
}

std::string timecodeText(double seconds, double frameRate)
{
  const long long fps = std::max(1LL, std::llround(frameRate));
  const double frames = seconds * static_cast<double>(fps);
  const auto whole = static_cast<long long>(std::floor(frames + 1e-9));
  const auto thousandths = std::min(999LL, static_cast<long long>(std::llround((frames - static_cast<double>(whole)) * 1000.0)));
  const long long totalSeconds = whole / fps;
  char text[128];
  std::snprintf(text, sizeof text, "%02lld:%02lld:%02lld:%02lld.%03lld", totalSeconds / 3600, totalSeconds / 60 % 60,
                totalSeconds % 60, whole % fps, std::max(0LL, thousandths));
  return text;
}

} // namespace mocap

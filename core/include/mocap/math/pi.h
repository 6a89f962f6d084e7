#pragma once

namespace mocap {

/// π, for the files that need it (std::numbers::pi is C++20; M_PI is not standard C++).
inline constexpr double kPi = 3.14159265358979323846;

} // namespace mocap

#pragma once

#include "mocap/model/take.h"

#include <string>

namespace mocap::cli {

/// Prints "PATH: note: …" to stderr when writing `take` to `path` leaves points out (model outputs
/// in a TRC or BVH file: leftOutOnWriting), so no command drops data silently. O(#points).
void noteLeftOut(const Take& take, const std::string& path);

/// writeTake(take, path), then noteLeftOut. Throws as writeTake.
void writeOutputTake(const Take& take, const std::string& path);

} // namespace mocap::cli

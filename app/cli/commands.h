#pragma once

#include <string>
#include <vector>

namespace mocap::cli {

/// `mocap info FILE [--json]`: what the take holds and every gap. Returns the exit code.
int runInfo(const std::vector<std::string>& args);

/// `mocap convert IN OUT`: reads IN and writes OUT, formats by extension.
int runConvert(const std::vector<std::string>& args);

} // namespace mocap::cli

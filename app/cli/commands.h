#pragma once

#include <string>
#include <vector>

namespace mocap::cli {

/// `mocap info FILE [--json]`: what the take holds and every gap. Returns the exit code.
int runInfo(const std::vector<std::string>& args);

/// `mocap convert IN OUT [--units mm|cm|m]`: reads IN and writes OUT, formats by extension,
/// optionally rescaling positions to other units.
int runConvert(const std::vector<std::string>& args);

} // namespace mocap::cli

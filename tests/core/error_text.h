#pragma once

#include "mocap/base/error.h"

#include <string>

namespace mocap::test {

/// The message of the mocap::Error that `call` throws, or "" when it throws none: for tests that
/// check what an error says.
template <typename Call>
std::string errorOf(Call&& call)
{
  try {
    call();
  } catch (const Error& error) {
    return error.what();
  }
  return {};
}

} // namespace mocap::test

#pragma once

#include "test_support.h"

#include "mocap/io/take_io.h"

namespace mocap::test {

/// NoseMoCap.trc (tests/data/trc): 41 facial markers over 962 frames at 60 Hz, read once.
inline const Take& noseMoCapTake()
{
  static const Take take = readTake(dataFile("trc/NoseMoCap.trc"));
  return take;
}

} // namespace mocap::test

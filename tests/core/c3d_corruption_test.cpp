// Truncated and byte-flipped copies of real files must load or fail with mocap::Error: never
// crash, hang or throw anything else. (The ASan CI configuration runs these too.)
#include "test_support.h"

#include "mocap/io/c3d_reader.h"
#include "mocap/base/error.h"
#include "mocap/base/file_io.h"

#include <gtest/gtest.h>

#include <algorithm>

#include <random>

namespace mocap {
namespace {

enum class Outcome { Loaded, Rejected };

Outcome tryParse(const std::string& bytes)
{
  try {
    (void)parseC3d(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(), "corrupt.c3d");
    return Outcome::Loaded;
  } catch (const Error&) {
    return Outcome::Rejected;
  }
}

const char* const kFiles[] = {"c3d/sample01/Eb015pi.c3d", "c3d/sample01/Eb015vr.c3d", "c3d/sample01/Eb015sr.c3d",
                              "c3d/sample13/Dance.c3d", "c3d/btk_others/mocap36.c3d",
                              "c3d/sample03/gait-pig-nz.c3d"};

TEST(C3dCorruption, TruncatedCopiesNeverCrash)
{
  for (const char* file : kFiles) {
    SCOPED_TRACE(file);
    const std::string bytes = readFileBytes(test::dataFile(file));
    int rejected = 0;
    for (std::size_t length = 0; length < bytes.size(); length += (length < 8192 ? 37 : 4099))
      rejected += tryParse(bytes.substr(0, length)) == Outcome::Rejected;
    EXPECT_GT(rejected, 0);
  }
}

TEST(C3dCorruption, TruncatedDataSectionKeepsTheCompleteFrames)
{
  const std::string bytes = readFileBytes(test::dataFile("c3d/sample01/Eb015pr.c3d"));
  const std::size_t frameBytes = (26 * 4 + 64) * 4;
  const std::size_t dataStart = 10 * 512;
  const std::string cut = bytes.substr(0, dataStart + 100 * frameBytes + frameBytes / 2);
  std::vector<std::string> warnings;
  const Take take = parseC3d(reinterpret_cast<const unsigned char*>(cut.data()), cut.size(), "cut.c3d", &warnings);
  EXPECT_EQ(take.frameCount(), 100);
  // Among the warnings (this Vicon file also has residual-0 samples, shown as filled).
  EXPECT_TRUE(std::any_of(warnings.begin(), warnings.end(),
                          [](const std::string& w) { return w.find("truncated") != std::string::npos; }));
}

TEST(C3dCorruption, ByteFlippedCopiesNeverCrash)
{
  std::mt19937 random(20261124);
  for (const char* file : kFiles) {
    SCOPED_TRACE(file);
    const std::string bytes = readFileBytes(test::dataFile(file));
    // Flip bytes mostly in the header and parameter section, where the structure lives.
    const std::size_t hot = std::min<std::size_t>(bytes.size(), 20 * 512);
    for (int trial = 0; trial < 400; ++trial) {
      std::string copy = bytes;
      const int flips = 1 + trial % 4;
      for (int i = 0; i < flips; ++i) {
        const std::size_t at = trial % 5 == 0 ? random() % copy.size() : random() % hot;
        copy[at] = static_cast<char>(random() & 0xFF);
      }
      (void)tryParse(copy);
    }
  }
}

TEST(C3dCorruption, TruncatedParameterSectionNamesTheByte)
{
  const std::string bytes = readFileBytes(test::dataFile("c3d/sample01/Eb015pi.c3d"));
  try {
    (void)parseC3d(reinterpret_cast<const unsigned char*>(bytes.data()), 1234, "short.c3d");
    FAIL() << "accepted a file cut inside its parameter section";
  } catch (const FormatError& e) {
    EXPECT_NE(std::string(e.what()).find("short.c3d: parameter section truncated at byte"), std::string::npos)
        << e.what();
  }
}

} // namespace
} // namespace mocap

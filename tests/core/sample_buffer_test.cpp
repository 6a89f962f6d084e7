#include "mocap/model/sample_buffer.h"

#include <gtest/gtest.h>

#include <numeric>

namespace mocap {
namespace {

TEST(SampleBuffer, CopyMoveAndResizeKeepContents)
{
  for (std::size_t count : {std::size_t{10}, std::size_t{3} << 20}) {  // small (malloc) and large (huge pages)
    SCOPED_TRACE(count);
    SampleBuffer<double> a(count);
    std::iota(a.data(), a.data() + count, 0.0);
    const SampleBuffer<double> copy(a);
    EXPECT_NE(copy.data(), a.data());
    EXPECT_EQ(copy.data()[count - 1], static_cast<double>(count - 1));
    SampleBuffer<double> moved(std::move(a));
    EXPECT_EQ(a.data(), nullptr);  // NOLINT(bugprone-use-after-move): moved-from state is documented
    EXPECT_EQ(a.size(), 0u);
    moved.resize(count + 5);
    EXPECT_EQ(moved.size(), count + 5);
    EXPECT_EQ(moved.data()[count - 1], static_cast<double>(count - 1));
    moved.resize(3);
    EXPECT_EQ(moved.data()[2], 2.0);
  }
}

TEST(SampleBuffer, CopyAssignmentOfTheSameSizeKeepsTheStorage)
{
  SampleBuffer<double> a(100), b(100), c(7);
  std::iota(a.data(), a.data() + 100, 1.0);
  double* const storage = b.data();
  b = a;
  EXPECT_EQ(b.data(), storage) << "a pointer into the buffer (a NumPy view) stays valid";
  EXPECT_EQ(b.data()[99], 100.0);
  c = a;
  EXPECT_EQ(c.size(), 100u);
  EXPECT_EQ(c.data()[0], 1.0);
}

TEST(SampleBuffer, LargeBlocksAreReusedAfterRelease)
{
  const std::size_t count = std::size_t{4} << 20;
  const double* first = nullptr;
  {
    SampleBuffer<double> a(count);
    first = a.data();
    a.data()[count - 1] = 1.0;
  }
  SampleBuffer<double> b(count);
  EXPECT_EQ(b.data(), first) << "a released large block should serve the next take of the same size";
  b.data()[count - 1] = 2.0;
  SampleBuffer<double> c(count);
  EXPECT_NE(c.data(), b.data());
}

} // namespace
} // namespace mocap

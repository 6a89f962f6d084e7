#include "test_support.h"

#include <gtest/gtest.h>

#include <random>

namespace mocap::test {

std::filesystem::path dataFile(const std::string& relative)
{
  return std::filesystem::path(MOCAP_TEST_DATA) / relative;
}

std::filesystem::path sampleTake()
{
  return std::filesystem::path(MOCAP_SAMPLE_DIR) / "Facial-Sing.c3d";
}

TempDir::TempDir()
{
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string name = info ? std::string(info->test_suite_name()) + "." + info->name() : "mocap";
  std::random_device random;
  m_path = std::filesystem::temp_directory_path() / ("mocap-test-" + name + "-" + std::to_string(random()));
  std::filesystem::create_directories(m_path);
}

TempDir::~TempDir()
{
  std::error_code ec;
  std::filesystem::remove_all(m_path, ec);
}

std::size_t entryCount(const std::filesystem::path& folder)
{
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(folder))
    ++n;
  return n;
}

} // namespace mocap::test

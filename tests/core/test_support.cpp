#include "test_support.h"

#include "mocap/base/file_io.h"
#include "mocap/io/obj_io.h"
#include "mocap/model/mesh.h"
#include "checkout_paths.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace mocap::test {

std::filesystem::path dataFile(const std::string& relative)
{
  return std::filesystem::path(checkout::testDataDir()) / relative;
}

std::filesystem::path sampleTake()
{
  return std::filesystem::path(checkout::sampleDir()) / "Facial-Sing.c3d";
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

void writeSmallRig(const TempDir& dir)
{
  const Mesh face = readObj(dataFile("face_mesh/canonical_face_model.obj"));
  writeObj(dir.file("neutral.obj"), face);
  std::filesystem::create_directory(dir.file("shapes"));
  const auto near = [&](Eigen::Index v, const Eigen::RowVector3d& centre, double radius) {
    return std::exp(-(face.vertices.row(v) - centre).squaredNorm() / (radius * radius));
  };
  MeshVertices jaw = face.vertices, brow = face.vertices, smile = face.vertices;
  for (Eigen::Index v = 0; v < face.vertexCount(); ++v) {
    // Below the lower lip (y −4.5 cm) the face opens down and back, fully at the chin (y −9.4).
    const double open = std::clamp((-4.5 - face.vertices(v, 1)) / 4.9, 0.0, 1.0);
    jaw(v, 1) -= 1.2 * open;
    jaw(v, 2) -= 0.3 * open;
    brow(v, 1) += 0.5 * near(v, Eigen::RowVector3d(0.0, 5.0, 5.3), 2.0);
    const double corner = near(v, face.vertices.row(291), 1.4);  // the left mouth corner
    smile(v, 0) += 0.4 * corner;
    smile(v, 1) += 0.3 * corner;
  }
  writeObj(dir.path() / "shapes" / "jawOpen.obj", face, jaw);
  writeObj(dir.path() / "shapes" / "browInnerUp.obj", face, brow);
  writeObj(dir.path() / "shapes" / "mouthSmile_L.obj", face, smile);
}

void writeCorruptC3d(const std::filesystem::path& to)
{
  std::string bytes = readFileBytes(dataFile("c3d/sample01/Eb015pi.c3d"));
  const std::size_t name = bytes.find("\x06\x01LABELS", 512);  // length 6, POINT's group id 1
  ASSERT_NE(name, std::string::npos);
  bytes.replace(name + 2, 6, std::string("\x01\x02\x03\x04\x05\x06", 6));
  writeFileAtomically(to, bytes);
}

std::size_t entryCount(const std::filesystem::path& folder)
{
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(folder))
    ++n;
  return n;
}

} // namespace mocap::test

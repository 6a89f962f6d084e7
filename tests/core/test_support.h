#pragma once

#include <filesystem>
#include <string>

namespace mocap::test {

/// Path of a file under tests/data.
[[nodiscard]] std::filesystem::path dataFile(const std::string& relative);

/// The bundled sample take (resources/sample/Facial-Sing.c3d).
[[nodiscard]] std::filesystem::path sampleTake();

/// A fresh, empty folder for one test, removed when the object goes away.
class TempDir
{
public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  [[nodiscard]] const std::filesystem::path& path() const { return m_path; }
  [[nodiscard]] std::filesystem::path file(const std::string& name) const { return m_path / name; }

private:
  std::filesystem::path m_path;
};

/// A rig of the MediaPipe face (tests/data, cm) with three shapes — jawOpen (the chin down and
/// back), browInnerUp (the inner brows up), mouthSmile_L (the left mouth corner out and up) —
/// written in ICT FaceKit's layout: `dir`/neutral.obj and `dir`/shapes/<name>.obj. The sample
/// binding fits its neutral.
void writeSmallRig(const TempDir& dir);

/// How many entries (files and folders) `folder` holds directly.
[[nodiscard]] std::size_t entryCount(const std::filesystem::path& folder);

} // namespace mocap::test

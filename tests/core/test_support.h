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

/// Writes to `to` a copy of c3d/sample01/Eb015pi.c3d whose parameter section is corrupt in its
/// middle (POINT:LABELS' record name overwritten with binary bytes), which every reader must refuse
/// with "parameter section corrupt". (sample18's file, once the fixture, reads with warnings.)
void writeCorruptC3d(const std::filesystem::path& to);

/// How many entries (files and folders) `folder` holds directly.
[[nodiscard]] std::size_t entryCount(const std::filesystem::path& folder);

} // namespace mocap::test

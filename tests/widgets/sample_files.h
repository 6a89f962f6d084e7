#pragma once

#include "checkout_paths.h"

#include <QImage>
#include <QString>

#include <Eigen/Core>

#include <filesystem>

namespace mocap::test {

/// A path as Qt takes it.
inline QString qpath(const std::filesystem::path& path)
{
  return QString::fromStdString(path.string());
}

/// The bundled sample's face mesh (the MediaPipe canonical face, resources/sample).
inline QString sampleMesh()
{
  return QString::fromUtf8(checkout::sampleDir()) + QStringLiteral("/canonical_face_model.obj");
}

/// The bundled binding of that mesh to the sample take.
inline QString sampleBinding()
{
  return QString::fromUtf8(checkout::sampleDir()) + QStringLiteral("/Facial-Sing.binding.json");
}

} // namespace mocap::test

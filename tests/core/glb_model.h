#pragma once

#include <gtest/gtest.h>

#include <tiny_gltf.h>

#include <string>

namespace mocap::test {

/// `glb` parsed by TinyGLTF's own loader, an independent reader of what our writer wrote; a
/// failed load is a test failure (and an empty model).
inline tinygltf::Model glbModel(const std::string& glb)
{
  tinygltf::Model model;
  std::string error, warning;
  EXPECT_TRUE(tinygltf::TinyGLTF().LoadBinaryFromMemory(&model, &error, &warning,
                                                         reinterpret_cast<const unsigned char*>(glb.data()),
                                                         static_cast<unsigned int>(glb.size())))
      << error;
  return model;
}

} // namespace mocap::test

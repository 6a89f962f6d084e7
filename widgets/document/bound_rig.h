#pragma once

#include "mocap/deform/mesh_binding.h"
#include "mocap/model/blendshape_rig.h"

#include <memory>

namespace mocap::ui {

/// A blendshape rig with the marker binding made on its neutral: what layouts are judged on (the
/// studio: the session's rig and its face mesh's binding). Empty when either is missing.
struct BoundRig
{
  std::shared_ptr<const BlendshapeRig> rig;
  MeshBinding binding;
};

} // namespace mocap::ui

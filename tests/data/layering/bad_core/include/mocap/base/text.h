#pragma once
// A deliberate layering break for the check_core_layers test: base may not include deform.
#include "mocap/deform/face_rig.h"

// The scene's lights (ScatteringRenderer::setLights), for every program that
// lights something. A uniform block, not a storage buffer: llvmpipe reads a
// storage buffer lane by lane even at an index every lane shares, and reading
// the lights so was a quarter of the surface pass. std140 lays out Light (two vec4) as std430 and C++ do.
#include "gpu_layout.h"
layout(std140, binding = kBindingLights) uniform Lights { Light lights[kMaxLights]; };

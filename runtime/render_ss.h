#pragma once
// `lucent render --method ss`: the scene's objects with their sample files,
// drawn offscreen by the ScatteringRenderer.
#include <string>
#include <vector>

#include "core/image.h"
#include "core/sample_set.h"
#include "core/scene.h"
#include "core/volume_object.h"
#include "runtime/offscreen_context.h"

namespace lucent {

struct SsSettings {
    GlBackend backend = GlBackend::Auto;
    bool surface = true;
    double cutoff = 1e-4;
};

// Reads an object's sample file and checks that it was made for this mesh and medium.
SampleSet loadSamplesFor(const VolumeObject& object);

// Reads each object's sample file (checking it belongs to the object) and renders.
// backendUsed receives the backend that served the frame.
Image renderSingleScattering(const SceneDesc& scene, const std::vector<VolumeObject>& objects,
                             const SsSettings& settings, std::string* backendUsed = nullptr);

}  // namespace lucent

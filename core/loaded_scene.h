#pragma once
// A scene ready for any method: its description, each object loaded (mesh,
// density, blockers) and, for the methods that draw from samples, each object's
// sample set, checked to have been made for that object's mesh and medium.
// This is the one place where sample sets meet objects: from sample files
// (lucent render, the viewer) or from memory (benchmarks, library hosts).
#include <string>
#include <vector>

#include <memory>

#include "core/environment_map.h"
#include "core/sample_set.h"
#include "core/scene.h"
#include "core/volume_object.h"

namespace lucent {

struct LoadedScene {
    SceneDesc desc;
    std::vector<VolumeObject> objects;
    std::vector<SampleSet> samples;                     // one per object, or empty when no method asked for them
    std::shared_ptr<const EnvironmentMap> environment;  // desc.environment's map, loaded
    std::vector<std::string> warnings;                  // for the caller to show ("lucent: warning: ...")

    // desc.lights and, with an environment, environmentDirections directional
    // lights drawn from it: what the methods without their own environment sampling render.
    std::vector<Light> lightsWithEnvironment(int environmentDirections) const {
        return withEnvironmentLights(desc.lights, environment.get(), environmentDirections);
    }
    bool hasSamples() const { return !objects.empty() && samples.size() == objects.size(); }
    Bounds3 bounds() const;  // of every object's boundary mesh
};

// Loads every object of desc; with withSampleFiles, also reads each object's
// sample file and checks it (Error naming the file otherwise).
LoadedScene loadScene(const SceneDesc& desc, bool withSampleFiles);

// Every file the scene reads: the scene file, meshes, blockers, grids and, with
// withSampleFiles, the sample files (what no output of a run may replace).
std::vector<std::filesystem::path> inputFilesOf(const SceneDesc& desc, bool withSampleFiles);

// Checks that samples were made for object (same fingerprint of mesh, blockers,
// grid and medium) and returns them; origin names them in the error.
SampleSet checkSamplesBelong(const VolumeObject& object, SampleSet samples, const std::string& origin);

// Gives the scene one sample set per object, made in memory (for example by
// preprocessObject), through the same check as a sample file.
void attachSamples(LoadedScene& scene, std::vector<SampleSet> samples);

}  // namespace lucent

#include "core/loaded_scene.h"

#include <utility>

#include "core/error.h"

namespace lucent {

Bounds3 LoadedScene::bounds() const {
    Bounds3 b;
    for (const VolumeObject& o : objects) {
        b.extend(o.mesh().bounds().min);
        b.extend(o.mesh().bounds().max);
    }
    return b;
}

std::vector<std::filesystem::path> inputFilesOf(const SceneDesc& desc, bool withSampleFiles) {
    std::vector<std::filesystem::path> files{desc.file};
    for (const ObjectDesc& o : desc.objects) {
        files.push_back(o.mesh);
        files.insert(files.end(), o.medium.blockers.begin(), o.medium.blockers.end());
        if (o.medium.density.type == DensityDesc::Type::Grid) files.push_back(o.medium.density.file);
        if (withSampleFiles) files.push_back(o.samples);
    }
    if (desc.environment) files.push_back(desc.environment->file);
    return files;
}

SampleSet checkSamplesBelong(const VolumeObject& object, SampleSet samples, const std::string& origin) {
    if (samples.sceneFingerprint != object.desc().fingerprint)
        throw Error(origin, "sample file was made for a different mesh or medium than object '" + object.desc().name +
                                "'; run lucent preprocess again");
    return samples;
}

LoadedScene loadScene(const SceneDesc& desc, bool withSampleFiles) {
    LoadedScene scene;
    scene.desc = desc;
    if (desc.environment) scene.environment = EnvironmentMap::load(*desc.environment);
    if (!withSampleFiles) {
        scene.objects = loadObjects(scene.desc, scene.warnings);
        return scene;
    }
    // The sample files first: one made for an object's present mesh file (same
    // fingerprint) holds that mesh as preprocessing checked it, so the mesh file
    // is not parsed again (parsing it took longer than reading the samples).
    // Parsing skipped, so are its warnings; preprocess told them. When a sample
    // file cannot be read, the meshes are loaded first all the same, so that a
    // mesh's error is told before a sample file's.
    std::vector<SampleSet> samples(desc.objects.size());
    std::vector<TriangleMesh> checkedMeshes(desc.objects.size());
    try {
        for (size_t i = 0; i < desc.objects.size(); ++i) {
            samples[i] = readSampleFile(desc.objects[i].samples);
            if (samples[i].sceneFingerprint == desc.objects[i].fingerprint)
                checkedMeshes[i] = std::move(samples[i].mesh);
            samples[i].mesh = TriangleMesh{};
        }
    } catch (const Error&) {
        scene.objects = loadObjects(scene.desc, scene.warnings);
        throw;
    }
    scene.objects = loadObjects(scene.desc, scene.warnings, std::move(checkedMeshes));
    for (size_t i = 0; i < samples.size(); ++i)
        samples[i] = checkSamplesBelong(scene.objects[i], std::move(samples[i]), desc.objects[i].samples.string());
    scene.samples = std::move(samples);
    return scene;
}

void attachSamples(LoadedScene& scene, std::vector<SampleSet> samples) {
    if (samples.size() != scene.objects.size())
        throw Error(scene.desc.file.string(), "got " + std::to_string(samples.size()) + " sample sets for " +
                                                  std::to_string(scene.objects.size()) + " objects");
    for (size_t i = 0; i < samples.size(); ++i)
        samples[i] = checkSamplesBelong(scene.objects[i], std::move(samples[i]),
                                        "in-memory samples of " + scene.objects[i].desc().name);
    scene.samples = std::move(samples);
}

}  // namespace lucent

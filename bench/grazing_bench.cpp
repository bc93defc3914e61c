// How far ss's drawing of optically thick objects falls from the reference as
// the light moves from in front of the object to behind it (issue 40: edges
// in the thick regime). Each pixel's ray is marched with the light's way
// through the medium read from maps of the mesh seen from the light
// (runtime/internal/optically_thick.frag): light that enters a face the camera
// does not see and leaves near the edge beside it is there, as far as the maps
// resolve it. The camera is the bundled torus-cube's; a point light circles the
// object at distance 4, from in front (0 degrees) over its +x side (90) to
// behind (180). The error is the relative RMSE 2 px inside the silhouette (as
// lit from the front), with the reference's brightness there against the
// front-lit image's; runtime/grazing_light.h takes its threshold from this table.
//
//   build/bin/lucent-bench-grazing [--size 128] [--record docs/results/grazing.md]
#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>

#include "bench/results_record.h"
#include "core/loaded_scene.h"
#include "preprocess/preprocessor.h"
#include "reference/reference_renderer.h"
#include "runtime/grazing_light.h"
#include "runtime/ss_method.h"

using namespace lucent;

namespace {

constexpr double kSigmaT = 80.0;  // 160 optical depths across the cube, 160 through the sphere

SceneDesc litFrom(const std::string& mesh, double degrees, int size) {
    SceneDesc scene;
    scene.camera.position = Vec3(0.0, 1.2, 5.0);
    scene.camera.width = scene.camera.height = size;
    const double a = glm::radians(degrees);
    Light light;
    light.position = Vec3(4.0 * std::sin(a), -0.3, 4.0 * std::cos(a));
    light.power = Rgb(60.0);
    scene.lights = {light};
    ObjectDesc o;
    o.name = mesh;
    o.mesh = std::string(LUCENT_SOURCE_DIR) + "/models/" + mesh;
    o.medium.sigmaT = Rgb(kSigmaT);
    o.medium.albedo = Rgb(0.9);
    scene.objects = {o};
    return scene;
}

// The pixels of the front-lit reference, 2 px inside its silhouette.
std::vector<bool> interior(const Image& frontLit) {
    const int w = frontLit.width, h = frontLit.height;
    std::vector<bool> inside(size_t(w) * h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            bool all = true;
            for (int dy = -2; dy <= 2 && all; ++dy)
                for (int dx = -2; dx <= 2 && all; ++dx) {
                    const int u = x + dx, v = y + dy;
                    all = u >= 0 && v >= 0 && u < w && v < h && frontLit.at(u, v).g > 0.0;
                }
            inside[size_t(y) * w + x] = all;
        }
    return inside;
}

struct Error {
    double relativeRmse = 0.0, brightness = 0.0;  // brightness: the truth's mean over the mask
};

Error errorOver(const Image& test, const Image& truth, const std::vector<bool>& mask) {
    double squared = 0.0, reference = 0.0, sum = 0.0;
    size_t n = 0;
    for (int y = 0; y < truth.height; ++y)
        for (int x = 0; x < truth.width; ++x) {
            if (!mask[size_t(y) * truth.width + x]) continue;
            for (int c = 0; c < 3; ++c) {
                const double r = truth.at(x, y)[c], d = test.at(x, y)[c] - r;
                squared += d * d;
                reference += r * r;
                sum += r;
            }
            ++n;
        }
    return {reference > 0.0 ? std::sqrt(squared / reference) : 0.0, n > 0 ? sum / (3.0 * n) : 0.0};
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"ss's closed form for optically thick objects against the reference, lit from in front to behind"};
    int size = 128;
    std::string record;
    app.add_option("--size", size, "Image width and height")->check(CLI::Range(16, 1024));
    app.add_option("--record", record, "Also write the results to this Markdown file (docs/results/)");
    CLI11_PARSE(app, argc, argv);
    try {
        ResultsRecord out(argc, argv);
        out.print(
            "ss (optically thick: no samples, each pixel's ray marched) against --method reference, sigma_t %g, albedo "
            "0.9, %dx%d, the torus-cube's camera, a point light at distance 4 from in front (0 degrees) over +x "
            "to behind (180). Lighting: runtime/grazing_light.h's mean cosine of the seen surface (ss warns "
            "above 0 and under %g). Error: relative RMSE 2 px inside the silhouette; brightness: the reference's mean "
            "there over the front-lit one's.\n\n",
            kSigmaT, size, size, kGrazingLight);
        out.tableHeader({"mesh", "light (degrees)", "lighting", "brightness", "error"},
                        {false, true, true, true, true});
        MethodSettings settings;
        settings.surface = false;
        ReferenceSettings reference;
        reference.surface = false;
        for (const std::string mesh : {"cube.obj", "sphere.obj"}) {
            std::vector<bool> mask;
            double frontBrightness = 0.0;
            for (const double degrees :
                 {0.0, 30.0, 60.0, 70.0, 72.0, 74.0, 75.0, 76.0, 80.0, 90.0, 105.0, 112.0, 120.0, 135.0}) {
                const SceneDesc scene = litFrom(mesh, degrees, size);
                std::fprintf(stderr, "lucent-bench-grazing: %s lit from %g degrees\n", mesh.c_str(), degrees);
                LoadedScene loaded = loadScene(scene, false);
                attachSamples(loaded, {preprocessObject(loaded.objects[0], qualityPreset("default"))});
                if (loaded.samples[0].parameters.scheme != SampleScheme::OpticallyThick)
                    throw std::runtime_error(mesh + " is not optically thick at sigma_t 80");
                const Image truth = ReferenceRenderer(scene, loaded.objects).render(reference);
                if (mask.empty()) mask = interior(truth);
                const Error e = errorOver(SsMethod(SsOptions{}).render(loaded, settings), truth, mask);
                if (frontBrightness == 0.0) frontBrightness = e.brightness;
                const double lighting =
                    seenSurfaceLighting(loaded.objects[0].mesh(), scene.camera.position, scene.lights);
                out.tableRow({mesh, formatted("%g", degrees), formatted("%.3f", lighting),
                              formatted("%.2g", e.brightness / frontBrightness),
                              formatted("%.1f%%", 100.0 * e.relativeRmse)});
            }
        }
        if (!record.empty()) out.write(record);
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "lucent-bench-grazing: %s\n", e.what());
        return 1;
    }
}

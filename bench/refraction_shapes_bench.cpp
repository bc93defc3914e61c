// ss and lbl at a refracting boundary on solids of every kind of surface:
// what --method auto's rule for refracting objects rests on (methods/
// method_table.cpp, docs/accuracy.md, What auto picks).
//
//   build/bin/lucent-bench-refraction-shapes --scad models/refraction/*.scad,models/cad/*.scad -o DIR
//       [--iors 1.33,1.5] [--albedo 0.8] [--g 0] [--optical-radii 0.5,2] [--spp 256] [--size 64]
//       [--record docs/results/refraction-shapes.md]
//
// Each OpenSCAD model is exported to a closed mesh (openscad) in DIR and set in
// the scene `lucent bench accuracy --scad` makes for it (bench/cgal_demo_meshes.h),
// preprocessed at default quality, at each optical radius. Per ior: the surface's shape
// (core/surface_shape.h) and what auto picks, ss against the refracting
// single-scattering reference, and lbl against --method path (rendered twice,
// its own noise taken out).
#include <CLI/CLI.hpp>

#include <cstdio>

#include "bench/cad_solids.h"
#include "bench/cgal_demo_meshes.h"
#include "bench/path_truth.h"
#include "bench/results_record.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/image_compare.h"
#include "core/loaded_scene.h"
#include "core/surface_shape.h"
#include "methods/method_table.h"
#include "preprocess/preprocessor.h"

using namespace lucent;

namespace {

struct Settings {
    std::vector<std::string> scad;
    std::string output;
    std::vector<double> iors{1.33, 1.5};
    double albedo = 0.8, g = 0.0;
    std::vector<double> opticalRadii{1.0};
    int spp = 256, size = 64;
};

std::string shapeName(const SurfaceShape& s) {
    if (!s.convex) return "concave";
    if (s.sharpestDegrees >= kCreaseDegrees) return "sharp edges";
    return smoothConvex(s) ? "smooth convex" : "flat faces";
}

void measureSolid(ResultsRecord& out, const Settings& s, const std::filesystem::path& mesh, double opticalRadius) {
    SceneDesc scene = parseScene(writeMeshScene(mesh, s.output, opticalRadius, s.size));
    ObjectDesc& object = scene.objects[0];
    object.medium.albedo = Rgb(s.albedo);
    object.medium.g = s.g;
    LoadedScene matched = loadScene(scene, false);
    // The samples do not depend on the ior: one set serves every row.
    const SampleSet samples = preprocessObject(matched.objects[0], qualityPreset("default"));
    const SurfaceShape shape = surfaceShape(matched.objects[0].objectMesh());
    MethodSettings settings;
    settings.surface = false;
    for (double ior : s.iors) {
        object.medium.ior = ior;
        LoadedScene loaded = loadScene(scene, false);
        attachSamples(loaded, {samples});
        const PathTruth truth = pathTruth(loaded, settings, s.spp);
        const Image single = renderWith(findMethod("reference"), loaded, settings);
        const Image ss = renderWith(findMethod("ss"), loaded, settings);
        const Image lbl = renderWith(findMethod("lbl"), loaded, settings);
        const NoisyReferenceError lblError = luminanceRelativeRmse(lbl, truth.a, truth.b);
        out.print("| %s | %g | %.2f | %s | %.0f | %.3f | %s | %.4f | %.4f | %.3f | %.4f | %.3f | %.1f |\n",
                  mesh.stem().c_str(), opticalRadius, ior, shapeName(shape).c_str(), shape.sharpestDegrees,
                  shape.largestFlatShare, chooseMethod(scene).method.c_str(), lblError.noise,
                  luminanceRelativeRmse(ss, single), meanLuminance(ss) / meanLuminance(single), lblError.debiased,
                  meanLuminance(lbl) / meanLuminance(truth.mean), truth.seconds);
    }
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"Lucent refraction-shapes benchmark: ss and lbl at a refracting boundary, per kind of surface"};
    Settings s;
    std::string record;
    app.add_option("--scad", s.scad, "OpenSCAD models (.scad), exported to closed meshes by openscad")
        ->delimiter(',')
        ->required();
    app.add_option("-o,--output", s.output, "Directory for the meshes and scenes")->required();
    app.add_option("--iors", s.iors, "Indices of refraction")->delimiter(',')->check(CLI::Range(1.0, 4.0));
    app.add_option("--albedo", s.albedo, "Albedo of the media")->check(CLI::Range(0.0, 1.0));
    app.add_option("--g", s.g, "Henyey-Greenstein g of the media")->check(CLI::Range(-0.99, 0.99));
    app.add_option("--optical-radii", s.opticalRadii, "sigma_t times the smallest half-extent of each mesh's box")
        ->delimiter(',')
        ->check(CLI::Range(1e-3, 1e3));
    app.add_option("--spp", s.spp, "Paths per pixel of the ground truth")->check(CLI::Range(1, 1 << 20));
    app.add_option("--size", s.size, "Image width and height")->check(CLI::Range(8, 2048));
    app.add_option("--record", record, "Also write the results to this Markdown file (docs/results/)");
    CLI11_PARSE(app, argc, argv);
    try {
        if (!record.empty()) checkWritable(record);
        std::filesystem::create_directories(s.output);
        ResultsRecord out(argc, argv);
        out.print(
            "each model at each optical radius (sigma_t times its box's smallest half-extent), albedo %.2f, g %.2f, "
            "one point light, %dx%d, no surface term: its surface's shape (core/surface_shape.h: the sharpest "
            "bend between faces in degrees, the largest flat patch's share of the area) and what --method auto "
            "picks; ss against --method reference (single scattering, refracting) and lbl against --method path "
            "at %d paths per pixel (its noise taken out), relative RMSE of luminance and mean ratio\n\n",
            s.albedo, s.g, s.size, s.size, s.spp);
        out.tableHeader({"model", "optical radius", "ior", "surface", "sharpest (deg)", "flat share", "auto",
                         "path noise", "ss vs single", "ss mean ratio", "lbl", "lbl mean ratio", "path (s)"},
                        {false, true, true, false, true, true, false, true, true, true, true, true, true});
        for (const std::string& scad : s.scad) {
            const std::filesystem::path mesh = exportScadSolid(scad, s.output);
            for (double opticalRadius : s.opticalRadii) measureSolid(out, s, mesh, opticalRadius);
        }
        if (!record.empty()) out.write(record);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "lucent-bench-refraction-shapes: error: %s\n", e.what());
        return 1;
    }
    return 0;
}

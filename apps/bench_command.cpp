#include <cstdio>
#include <memory>

#include "apps/commands.h"
#include "core/run_program.h"
#include "bench/accuracy_sweep.h"
#include "bench/cad_solids.h"
#include "bench/cgal_demo_meshes.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "preprocess/preprocessor.h"

namespace lucent {

Command addBenchCommand(CLI::App& app) {
    struct Options {
        std::vector<std::string> scenes, knobs, cgal, scad;
        double opticalRadius = 1.0;
        std::string output = "bench-accuracy", backend, quality = "default", record;
        int size = 0, frames = 7;
        double tolerance = 1e-3;
        bool plot = true;
    };
    auto o = std::make_shared<Options>();
    CLI::App* bench = app.add_subcommand("bench", "Speed/accuracy sweeps (docs/accuracy.md)");
    bench->require_subcommand(1);
    CLI::App* sub =
        bench->add_subcommand("accuracy",
                              "Sweep each quality knob; record preprocessing time, median frame time and error against "
                              "--method reference; write CSV and the error-versus-time plots");
    sub->add_option("scenes", o->scenes, "Scene files");
    sub->add_option("--cgal", o->cgal,
                    "Meshes of CGAL's demo data (Debian's libcgal-demo), each in a scene made for it: elephant, "
                    "eight, fandisk, ...")
        ->delimiter(',');
    sub->add_option("--scad", o->scad,
                    "OpenSCAD models (.scad, for example models/cad/*.scad), exported to closed meshes by openscad, "
                    "each in a scene made for it as the --cgal meshes are")
        ->delimiter(',');
    sub->add_option("--optical-radius", o->opticalRadius,
                    "sigma_t times the smallest half-extent of each --cgal or --scad mesh's box (default 1)")
        ->check(finiteRange(1e-3, 1e3));
    sub->add_option("-o,--output", o->output, "Directory for accuracy.csv and the plots");
    std::string knobHelp = "Knobs to sweep (default all):";
    for (const std::string& k : accuracyKnobNames()) knobHelp += " " + k;
    sub->add_option("--knobs", o->knobs, knobHelp)->delimiter(',');
    sub->add_option("--size", o->size, "Image width and height (default: each scene camera's)")
        ->check(CLI::Range(8, 4096));
    sub->add_option("--frames", o->frames, "Timed frames per setting (median reported)")->check(CLI::Range(1, 1000));
    sub->add_option("--tolerance", o->tolerance, "Quadrature tolerance of the reference")
        ->check(finiteRange(1e-8, 0.5));
    sub->add_option("--quality", o->quality, "Preset the knobs move away from: draft, default or high")
        ->check(CLI::IsMember({"draft", "default", "high"}));
    sub->add_option("--backend", o->backend, "osmesa or egl")->check(CLI::IsMember({"osmesa", "egl"}));
    sub->add_flag("!--no-plot", o->plot, "Write the CSV only (the plots need python3-matplotlib)");
    sub->add_option("--record", o->record, "Also write the results as a Markdown table to this file (docs/results/)");
    return [o] {
        AccuracyBenchOptions options;
        options.knobs = o->knobs;
        options.size = o->size;
        options.frames = o->frames;
        options.referenceTolerance = o->tolerance;
        options.backend = parseGlBackend(o->backend);
        options.base = qualityPreset(o->quality);
        accuracySweep(options.knobs, options.base);  // rejects an unknown knob before any work
        if (!o->record.empty()) checkWritable(o->record);
        std::vector<std::filesystem::path> scenes(o->scenes.begin(), o->scenes.end());
        std::filesystem::create_directories(o->output);
        const std::filesystem::path cgalDir = std::filesystem::path(o->output) / "cgal",
                                    cadDir = std::filesystem::path(o->output) / "cad";
        auto addMeshScene = [&](const std::filesystem::path& mesh) {
            scenes.push_back(writeMeshScene(mesh, mesh.parent_path(), o->opticalRadius, o->size > 0 ? o->size : 256));
        };
        for (const std::string& name : o->cgal) addMeshScene(extractCgalDemoMesh(name, cgalDir));
        for (const std::string& model : o->scad) addMeshScene(exportScadSolid(model, cadDir));
        if (scenes.empty()) throw Error("lucent bench accuracy: give scene files, --cgal meshes or --scad models");
        const std::filesystem::path csv = std::filesystem::path(o->output) / "accuracy.csv";
        const std::vector<SweepRow> rows = runAccuracyBench(scenes, options, csv);
        std::fprintf(stderr, "lucent: wrote %s\n", csv.string().c_str());
        if (!o->record.empty()) recordAccuracyBench(rows, options).write(o->record);
        if (!o->plot) return;
        const std::filesystem::path script = installedDataFile("plot-accuracy.py");
        if (runProgram({script.string(), csv.string(), o->output}) != 0)  // its #! line picks Debian's python3
            throw Error(csv.string(),
                        "plotting failed (python3-matplotlib missing? scripts/install-deps.sh installs it)");
    };
}

}  // namespace lucent

#include "bench/cad_solids.h"

#include <string>
#include <system_error>

#include "core/error.h"
#include "core/input_file.h"
#include "core/run_program.h"

namespace lucent {

std::filesystem::path exportScadSolid(const std::filesystem::path& scad, const std::filesystem::path& dir) {
    if (scad.extension() != ".scad") throw Error(scad.string(), "an OpenSCAD model ends in .scad");
    regularFileSize(scad, "OpenSCAD model");
    std::filesystem::create_directories(dir);
    const std::string stem = scad.stem().string();
    // Absolute paths begin with '/', so that openscad never reads a path as one of its options.
    const std::filesystem::path model = std::filesystem::absolute(scad),
                                out = std::filesystem::absolute(dir / (stem + ".stl"));
    // openscad picks the format by the extension, so the partial file ends in .stl too.
    const std::filesystem::path partial = std::filesystem::absolute(dir / (stem + ".partial.stl")),
                                log = dir / (stem + ".openscad.log");
    int status = 0;
    try {
        status = runProgram({"openscad", "-q", "-o", partial.string(), model.string()}, log);
    } catch (const Error& e) {
        throw Error(scad.string(), std::string("openscad: ") + e.what() + " (scripts/install-deps.sh installs it)");
    }
    if (status != 0) {
        std::error_code ignored;
        std::filesystem::remove(partial, ignored);
        throw Error(scad.string(),
                    "openscad failed with exit code " + std::to_string(status) + " (see " + log.string() + ")");
    }
    std::filesystem::rename(partial, out);
    return out;
}

}  // namespace lucent

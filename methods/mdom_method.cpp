#include "methods/mdom_method.h"

#include <cmath>
#include <cstdio>

#include "hybrid/mdom_scattering.h"
#include "runtime/ss_method.h"

namespace lucent {

std::vector<std::string> MdomMethod::limitations(const LoadedScene& scene) const {
    std::vector<std::string> out = SsMethod().limitations(scene);
    for (const VolumeObject& o : scene.objects) {
        const MediumDesc& m = o.desc().medium;
        if (m.ior != 1.0)
            out.push_back("object '" + o.desc().name +
                          "': ior differs from 1: mdom marches light in straight lines (thesis 5.2), index-matched");
        if (std::abs(m.g) > 0.5)
            out.push_back("object '" + o.desc().name +
                          "': |g| > 0.5: mdom keeps 16 moments of the scattered light, measured 18-21% from the path "
                          "tracer at g 0.8 (--method path is the ground truth)");
    }
    return out;
}

Image MdomMethod::render(const LoadedScene& scene, const MethodSettings& settings) {
    hybrid::MdomScattering solver;
    hybrid::MdomSettings ms;
    ms.resolution = settings.gridResolution;
    ms.directions = settings.directions;
    ms.bands = int(std::lround(std::sqrt(double(settings.moments))));
    std::vector<ScatteringGrid> grids;
    for (const VolumeObject& object : scene.objects) {
        hybrid::MdomStats stats;
        grids.push_back(solver.solve(object, scene.desc.lights, ms, &stats).towards(scene.desc.camera.position));
        const auto& d = grids.back().dims;
        std::fprintf(stderr,
                     "lucent: mdom: object '%s': %dx%dx%d voxels, %d directions, %d moments, %d iterations%s: direct %.2f s, "
                     "sweeps %.2f s (voxelised in %.2f s)\n",
                     object.desc().name.c_str(), d[0], d[1], d[2], ms.directions, settings.moments, stats.iterations,
                     stats.converged ? "" : " (not converged)", stats.directSeconds, stats.sweepSeconds,
                     stats.voxeliseSeconds);
    }
    std::string backend;
    Image image = renderSingleScattering(scene, settings, grids, backend);
    servedBy_ = backend + " + OpenCL '" + solver.deviceName() + "'";
    return image;
}

}  // namespace lucent

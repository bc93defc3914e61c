#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include "apps/commands.h"
#include "core/sample_set.h"

namespace lucent {
namespace {

struct Stats {
    double min = HUGE_VAL, max = -HUGE_VAL, sum = 0;
    size_t n = 0;
    void add(double v) {
        min = std::min(min, v);
        max = std::max(max, v);
        sum += v;
        ++n;
    }
    void print(const char* label) const {
        if (n) std::printf("  %-22s min %-12.5g mean %-12.5g max %.5g\n", label, min, sum / double(n), max);
    }
};

}  // namespace

Command addInfoCommand(CLI::App& app) {
    auto file = std::make_shared<std::string>();
    CLI::App* sub = app.add_subcommand("info", "Describe what a sample file holds");
    sub->add_option("file", *file, "Sample file (.lsf)")->required();
    return [file] {
        const SampleSet s = readSampleFile(*file);
        const SampleParameters& p = s.parameters;
        std::printf("%s: Lucent sample file, version %u\n", file->c_str(), kSampleFileVersion);
        std::printf("  samples                %zu\n", s.size());
        std::printf("  SH order               %u (%u coefficients x %u channel%s)\n", s.shOrder, s.shOrder * s.shOrder,
                    s.channels, s.channels > 1 ? "s" : "");
        std::printf("  bounds                 [%g %g %g] - [%g %g %g]\n", s.bounds.min.x, s.bounds.min.y,
                    s.bounds.min.z, s.bounds.max.x, s.bounds.max.y, s.bounds.max.z);
        std::printf("  scene fingerprint      %016llx\n", (unsigned long long)s.sceneFingerprint);
        std::printf("  seed                   %llu\n", (unsigned long long)p.seed);
        std::printf("  directions             %u heuristic, %u projection\n", p.heuristicDirections,
                    p.projectionDirections);
        std::printf("  layers                 %u, spacing %g\n", p.layerCount, p.layerSpacing);
        std::printf("  mean Poisson radius    %g\n", p.meanRadius);
        std::printf("  width factor           %g (Gaussian FWHM / radius)\n", p.widthFactor);
        std::printf("  cull epsilon           %g\n", p.cullEpsilon);
        std::printf("  placement scale        %g (the optical size it was made for)\n", p.placementScale);
        std::printf("  scheme                 %s\n", p.scheme == SampleScheme::Published ? "published (thesis 3.3)"
                                                     : p.scheme == SampleScheme::OpticallyThick
                                                         ? "optically thick (each pixel's ray marched, no samples)"
                                                         : "lucent");
        Stats radius, width, weight, dc, error, share, curvature;
        const size_t stride = s.coefficientsPerSample();
        const std::vector<float>& sh = s.coefficients();  // read from the sample file here, once
        for (size_t i = 0; i < s.size(); ++i) {
            radius.add(s.radii[i]);
            width.add(s.widths[i]);
            weight.add(s.weights[i]);
            // Y_00 = 1 / (2 sqrt(pi)): the mean over directions of what the SH hold is c_00 / (2 sqrt(pi)).
            dc.add(sh[i * stride] / (2.0 * std::sqrt(3.14159265358979323846)));
            error.add(s.truncationError[i]);
            if (s.boundary[i].valid()) {
                share.add(s.boundary[i].share);
                curvature.add(s.boundary[i].curvature);
            }
        }
        // Thin parts widen a Gaussian beyond FWHM = widthFactor * radius (thesis 3.3.2; docs/accuracy.md, Thin parts).
        size_t widened = 0;
        double mostWidening = 1.0;
        for (size_t i = 0; i < s.size(); ++i) {
            const double widening = s.widths[i] * 2.0 * std::sqrt(2.0 * std::log(2.0)) / (p.widthFactor * s.radii[i]);
            widened += widening > 1.01;
            mostWidening = std::max(mostWidening, widening);
        }
        if (p.scheme == SampleScheme::Lucent)
            std::printf("  widened in thin parts  %zu of %zu samples (%.1f%%), up to %.2f times\n", widened, s.size(),
                        s.size() ? 100.0 * double(widened) / double(s.size()) : 0.0, mostWidening);
        radius.print("Poisson radius");
        width.print("Gaussian sigma");
        weight.print("weight w");
        dc.print("SH mean");
        share.print("boundary ball share");
        curvature.print("boundary curvature");
        error.print("missed by ball and SH");
    };
}

}  // namespace lucent

#include <cstdio>

#include "apps/commands.h"
#include "core/medium_presets.h"

namespace lucent {

// The material presets with their published coefficients (core/medium_presets.h)
// and the medium each becomes: sigma_t per mm, albedo, and the one g Lucent uses.
Command addPresetsCommand(CLI::App& app) {
    app.add_subcommand("presets",
                       "List the measured materials a scene's medium can name with \"preset\" "
                       "(docs/scene-file.md)");
    return [] {
        std::printf("%-27s %-16s %-27s %-27s %-21s %-27s %-21s %s\n", "preset", "source", "sigma_s (1/mm)",
                    "sigma_a (1/mm)", "g", "sigma_t (1/mm)", "albedo", "g used");
        auto rgb = [](const Rgb& c, const char* format) {
            static char text[3][96];
            static int slot = 0;
            slot = (slot + 1) % 3;
            std::snprintf(text[slot], sizeof text[slot], format, c.r, c.g, c.b);
            return text[slot];
        };
        for (const MediumPreset& p : mediumPresets()) {
            std::printf("%-27s %-16s %-27s %-27s ", p.name, p.source, rgb(p.sigmaS, "%.6g %.6g %.6g"),
                        rgb(p.sigmaA, "%.6g %.6g %.6g"));
            std::printf("%-21s %-27s ", rgb(p.g, "%.3f %.3f %.3f"), rgb(p.sigmaT(), "%.6g %.6g %.6g"));
            std::printf("%-21s %.3f\n", rgb(p.albedo(), "%.5f %.5f %.5f"), p.meanG());
        }
    };
}

}  // namespace lucent

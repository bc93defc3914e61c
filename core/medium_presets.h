#pragma once
// Published scattering coefficients of real materials, per colour channel, in
// mm^-1: Jensen et al. 2001 ("A Practical Model for Subsurface Light
// Transport", SIGGRAPH, figure 5: reduced scattering and absorption) and
// Narasimhan et al. 2006 ("Acquiring Scattering Properties of Participating
// Media by Dilution", SIGGRAPH, table 1: scattering, absorption and the
// Henyey-Greenstein g of each medium at full concentration). docs/scene-file.md
// says what each source assumes.
#include <optional>
#include <string>
#include <vector>

#include "core/math.h"

namespace lucent {

struct MediumPreset {
    const char* name;
    const char* source;  // "Jensen 2001" or "Narasimhan 2006"
    Rgb sigmaS, sigmaA;  // mm^-1; Jensen's sigma_s is the reduced sigma_s' (g = 0 below)
    Rgb g;               // per channel; 0 where only reduced coefficients were published

    // What a Lucent medium takes: one g for all channels, the channels' g
    // weighted by their scattering (a channel that does not scatter has no say).
    Rgb sigmaT() const { return sigmaS + sigmaA; }
    Rgb albedo() const;
    double meanG() const;
};

const std::vector<MediumPreset>& mediumPresets();
const MediumPreset* findMediumPreset(const std::string& name);
std::string mediumPresetNames();  // "apple, chicken1, ..." for error messages

// Millimetres per scene unit for the scene's "units" key ("mm", "cm", "m").
std::optional<double> millimetresPerUnit(const std::string& units);

}  // namespace lucent

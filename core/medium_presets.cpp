#include "core/medium_presets.h"

namespace lucent {

Rgb MediumPreset::albedo() const {
    const Rgb t = sigmaT();
    return Rgb(t.r > 0.0 ? sigmaS.r / t.r : 0.0, t.g > 0.0 ? sigmaS.g / t.g : 0.0, t.b > 0.0 ? sigmaS.b / t.b : 0.0);
}

double MediumPreset::meanG() const {
    const double s = sigmaS.r + sigmaS.g + sigmaS.b;
    return s > 0.0 ? (sigmaS.r * g.r + sigmaS.g * g.g + sigmaS.b * g.b) / s : 0.0;
}

const std::vector<MediumPreset>& mediumPresets() {
    static const std::vector<MediumPreset> presets = {
        // Jensen et al. 2001, figure 5: sigma_s' and sigma_a in mm^-1 (R, G, B).
        {"apple", "Jensen 2001", Rgb(2.29, 2.39, 1.97), Rgb(0.0030, 0.0034, 0.046), Rgb(0.0)},
        {"chicken1", "Jensen 2001", Rgb(0.15, 0.21, 0.38), Rgb(0.015, 0.077, 0.19), Rgb(0.0)},
        {"chicken2", "Jensen 2001", Rgb(0.19, 0.25, 0.32), Rgb(0.018, 0.088, 0.20), Rgb(0.0)},
        {"cream", "Jensen 2001", Rgb(7.38, 5.47, 3.15), Rgb(0.0002, 0.0028, 0.0163), Rgb(0.0)},
        {"ketchup", "Jensen 2001", Rgb(0.18, 0.07, 0.03), Rgb(0.061, 0.97, 1.45), Rgb(0.0)},
        {"marble", "Jensen 2001", Rgb(2.19, 2.62, 3.00), Rgb(0.0021, 0.0041, 0.0071), Rgb(0.0)},
        {"potato", "Jensen 2001", Rgb(0.68, 0.70, 0.55), Rgb(0.0024, 0.0090, 0.12), Rgb(0.0)},
        {"skimmilk", "Jensen 2001", Rgb(0.70, 1.22, 1.90), Rgb(0.0014, 0.0025, 0.0142), Rgb(0.0)},
        {"skin1", "Jensen 2001", Rgb(0.74, 0.88, 1.01), Rgb(0.032, 0.17, 0.48), Rgb(0.0)},
        {"skin2", "Jensen 2001", Rgb(1.09, 1.59, 1.79), Rgb(0.013, 0.070, 0.145), Rgb(0.0)},
        {"spectralon", "Jensen 2001", Rgb(11.6, 20.4, 14.9), Rgb(0.0), Rgb(0.0)},
        {"wholemilk", "Jensen 2001", Rgb(2.55, 3.21, 3.77), Rgb(0.0011, 0.0024, 0.014), Rgb(0.0)},
        // Narasimhan et al. 2006, table 1: sigma_s, sigma_a in mm^-1 and g (R, G, B).
        {"lowfat-milk", "Narasimhan 2006", Rgb(13.1157, 15.4445, 17.9572), Rgb(0.00287, 0.00575, 0.01150),
         Rgb(0.932, 0.902, 0.859)},
        {"reduced-milk", "Narasimhan 2006", Rgb(13.7335, 15.6003, 17.8007), Rgb(0.00256, 0.00511, 0.01278),
         Rgb(0.819, 0.797, 0.746)},
        {"regular-milk", "Narasimhan 2006", Rgb(18.2052, 20.3826, 22.3698), Rgb(0.00153, 0.00460, 0.01993),
         Rgb(0.750, 0.714, 0.681)},
        {"espresso", "Narasimhan 2006", Rgb(7.78262, 8.13050, 8.53875), Rgb(4.79838, 6.57512, 8.84925),
         Rgb(0.907, 0.896, 0.880)},
        {"mint-mocha-coffee", "Narasimhan 2006", Rgb(3.51133, 4.14383, 5.59667), Rgb(3.77200, 5.82283, 7.82000),
         Rgb(0.910, 0.907, 0.914)},
        {"lowfat-soy-milk", "Narasimhan 2006", Rgb(2.03838, 2.32875, 3.90281), Rgb(0.00144, 0.00719, 0.03594),
         Rgb(0.850, 0.853, 0.842)},
        {"regular-soy-milk", "Narasimhan 2006", Rgb(4.66325, 5.20183, 8.74575), Rgb(0.00192, 0.00958, 0.06517),
         Rgb(0.873, 0.858, 0.832)},
        {"lowfat-chocolate-milk", "Narasimhan 2006", Rgb(9.83710, 11.4954, 13.1629), Rgb(0.01150, 0.03680, 0.15640),
         Rgb(0.934, 0.927, 0.916)},
        {"regular-chocolate-milk", "Narasimhan 2006", Rgb(10.5685, 13.1416, 15.2202), Rgb(0.01006, 0.04313, 0.14375),
         Rgb(0.862, 0.838, 0.806)},
        {"coke", "Narasimhan 2006", Rgb(0.00254, 0.00299, 0.0), Rgb(0.10014, 0.16503, 0.24680), Rgb(0.965, 0.972, 0.0)},
        {"pepsi", "Narasimhan 2006", Rgb(0.00083, 0.00203, 0.0), Rgb(0.09164, 0.14158, 0.20729),
         Rgb(0.926, 0.979, 0.0)},
        {"sprite", "Narasimhan 2006", Rgb(0.00011, 0.00014, 0.00014), Rgb(0.00189, 0.00183, 0.00200),
         Rgb(0.943, 0.953, 0.952)},
        {"gatorade", "Narasimhan 2006", Rgb(0.03668, 0.04488, 0.05742), Rgb(0.02479, 0.01929, 0.00888),
         Rgb(0.933, 0.933, 0.935)},
        {"chardonnay", "Narasimhan 2006", Rgb(0.00021, 0.00033, 0.00048), Rgb(0.01078, 0.01186, 0.02400),
         Rgb(0.914, 0.958, 0.975)},
        {"white-zinfandel", "Narasimhan 2006", Rgb(0.00022, 0.00033, 0.00046), Rgb(0.01207, 0.01618, 0.01984),
         Rgb(0.919, 0.943, 0.972)},
        {"merlot", "Narasimhan 2006", Rgb(0.00081, 0.0, 0.0), Rgb(0.11632, 0.25191, 0.29434), Rgb(0.974, 0.0, 0.0)},
        {"budweiser-beer", "Narasimhan 2006", Rgb(0.00029, 0.00055, 0.00059), Rgb(0.01149, 0.02491, 0.05779),
         Rgb(0.917, 0.956, 0.982)},
        {"coors-light-beer", "Narasimhan 2006", Rgb(0.00062, 0.00127, 0.0), Rgb(0.00616, 0.01398, 0.03498),
         Rgb(0.918, 0.966, 0.0)},
        {"clorox", "Narasimhan 2006", Rgb(0.02731, 0.03302, 0.03695), Rgb(0.00335, 0.01489, 0.02630),
         Rgb(0.912, 0.905, 0.892)},
        {"apple-juice", "Narasimhan 2006", Rgb(0.00257, 0.00311, 0.00413), Rgb(0.01296, 0.02374, 0.05218),
         Rgb(0.947, 0.949, 0.945)},
        {"cranberry-juice", "Narasimhan 2006", Rgb(0.00196, 0.00238, 0.00301), Rgb(0.03944, 0.09422, 0.12426),
         Rgb(0.947, 0.951, 0.974)},
        {"grape-juice", "Narasimhan 2006", Rgb(0.00138, 0.0, 0.0), Rgb(0.10404, 0.23958, 0.29325),
         Rgb(0.961, 0.0, 0.0)},
        {"ruby-grapefruit-juice", "Narasimhan 2006", Rgb(0.15496, 0.15391, 0.15995), Rgb(0.08587, 0.18314, 0.25262),
         Rgb(0.929, 0.929, 0.931)},
        {"white-grapefruit-juice", "Narasimhan 2006", Rgb(0.50499, 0.52742, 0.75282), Rgb(0.01380, 0.01883, 0.05678),
         Rgb(0.548, 0.545, 0.565)},
        {"shampoo", "Narasimhan 2006", Rgb(0.00797, 0.00874, 0.01127), Rgb(0.01411, 0.04569, 0.06172),
         Rgb(0.910, 0.905, 0.920)},
        {"strawberry-shampoo", "Narasimhan 2006", Rgb(0.00215, 0.00245, 0.00253), Rgb(0.01449, 0.05796, 0.07582),
         Rgb(0.927, 0.935, 0.994)},
        {"head-and-shoulders-shampoo", "Narasimhan 2006", Rgb(0.26747, 0.27696, 0.29574),
         Rgb(0.08462, 0.15688, 0.20365), Rgb(0.911, 0.896, 0.884)},
        {"lemon-tea-powder", "Narasimhan 2006", Rgb(0.74489, 0.83823, 1.00158), Rgb(2.42881, 4.57573, 7.21270),
         Rgb(0.946, 0.946, 0.949)},
        {"orange-powder", "Narasimhan 2006", Rgb(0.00193, 0.00213, 0.00226), Rgb(0.00145, 0.00344, 0.00786),
         Rgb(0.919, 0.918, 0.922)},
        {"pink-lemonade-powder", "Narasimhan 2006", Rgb(0.00123, 0.00133, 0.00131), Rgb(0.00116, 0.00237, 0.00320),
         Rgb(0.902, 0.902, 0.904)},
        {"cappuccino-powder", "Narasimhan 2006", Rgb(12.2094, 16.4659, 29.2727), Rgb(35.8441, 49.5470, 61.0844),
         Rgb(0.849, 0.843, 0.926)},
        {"salt-powder", "Narasimhan 2006", Rgb(0.13805, 0.15677, 0.17865), Rgb(0.28415, 0.32570, 0.34148),
         Rgb(0.802, 0.793, 0.821)},
        {"sugar-powder", "Narasimhan 2006", Rgb(0.00282, 0.00315, 0.00393), Rgb(0.01264, 0.03105, 0.05012),
         Rgb(0.921, 0.919, 0.931)},
        {"suisse-mocha-powder", "Narasimhan 2006", Rgb(30.0848, 33.4452, 38.7191), Rgb(17.5020, 27.0044, 35.4334),
         Rgb(0.907, 0.894, 0.888)},
        {"pacific-ocean-surface-water", "Narasimhan 2006", Rgb(0.00180, 0.00183, 0.00228),
         Rgb(0.03184, 0.03132, 0.03015), Rgb(0.902, 0.825, 0.914)},
    };
    return presets;
}

const MediumPreset* findMediumPreset(const std::string& name) {
    for (const MediumPreset& p : mediumPresets())
        if (name == p.name) return &p;
    return nullptr;
}

std::string mediumPresetNames() {
    std::string names;
    for (const MediumPreset& p : mediumPresets()) names += (names.empty() ? "" : ", ") + std::string(p.name);
    return names;
}

std::optional<double> millimetresPerUnit(const std::string& units) {
    if (units == "mm") return 1.0;
    if (units == "cm") return 10.0;
    if (units == "m") return 1000.0;
    return std::nullopt;
}

}  // namespace lucent

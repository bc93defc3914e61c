#pragma once
// What the viewer shows and the user (or a script) changes: camera, lights,
// where each object stands, its index of refraction, albedo and g, medium scale, passes, exposure.
#include <cmath>
#include <string>
#include <vector>

#include "core/scene.h"
#include "viewer/orbit_camera.h"

namespace lucent {

struct ViewerState {
    explicit ViewerState(const SceneDesc& scene)
        : camera(scene.camera),
          lights(scene.lights),
          hasEnvironment(scene.environment.has_value()),
          environmentScale(scene.environment ? scene.environment->scale : 1.0),
          background(scene.render.background) {
        for (const ObjectDesc& o : scene.objects) {
            placements.push_back(o.transform);
            iors.push_back(o.medium.ior);
            albedos.push_back(o.medium.albedo);
            gs.push_back(o.medium.g);
        }
    }
    OrbitCamera camera;
    std::vector<Light> lights;
    // The scene's environment light, drawn as ss draws it (directional lights
    // drawn from its map): its scale, and a turn about +y on top of the scene's
    // rotation, which `environment scale S`, `environment turn DEGREES` and the panel change.
    bool hasEnvironment = false;
    double environmentScale = 1.0, environmentTurnDegrees = 0.0;
    // The map drawn behind the objects and through them, as ss draws it with
    // "background": true (core/environment_background.h); `background on|off` and the panel.
    bool background = false;
    // A map file `environment load FILE` (or the panel) asks for: loaded before
    // the next frame in place of the scene's, or the first; when it cannot be
    // read, a warning says why and the environment stays as it was.
    std::string environmentToLoad;
    // Each object's placement, from the scene's transforms; the selected one is
    // what `move`, `rotate` and `scale` (and the panel) change.
    std::vector<Similarity> placements;
    size_t selected = 0;
    bool placementsChanged = false;
    // Each object's refractive index, from the scene; `ior` (and the panel) change the selected one's.
    std::vector<double> iors;
    bool iorsChanged = false;
    // Each object's albedo and Henyey-Greenstein g, from the scene; `albedo` and `g` (and the
    // panel) change the selected one's. The samples do not depend on them: no new preprocessing.
    std::vector<Rgb> albedos;
    std::vector<double> gs;
    bool mediaChanged = false;
    float extinctionScale = 1.0f;
    bool surface = true, scattering = true;
    // Each sample's light traced through the objects (DrawOptions::tracedLight)
    // or read from its SH.
    bool tracedLight = true;
    // Multiple scattering added by a hybrid's grids, solved again when the
    // lights change: lbl (docs/hybrid.md) at once, mdom (docs/mdom.md) one
    // iteration per frame, each shown as it comes.
    enum class Multiple { Off, Lbl, Mdom };
    Multiple multiple = Multiple::Off;
    bool waiting = false;  // a script's `wait`: no further script line until the solve is done
    // Exposure in stops: the display multiplies radiance by 2^stops. NaN: pick
    // one from the first frame (the 99.5th percentile of luminance to white).
    float exposureStops = NAN;
    bool panel = true;  // the control panel, docked beside the view
    bool lightsChanged = true;
    bool quit = false;
    struct Screenshot {
        std::string file;
        bool withPanel = false;  // the whole window as shown (PNG), or the view alone
        bool operator==(const Screenshot& o) const { return file == o.file && withPanel == o.withPanel; }
    };
    std::vector<Screenshot> screenshots;  // to save after the next frame
};

// Applies one script line (see docs/viewer.md); throws Error("SCRIPT:LINE: problem").
void applyScriptLine(ViewerState& state, const std::string& line, const std::string& where);

}  // namespace lucent

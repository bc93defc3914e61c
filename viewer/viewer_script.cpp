#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "core/error.h"
#include "core/limits.h"
#include "viewer/viewer_state.h"

namespace lucent {
namespace {

std::string formatNumber(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

// Three finite numbers, each within +-limit (the scene file's ranges, core/limits.h).
Vec3 readVec3(std::istringstream& in, const std::string& where, const char* what, double limit = kMaxCoordinate) {
    Vec3 v;
    if (!(in >> v.x >> v.y >> v.z)) throw Error(where, std::string("expected three numbers for ") + what);
    for (int k = 0; k < 3; ++k)
        if (!std::isfinite(v[k]) || std::abs(v[k]) > limit)
            throw Error(where, std::string(what) + " must be finite and within +-" + formatNumber(limit));
    return v;
}

// Not zero; unit length however large (as the scene parser does).
Vec3 readDirection(std::istringstream& in, const std::string& where) {
    const Vec3 d = readVec3(in, where, "direction", 1e300);
    const double largest = std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)});
    if (!(largest > 0.0)) throw Error(where, "direction must not be the zero vector");
    return glm::normalize(d / largest);
}

// Intensity or irradiance per channel: non-negative, at most kMaxMagnitude.
Rgb readColour(std::istringstream& in, const std::string& where) {
    const Vec3 c = readVec3(in, where, "colour", kMaxMagnitude);
    if (c.x < 0.0 || c.y < 0.0 || c.z < 0.0) throw Error(where, "colour must not be negative");
    return c;
}

double readPositive(std::istringstream& in, const std::string& where, const char* what) {
    double v = 0.0;
    if (!(in >> v) || !std::isfinite(v) || !(v > 0.0))
        throw Error(where, std::string(what) + " needs a positive finite number");
    return v;
}

// A point light's radius: 0 or more, as the scene file's key.
double readRadius(std::istringstream& in, const std::string& where) {
    double r;
    if (!(in >> r) || !(r >= 0.0 && r <= kMaxCoordinate))
        throw Error(where, "a light's radius needs a number in [0, 1e13]");
    return r;
}

// INNER OUTER in degrees, as the scene file's spot keys take them.
SpotCone readCone(std::istringstream& in, const std::string& where, const Vec3& axis) {
    double inner, outer;
    if (!(in >> inner >> outer) || !std::isfinite(inner) || !std::isfinite(outer) || inner < 0.0 || !(inner < outer) ||
        !(outer <= 90.0))
        throw Error(where, "a spot's cone needs INNER OUTER in degrees, 0 <= INNER < OUTER <= 90");
    return SpotCone{axis, inner, outer};
}

Light& lightAt(ViewerState& state, std::istringstream& in, const std::string& where) {
    size_t index;
    if (!(in >> index) || index >= state.lights.size())
        throw Error(where, "no light with that index (there are " + std::to_string(state.lights.size()) + ")");
    return state.lights[index];
}

Similarity& selectedPlacement(ViewerState& state, const std::string& where) {
    if (state.selected >= state.placements.size()) throw Error(where, "no object is selected");
    state.placementsChanged = true;
    return state.placements[state.selected];
}

bool onOff(std::istringstream& in, const std::string& where) {
    std::string word;
    in >> word;
    if (word != "on" && word != "off") throw Error(where, "expected on or off");
    return word == "on";
}

}  // namespace

void applyScriptLine(ViewerState& state, const std::string& raw, const std::string& where) {
    const std::string line = raw.substr(0, raw.find('#'));
    std::istringstream in(line);
    std::string command;
    if (!(in >> command)) return;
    if (command == "orbit") {
        double yaw, pitch;
        if (!(in >> yaw >> pitch) || !std::isfinite(yaw) || !std::isfinite(pitch))
            throw Error(where, "orbit needs yaw and pitch in degrees");
        state.camera.orbit(yaw, pitch);
    } else if (command == "zoom") {
        state.camera.zoom(readPositive(in, where, "zoom"));
    } else if (command == "pan") {
        double right, up;
        if (!(in >> right >> up) || !std::isfinite(right) || !std::isfinite(up))
            throw Error(where, "pan needs two finite fractions of the distance");
        state.camera.pan(right, up);
    } else if (command == "light") {
        Light& light = lightAt(state, in, where);
        std::string what;
        in >> what;
        if (what == "position")
            light.position = readVec3(in, where, "position");
        else if (what == "direction" && light.spot)
            light.spot->axis = readDirection(in, where);
        else if (what == "direction")
            light.direction = readDirection(in, where);
        else if (what == "cone" && light.spot)
            light.spot = readCone(in, where, light.spot->axis);
        else if (what == "radius" && light.type == Light::Type::Point && !light.spot)
            light.radius = readRadius(in, where);
        else if (what == "colour" || what == "color")
            light.power = readColour(in, where);
        else
            throw Error(where,
                        "light property must be position, direction, colour, (a spot's) cone or (a point's) radius");
        state.lightsChanged = true;
    } else if (command == "environment") {
        std::string what;
        in >> what;
        double v = 0.0;
        if (what == "load") {
            if (!(in >> state.environmentToLoad)) throw Error(where, "environment load needs a map file (.hdr, .exr)");
            return;
        }
        if (!state.hasEnvironment) throw Error(where, "the scene has no environment light");
        if (what == "scale") {
            if (!(in >> v) || !(v >= 0.0 && v <= kMaxMagnitude))
                throw Error(where, "environment scale needs a number in [0, 1e30]");
            state.environmentScale = v;
        } else if (what == "turn") {
            if (!(in >> v) || !std::isfinite(v) || std::abs(v) > 1e6)
                throw Error(where, "environment turn needs degrees in [-1e6, 1e6]");
            state.environmentTurnDegrees = v;
        } else {
            throw Error(where, "environment property must be load, scale or turn");
        }
        state.lightsChanged = true;
    } else if (command == "add") {
        std::string type;
        in >> type;
        Light light;
        if (type == "point") {
            light.position = readVec3(in, where, "position");
        } else if (type == "spot") {
            light.position = readVec3(in, where, "position");
            const Vec3 axis = readDirection(in, where);
            light.spot = readCone(in, where, axis);
        } else if (type == "directional") {
            light.type = Light::Type::Directional;
            light.direction = readDirection(in, where);
        } else {
            throw Error(where, "add needs point, spot or directional");
        }
        light.power = readColour(in, where);
        if (state.lights.size() >= kMaxLights)
            throw Error(where, "at most " + std::to_string(kMaxLights) + " lights (docs/robustness.md)");
        state.lights.push_back(light);
        state.lightsChanged = true;
    } else if (command == "remove") {
        Light& light = lightAt(state, in, where);
        state.lights.erase(state.lights.begin() + (&light - state.lights.data()));
        state.lightsChanged = true;
    } else if (command == "select") {
        size_t index;
        if (!(in >> index) || index >= state.placements.size())
            throw Error(where, "no object with that index (there are " + std::to_string(state.placements.size()) + ")");
        state.selected = index;
    } else if (command == "move") {
        const Vec3 offset = readVec3(in, where, "offset");
        Similarity& p = selectedPlacement(state, where);
        const Vec3 moved = p.translation + offset;
        if (std::max({std::abs(moved.x), std::abs(moved.y), std::abs(moved.z)}) > kMaxCoordinate)
            throw Error(where, "move would take the object beyond +-" + formatNumber(kMaxCoordinate));
        p.translation = moved;
    } else if (command == "rotate") {
        // About the world axis through the object's origin: the turn comes after its own rotation.
        const Vec3 axis = readDirection(in, where);
        double degrees;
        if (!(in >> degrees) || !std::isfinite(degrees) || std::abs(degrees) > 1e6)
            throw Error(where, "rotate needs an axis and degrees in [-1e6, 1e6]");
        Similarity& p = selectedPlacement(state, where);
        p.rotation = makeSimilarity(1.0, axis, degrees, Vec3(0.0)).rotation * p.rotation;
    } else if (command == "scale") {
        const double factor = readPositive(in, where, "scale");
        Similarity& p = selectedPlacement(state, where);
        if (!(p.scale * factor >= kMinScale && p.scale * factor <= kMaxScale))
            throw Error(where, "scale would leave [" + formatNumber(kMinScale) + ", " + formatNumber(kMaxScale) + "]");
        p.scale *= factor;
    } else if (command == "ior") {
        double ior = 0.0;
        if (!(in >> ior) || !(ior >= 1.0 && ior <= 4.0)) throw Error(where, "ior needs an index in [1, 4]");
        if (state.selected >= state.iors.size()) throw Error(where, "no object is selected");
        state.iors[state.selected] = ior;
        state.iorsChanged = true;
    } else if (command == "albedo") {
        const Vec3 a = readVec3(in, where, "albedo", kMaxMagnitude);
        if (!(glm::all(glm::greaterThanEqual(a, Vec3(0.0))) && glm::all(glm::lessThanEqual(a, Vec3(1.0)))))
            throw Error(where, "albedo needs three numbers in [0, 1]");
        if (state.selected >= state.albedos.size()) throw Error(where, "no object is selected");
        state.albedos[state.selected] = Rgb(a);
        state.mediaChanged = true;
    } else if (command == "g") {
        double g = 0.0;
        if (!(in >> g) || !(g >= -0.999 && g <= 0.999)) throw Error(where, "g needs a mean cosine in [-0.999, 0.999]");
        if (state.selected >= state.gs.size()) throw Error(where, "no object is selected");
        state.gs[state.selected] = g;
        state.mediaChanged = true;
    } else if (command == "extinction") {
        state.extinctionScale = float(readPositive(in, where, "extinction"));
    } else if (command == "exposure") {
        double stops = 0.0;
        if (!(in >> stops) || !std::isfinite(stops) || std::abs(stops) > 64.0)
            throw Error(where, "exposure needs a number of stops in [-64, 64]");
        state.exposureStops = float(stops);
    } else if (command == "panel") {
        state.panel = onOff(in, where);
    } else if (command == "surface") {
        state.surface = onOff(in, where);
    } else if (command == "traced") {
        state.tracedLight = onOff(in, where);
    } else if (command == "multiple") {
        std::string which;
        in >> which;
        if (which == "on" || which == "lbl")
            state.multiple = ViewerState::Multiple::Lbl;
        else if (which == "mdom")
            state.multiple = ViewerState::Multiple::Mdom;
        else if (which == "off")
            state.multiple = ViewerState::Multiple::Off;
        else
            throw Error(where, "multiple needs on, off, lbl or mdom");
    } else if (command == "wait") {
        state.waiting = true;
    } else if (command == "scattering") {
        state.scattering = onOff(in, where);
    } else if (command == "background") {
        state.background = onOff(in, where);
    } else if (command == "screenshot") {
        std::string file;
        if (!(in >> file)) throw Error(where, "screenshot needs a file name");
        ViewerState::Screenshot shot{file, false};
        std::string what;
        if (in >> what) {
            if (what != "panel") throw Error(where, "screenshot takes a file name and optionally 'panel'");
            if (std::filesystem::path(file).extension() != ".png")
                throw Error(where, "a screenshot with the panel is what the window shows: it must be a .png");
            shot.withPanel = true;
        }
        state.screenshots.push_back(shot);
    } else if (command == "quit") {
        state.quit = true;
    } else {
        throw Error(where, "unknown command '" + command + "'");
    }
}

}  // namespace lucent

#include <sstream>

#include "core/error.h"
#include "viewer/viewer_state.h"

namespace lucent {
namespace {

Vec3 readVec3(std::istringstream& in, const std::string& where, const char* what) {
    Vec3 v;
    if (!(in >> v.x >> v.y >> v.z)) throw Error(where, std::string("expected three numbers for ") + what);
    return v;
}

Light& lightAt(ViewerState& state, std::istringstream& in, const std::string& where) {
    size_t index;
    if (!(in >> index) || index >= state.lights.size())
        throw Error(where, "no light with that index (there are " + std::to_string(state.lights.size()) + ")");
    return state.lights[index];
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
        if (!(in >> yaw >> pitch)) throw Error(where, "orbit needs yaw and pitch in degrees");
        state.camera.orbit(yaw, pitch);
    } else if (command == "zoom") {
        double factor;
        if (!(in >> factor) || !(factor > 0.0)) throw Error(where, "zoom needs a positive factor");
        state.camera.zoom(factor);
    } else if (command == "pan") {
        double right, up;
        if (!(in >> right >> up)) throw Error(where, "pan needs two fractions of the distance");
        state.camera.pan(right, up);
    } else if (command == "light") {
        Light& light = lightAt(state, in, where);
        std::string what;
        in >> what;
        if (what == "position") light.position = readVec3(in, where, "position");
        else if (what == "direction") light.direction = glm::normalize(readVec3(in, where, "direction"));
        else if (what == "colour" || what == "color") light.power = readVec3(in, where, "colour");
        else throw Error(where, "light property must be position, direction or colour");
        state.lightsChanged = true;
    } else if (command == "add") {
        std::string type;
        in >> type;
        Light light;
        if (type == "point") {
            light.position = readVec3(in, where, "position");
        } else if (type == "directional") {
            light.type = Light::Type::Directional;
            light.direction = glm::normalize(readVec3(in, where, "direction"));
        } else {
            throw Error(where, "add needs point or directional");
        }
        light.power = readVec3(in, where, "colour");
        state.lights.push_back(light);
        state.lightsChanged = true;
    } else if (command == "remove") {
        Light& light = lightAt(state, in, where);
        state.lights.erase(state.lights.begin() + (&light - state.lights.data()));
        state.lightsChanged = true;
    } else if (command == "extinction") {
        float k;
        if (!(in >> k) || !(k > 0.0f)) throw Error(where, "extinction needs a positive scale");
        state.extinctionScale = k;
    } else if (command == "exposure") {
        if (!(in >> state.exposure) || !(state.exposure > 0.0f)) throw Error(where, "exposure needs a positive value");
    } else if (command == "surface") {
        state.surface = onOff(in, where);
    } else if (command == "scattering") {
        state.scattering = onOff(in, where);
    } else if (command == "screenshot") {
        std::string file;
        if (!(in >> file)) throw Error(where, "screenshot needs a file name");
        state.screenshots.push_back(file);
    } else if (command == "quit") {
        state.quit = true;
    } else {
        throw Error(where, "unknown command '" + command + "'");
    }
}

}  // namespace lucent

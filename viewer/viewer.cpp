#include "viewer/viewer.h"

#define GLFW_INCLUDE_NONE  // Lucent's runtime loads OpenGL itself (runtime/opengl.h)
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <cmath>
#include <future>
#include <cstdio>
#include <sstream>
#include <glm/gtc/type_ptr.hpp>

#include "core/environment_background.h"
#include "core/environment_map.h"
#include "core/error.h"
#include "core/image.h"
#include "core/input_file.h"
#include "core/loaded_scene.h"
#include "core/statistics.h"
#include "core/stopwatch.h"
#include "core/limits.h"
#include "methods/grid_method.h"
#include "methods/method_table.h"
#include "runtime/offscreen_context.h"
#include "runtime/offscreen_frame.h"
#include "runtime/preprocessed_size.h"
#include "runtime/scattering_renderer.h"
#include "runtime/ss_method.h"
#include "viewer/scattering_grids.h"
#include "viewer/viewer_state.h"

namespace lucent {
namespace {

class GlfwWindow {
public:
    GlfwWindow(int width, int height) {
        glfwSetErrorCallback([](int, const char* text) { lastError() = text; });
        if (!glfwInit()) throw Error("no usable OpenGL context: glfw: " + lastError() + " (is DISPLAY set?)");
        glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
        glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
        window_ = glfwCreateWindow(width, height, "Lucent", nullptr, nullptr);
        if (!window_) {
            glfwTerminate();
            throw Error("no usable OpenGL context: glfw: " + lastError());
        }
        glfwMakeContextCurrent(window_);
        glfwSwapInterval(0);
        loadGl("glfw", [](const char* name) { return reinterpret_cast<void*>(glfwGetProcAddress(name)); });
    }
    ~GlfwWindow() {
        glfwDestroyWindow(window_);
        glfwTerminate();
    }
    GLFWwindow* get() const { return window_; }

private:
    static std::string& lastError() {
        static std::string text = "unknown error";
        return text;
    }
    GLFWwindow* window_ = nullptr;
};

// Dear ImGui on the window, for as long as the viewer runs.
class ImGuiSession {
public:
    explicit ImGuiSession(GLFWwindow* window) {
        IMGUI_CHECKVERSION();
        ImGui::CreateContext();
        ImGui::GetIO().IniFilename = nullptr;
        ImGui_ImplGlfw_InitForOpenGL(window, true);
        ImGui_ImplOpenGL3_Init("#version 450 core");
    }
    ~ImGuiSession() {
        ImGui_ImplOpenGL3_Shutdown();
        ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
    }
    ImGuiSession(const ImGuiSession&) = delete;
    ImGuiSession& operator=(const ImGuiSession&) = delete;
};

std::vector<std::string> readScript(const std::filesystem::path& file) {
    std::vector<std::string> lines;
    if (file.empty()) return lines;
    std::istringstream in(readTextFile(file, "viewer script"));
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

// A spot's aim and cone; true when any changed.
bool spotControls(SpotCone& cone) {
    glm::vec3 axis(cone.axis);
    bool changed = false;
    if (ImGui::DragFloat3("aim", glm::value_ptr(axis), 0.02f) && glm::length(axis) > 0.0f) {
        cone.axis = glm::normalize(Vec3(axis));
        changed = true;
    }
    float inner = float(cone.innerDegrees), outer = float(cone.outerDegrees);
    if (ImGui::SliderFloat("outer angle", &outer, 1.0f, 90.0f, "%.1f deg")) {
        cone.outerDegrees = outer;
        cone.innerDegrees = std::min(cone.innerDegrees, 0.99 * cone.outerDegrees);
        changed = true;
    }
    if (ImGui::SliderFloat("inner angle", &inner, 0.0f, outer, "%.1f deg")) {
        cone.innerDegrees = std::min(double(inner), 0.99 * cone.outerDegrees);
        changed = true;
    }
    return changed;
}

// A map file to light the scene with instead (or at all), loaded before the next frame.
void environmentFileControl(ViewerState& state) {
    static char file[1024] = "";
    ImGui::InputText("map file", file, sizeof file);
    if (ImGui::Button("load map") && file[0] != '\0') state.environmentToLoad = file;
}

// The environment's scale and its turn about +y (docs/viewer.md).
void environmentControls(ViewerState& state) {
    ImGui::PushID("environment");
    ImGui::Text("environment");
    float scale = float(state.environmentScale), turn = float(state.environmentTurnDegrees);
    if (ImGui::DragFloat("scale", &scale, 0.01f * std::max(scale, 0.01f), 0.0f, 1e9f, "%.3g")) {
        state.environmentScale = std::max(0.0, double(scale));
        state.lightsChanged = true;
    }
    if (ImGui::SliderFloat("turn about +y", &turn, -180.0f, 180.0f, "%.0f deg")) {
        state.environmentTurnDegrees = turn;
        state.lightsChanged = true;
    }
    environmentFileControl(state);
    ImGui::Separator();
    ImGui::PopID();
}

void lightsPanel(ViewerState& state) {
    if (state.hasEnvironment)
        environmentControls(state);
    else
        environmentFileControl(state);
    for (size_t i = 0; i < state.lights.size(); ++i) {
        Light& light = state.lights[i];
        ImGui::PushID(int(i));
        const bool point = light.type == Light::Type::Point;
        ImGui::Text("%s light %zu", light.spot ? "spot" : point ? "point" : "directional", i);
        glm::vec3 position(point ? light.position : light.direction);
        glm::vec3 power(light.power);
        if (ImGui::DragFloat3(point ? "position" : "direction", glm::value_ptr(position), 0.02f)) {
            if (point)
                light.position = Vec3(position);
            else if (glm::length(position) > 0.0f)
                light.direction = glm::normalize(Vec3(position));
            state.lightsChanged = true;
        }
        if (light.spot) state.lightsChanged |= spotControls(*light.spot);
        float radius = float(light.radius);
        if (point && !light.spot && ImGui::DragFloat("radius", &radius, 0.01f, 0.0f, 1e6f, "%.3f")) {
            light.radius = std::max(0.0, double(radius));  // a sphere light (docs/scene-file.md)
            state.lightsChanged = true;
        }
        float peak = std::max({power.r, power.g, power.b, 1e-6f});
        glm::vec3 colour = power / peak;
        bool changed = ImGui::ColorEdit3("colour", glm::value_ptr(colour));
        changed |= ImGui::DragFloat(point ? "intensity W/sr" : "irradiance W/m2", &peak, 0.05f * peak, 0.0f, 1e9f);
        if (changed) {
            light.power = Rgb(colour * peak);
            state.lightsChanged = true;
        }
        if (ImGui::Button("remove")) {
            state.lights.erase(state.lights.begin() + long(i));
            state.lightsChanged = true;
            ImGui::PopID();
            break;
        }
        ImGui::Separator();
        ImGui::PopID();
    }
    if (ImGui::Button("add point light")) {
        Light l;
        l.position = state.camera.camera().position;
        l.power = Rgb(10.0);
        state.lights.push_back(l);
        state.lightsChanged = true;
    }
    ImGui::SameLine();
    if (ImGui::Button("add spot light")) {
        // From the camera, aimed where it looks.
        Light l;
        l.position = state.camera.camera().position;
        l.power = Rgb(10.0);
        l.spot = SpotCone{glm::normalize(state.camera.camera().target - l.position), 15.0, 25.0};
        state.lights.push_back(l);
        state.lightsChanged = true;
    }
    ImGui::SameLine();
    if (ImGui::Button("add directional light")) {
        Light l;
        l.type = Light::Type::Directional;
        l.direction = Vec3(0, -1, 0);
        l.power = Rgb(1.0);
        state.lights.push_back(l);
        state.lightsChanged = true;
    }
}

// The selected object's placement: which object, its index of refraction,
// where it stands, its scale, and turns of 15 degrees about the world's axes through its origin.
void objectsPanel(ViewerState& state, const LoadedScene& loaded) {
    if (state.placements.empty()) return;
    int selected = int(state.selected);
    std::string names;
    for (const VolumeObject& o : loaded.objects) names += o.desc().name + '\0';
    ImGui::Combo("object", &selected, names.c_str());
    state.selected = size_t(selected);
    Similarity& p = state.placements[state.selected];
    glm::vec3 position(p.translation);
    if (ImGui::DragFloat3("position", glm::value_ptr(position), 0.01f)) {
        p.translation = Vec3(position);
        state.placementsChanged = true;
    }
    // The index of refraction: no new preprocessing (sample files serve every ior).
    float ior = float(state.iors[state.selected]);
    if (ImGui::SliderFloat("ior", &ior, 1.0f, 2.0f, "%.3f")) {
        state.iors[state.selected] = std::clamp(double(ior), 1.0, 4.0);
        state.iorsChanged = true;
    }
    // Albedo and g: no new preprocessing either (the samples hold weights and attenuation).
    glm::vec3 albedo(state.albedos[state.selected]);
    if (ImGui::ColorEdit3("albedo", glm::value_ptr(albedo))) {
        state.albedos[state.selected] = glm::clamp(Rgb(albedo), Rgb(0.0), Rgb(1.0));
        state.mediaChanged = true;
    }
    float g = float(state.gs[state.selected]);
    if (ImGui::SliderFloat("g", &g, -0.99f, 0.99f, "%.2f")) {
        state.gs[state.selected] = std::clamp(double(g), -0.999, 0.999);
        state.mediaChanged = true;
    }
    float scale = float(p.scale);
    if (ImGui::SliderFloat("scale", &scale, 0.1f, 10.0f, "%.3f", ImGuiSliderFlags_Logarithmic) && scale > 0.0f) {
        p.scale = scale;
        state.placementsChanged = true;
    }
    // The medium's scale moves the optical size as the placement's does.
    if (loaded.hasSamples()) {
        const std::string stale =
            preprocessedSizeLimitation(loaded.objects[state.selected].desc().name, p.scale * state.extinctionScale,
                                       loaded.samples[state.selected].parameters);
        if (!stale.empty()) {
            ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.6f, 0.2f, 1.0f));
            ImGui::TextWrapped("%s", stale.c_str());
            ImGui::PopStyleColor();
        }
    }
    const char* axes[3] = {"x", "y", "z"};
    for (int a = 0; a < 3; ++a) {
        ImGui::PushID(a);
        for (const double degrees : {-15.0, 15.0}) {
            if (degrees > 0.0) ImGui::SameLine();
            if (ImGui::Button(degrees < 0.0 ? "-15" : "+15")) {
                Vec3 axis(0.0);
                axis[a] = 1.0;
                p.rotation = makeSimilarity(1.0, axis, degrees, Vec3(0.0)).rotation * p.rotation;
                state.placementsChanged = true;
            }
        }
        ImGui::SameLine();
        ImGui::Text("turn about %s", axes[a]);
        ImGui::PopID();
    }
}

// The scene's bounds with each object where it now stands (the depth range hugs them).
Bounds3 placedBounds(const LoadedScene& loaded, const std::vector<Similarity>& placements) {
    Bounds3 bounds;
    for (size_t i = 0; i < loaded.objects.size(); ++i) {
        const Bounds3 own = loaded.objects[i].objectMesh().bounds();
        for (int corner = 0; corner < 8; ++corner)
            bounds.extend(
                placements[i].point(Vec3(corner & 1 ? own.max.x : own.min.x, corner & 2 ? own.max.y : own.min.y,
                                         corner & 4 ? own.max.z : own.min.z)));
    }
    return bounds;
}

// The control panel's width in pixels, docked at the left of the window beside
// the view (wide enough for its labels).
constexpr int kPanelWidth = 380;

// One run of the viewer: the window, what it shows and the state the user and
// the script change. run() is the frame loop; each step of a frame is a
// function of its own.
class Viewer {
public:
    Viewer(const SceneDesc& scene, const ViewerOptions& options, std::vector<std::string> script, LoadedScene& loaded,
           std::string methodName)
        : options_(options),
          loaded_(loaded),
          methodName_(std::move(methodName)),
          script_(std::move(script)),
          state_(scene),
          bounds_(loaded.bounds()),
          window_((options.width ? options.width : scene.camera.width) + kPanelWidth,
                  options.height ? options.height : scene.camera.height),
          grids_(loaded) {
        state_.camera.resize(options.width ? options.width : scene.camera.width,
                             options.height ? options.height : scene.camera.height);
        // Starts as `lucent render --method ss` draws by default.
        state_.tracedLight = SsOptions::from(MethodOptions(findMethod(methodName_).options)).tracedLight;
        for (size_t i = 0; i < loaded.objects.size(); ++i)
            renderer_.addObject(translucentObjectFor(loaded.objects[i], loaded.samples[i]));
        if (scene.environment) {
            // At scale 1, so that any scale the panel or the script sets scales
            // them: the map the scene loaded, unscaled, unless its scale 0 left
            // nothing to unscale.
            const std::shared_ptr<const EnvironmentMap>& map = loaded.environment;
            if (map && map->scale() > 0.0) {
                useEnvironment(map, 1.0 / map->scale());
            } else {
                EnvironmentDesc unscaled = *scene.environment;
                unscaled.scale = 1.0;
                useEnvironment(EnvironmentMap::load(unscaled));
            }
        }
    }

    // The map's lights, their power times factor; the map itself, for the background.
    void useEnvironment(std::shared_ptr<const EnvironmentMap> map, double factor = 1.0) {
        environment_ = std::move(map);
        environmentFactor_ = factor;
        environmentLights_ = environment_->asDirectionalLights(SsOptions().environmentLights);
        gridEnvironmentLights_ = environment_->asDirectionalLights(kGridEnvironmentLights);
        for (auto* lights : {&environmentLights_, &gridEnvironmentLights_})
            for (Light& l : *lights) l.power *= factor;
    }

    // The map `environment load` or the panel asked for, in place of the current one.
    void loadEnvironment(const std::string& file) {
        try {
            EnvironmentDesc desc;
            desc.file = file;
            useEnvironment(EnvironmentMap::load(desc));
            state_.hasEnvironment = true;
            state_.lightsChanged = true;
        } catch (const Error& e) {
            std::fprintf(stderr, "lucent: warning: view: the environment stays as it was: %s\n", e.what());
        }
    }

    void run() {
        Stopwatch sinceLastFrame;
        while (!glfwWindowShouldClose(window_.get()) && !state_.quit) {
            if (!drawTimes_.empty()) loopTimes_.push_back(sinceLastFrame.milliseconds());
            sinceLastFrame.restart();
            glfwPollEvents();
            followScript();
            readInput();
            int fbWidth, fbHeight;
            glfwGetFramebufferSize(window_.get(), &fbWidth, &fbHeight);
            // The view fills the window beside the docked panel, or all of it.
            const int panelWidth = state_.panel ? std::min(kPanelWidth, fbWidth - 1) : 0;
            if (fbWidth - panelWidth <= 0 || fbHeight <= 0) continue;
            resizeFrame(fbWidth - panelWidth, fbHeight);
            applyEdits();
            drawScene();
            const std::vector<std::string> withPanel = saveViewScreenshots();
            frame_->present(fbWidth, fbHeight, panelWidth, 0, exposure());
            drawPanel(panelWidth, fbHeight);
            for (const std::string& file : withPanel) {
                writeImage(file, readWindow(fbWidth, fbHeight), 1.0f);
                std::fprintf(stderr, "lucent: view: saved %s (with the panel)\n", file.c_str());
            }
            glfwSwapBuffers(window_.get());
        }
        printSummary();
    }

private:
    // The script's next line, one per frame; after the last, the screenshot
    // asked for on the command line, and the end.
    void followScript() {
        if (state_.waiting && !grids_.solving()) state_.waiting = false;
        if (state_.waiting) return;  // a script's `wait`: the next line when the solve is done
        if (scriptLine_ < script_.size()) {
            applyScriptLine(state_, script_[scriptLine_],
                            options_.script.string() + ":" + std::to_string(scriptLine_ + 1));
            ++scriptLine_;
        } else if (!options_.screenshot.empty()) {
            state_.screenshots.push_back({options_.screenshot.string(), false});
            state_.quit = true;
        }
    }

    // Left drag orbits, right drag pans, the wheel zooms (unless over the
    // panel); Tab shows or hides the panel.
    void readInput() {
        GLFWwindow* window = window_.get();
        glm::dvec2 mouse;
        glfwGetCursorPos(window, &mouse.x, &mouse.y);
        if (!ImGui::GetIO().WantCaptureMouse) {
            const glm::dvec2 delta = mouse - lastMouse_;
            if (glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS)
                state_.camera.orbit(-0.3 * delta.x, 0.3 * delta.y);
            if (glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS)
                state_.camera.pan(-1e-3 * delta.x, 1e-3 * delta.y);
            const float wheel = ImGui::GetIO().MouseWheel;
            if (wheel != 0.0f) state_.camera.zoom(std::pow(0.9, wheel));
        }
        lastMouse_ = mouse;
        const bool tabDown = glfwGetKey(window, GLFW_KEY_TAB) == GLFW_PRESS;
        if (tabDown && !tabWasDown_ && !ImGui::GetIO().WantCaptureKeyboard) state_.panel = !state_.panel;
        tabWasDown_ = tabDown;
    }

    void resizeFrame(int width, int height) {
        if (frame_ && width == frameWidth_ && height == frameHeight_) return;
        frame_ = std::make_unique<OffscreenFrame>(width, height);
        frameWidth_ = width;
        frameHeight_ = height;
        state_.camera.resize(width, height);
    }

    // Lights, indices and placements the panel or the script changed reach the
    // renderer, and the multiple scattering is solved again for them.
    void applyEdits() {
        if (!state_.environmentToLoad.empty()) {
            loadEnvironment(state_.environmentToLoad);
            state_.environmentToLoad.clear();
        }
        // The environment reaches the samples through SH when their light is read
        // from the SH and every medium's g allows (setSsLights, runtime/ss_method.h).
        const bool projected = !environmentLights_.empty() && !state_.tracedLight &&
                               std::all_of(state_.gs.begin(), state_.gs.end(), environmentShHolds);
        if (projected != environmentProjected_) state_.lightsChanged = true;
        if (state_.lightsChanged) {
            // Lights added past the scene's limit, with the environment's, are taken back.
            const size_t room = kMaxLights - environmentLights_.size();
            if (state_.lights.size() > room) {
                std::fprintf(stderr, "lucent: warning: view: at most %zu lights beside the environment's %zu\n", room,
                             environmentLights_.size());
                state_.lights.resize(room);
            }
            renderer_.setEnvironment({});
            renderer_.setLights(projected ? state_.lights : withEnvironment(environmentLights_));
            if (projected) renderer_.setEnvironment(environmentNow(environmentLights_));
            environmentProjected_ = projected;
            state_.lightsChanged = false;
            grids_.invalidate();
        }
        if (state_.iorsChanged) {
            for (size_t i = 0; i < state_.iors.size(); ++i) {
                VolumeObject& o = loaded_.objects[i];
                if (o.desc().medium.ior == state_.iors[i]) continue;
                o.setIor(state_.iors[i]);
                renderer_.setSamples(i, loaded_.samples[i], &o);  // its light and view traced again
            }
            state_.iorsChanged = false;
            grids_.invalidate();
        }
        if (state_.mediaChanged) {
            for (size_t i = 0; i < state_.albedos.size(); ++i) {
                loaded_.objects[i].setAlbedoAndG(state_.albedos[i], state_.gs[i]);
                renderer_.setAlbedoAndG(i, state_.albedos[i], state_.gs[i]);
            }
            state_.mediaChanged = false;
            grids_.invalidate();  // the multiple scattering depends on both
        }
        if (state_.placementsChanged) {
            for (size_t i = 0; i < state_.placements.size(); ++i) renderer_.setPlacement(i, state_.placements[i]);
            warnStaleSizes();
            bounds_ = placedBounds(loaded_, state_.placements);
            state_.placementsChanged = false;
            grids_.invalidate();  // solved for where the objects stood
        }
        grids_.update(state_, renderer_, withEnvironment(gridEnvironmentLights_));
    }

    // Told once each time an object's scale leaves (or re-enters) the size its samples serve.
    void warnStaleSizes() {
        if (!loaded_.hasSamples()) return;
        sizeWarnings_.resize(state_.placements.size());
        for (size_t i = 0; i < state_.placements.size(); ++i) {
            std::string line = preprocessedSizeLimitation(loaded_.objects[i].desc().name, state_.placements[i].scale,
                                                          loaded_.samples[i].parameters);
            if (line != sizeWarnings_[i] && !line.empty()) std::fprintf(stderr, "lucent: warning: %s\n", line.c_str());
            sizeWarnings_[i] = std::move(line);
        }
    }

    void drawScene() {
        frame_->bindAndClear();
        DrawOptions drawOptions;
        drawOptions.surface = state_.surface;
        drawOptions.scattering = state_.scattering;
        drawOptions.extinctionScale = state_.extinctionScale;
        drawOptions.tracedLight = state_.tracedLight;
        // The environment behind and through the objects, on the CPU while the frame draws.
        std::future<Image> background;
        if (environment_ && state_.background)
            background = std::async(std::launch::async, [this] {
                return environmentBackground(loaded_.objects, *environment_, state_.camera.camera(), backgroundEdits(),
                                             0);
            });
        frameMs_ =
            1e3 * timeGlWork([&] { renderer_.draw(viewSetupFor(state_.camera.camera(), bounds_), drawOptions); });
        if (background.valid()) frame_->add(background.get());
        drawTimes_.push_back(frameMs_);
        if (std::isnan(state_.exposureStops)) state_.exposureStops = std::log2(autoExposure(frame_->read()));
    }

    float exposure() const { return std::exp2(state_.exposureStops); }

    // Saves the screenshots of the view alone; returns those that want the
    // whole window, saved once the panel is drawn.
    std::vector<std::string> saveViewScreenshots() {
        std::vector<std::string> withPanel;
        for (const auto& shot : state_.screenshots) {
            if (shot.withPanel) {
                withPanel.push_back(shot.file);
                continue;
            }
            writeImage(shot.file, frame_->read(), exposure());
            std::fprintf(stderr, "lucent: view: saved %s\n", shot.file.c_str());
        }
        state_.screenshots.clear();
        return withPanel;
    }

    void drawPanel(int panelWidth, int height) {
        ImGui_ImplOpenGL3_NewFrame();
        ImGui_ImplGlfw_NewFrame();
        ImGui::NewFrame();
        if (state_.panel) {
            ImGui::SetNextWindowPos(ImVec2(0, 0), ImGuiCond_Always);
            ImGui::SetNextWindowSize(ImVec2(float(panelWidth), float(height)), ImGuiCond_Always);
            ImGui::Begin("Lucent (Tab hides)", nullptr,
                         ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
            ImGui::PushItemWidth(-150.0f);  // room for the labels
            ImGui::Text("method %s: %.1f ms per frame, %zu samples", methodName_.c_str(), frameMs_,
                        renderer_.sampleCount());
            passesPanel();
            ImGui::Separator();
            objectsPanel(state_, loaded_);
            ImGui::Separator();
            lightsPanel(state_);
            ImGui::PopItemWidth();
            ImGui::End();
        }
        ImGui::Render();
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    }

    // What the frame shows, the medium's scale, the exposure and the screenshot button.
    void passesPanel() {
        ImGui::Checkbox("surface", &state_.surface);
        ImGui::SameLine();
        ImGui::Checkbox("scattering", &state_.scattering);
        if (environment_) ImGui::Checkbox("background", &state_.background);
        ImGui::SameLine();
        ImGui::Checkbox("traced light", &state_.tracedLight);
        tooltip("ss", "light");
#ifdef LUCENT_HAVE_OPENCL
        int multiple = int(state_.multiple);
        ImGui::Combo("multiple", &multiple, "off\0lbl\0mdom\0");
        state_.multiple = ViewerState::Multiple(multiple);
        if (!grids_.status().empty()) ImGui::Text("%s", grids_.status().c_str());
#endif
        ImGui::SliderFloat("medium scale", &state_.extinctionScale, 0.1f, 10.0f, "%.2f", ImGuiSliderFlags_Logarithmic);
        ImGui::SliderFloat("exposure (stops)", &state_.exposureStops, -20.0f, 20.0f, "%+.1f");
        if (ImGui::Button("save screenshot")) state_.screenshots.push_back({"lucent-screenshot.png", screenshotPanel_});
        ImGui::SameLine();
        ImGui::Checkbox("with the panel", &screenshotPanel_);
    }

    // The help of a method's option, from its declaration (docs/methods.md), on the last item.
    static void tooltip(const std::string& method, const std::string& option) {
        if (!ImGui::IsItemHovered()) return;
        for (const OptionSpec& spec : findMethod(method).options)
            if (spec.name == option)
                ImGui::SetTooltip("--method %s --%s: %s", method.c_str(), option.c_str(), spec.help.c_str());
    }

    void printSummary() const {
        if (loopTimes_.empty()) return;
        const double shown = median(loopTimes_);
        std::fprintf(stderr,
                     "lucent: view: %zu frames at %dx%d: median %.1f ms to draw, %.1f ms per frame shown (%.1f fps)\n",
                     loopTimes_.size(), frameWidth_, frameHeight_, median(drawTimes_), shown, 1e3 / shown);
    }

    const ViewerOptions& options_;
    LoadedScene& loaded_;                    // the objects' ior follows the panel
    std::vector<std::string> sizeWarnings_;  // per object, the last told
    const std::string methodName_;
    const std::vector<std::string> script_;
    size_t scriptLine_ = 0;
    ViewerState state_;
    Bounds3 bounds_;
    GlfwWindow window_;
    ImGuiSession imgui_{window_.get()};
    ScatteringRenderer renderer_;
    // Multiple scattering: solved on the OpenCL device when asked for, again when the lights or objects move.
    ScatteringGrids grids_;
    // The scene's environment at scale 1 as the directional lights ss draws it
    // as, and as the fewer lbl and mdom solve for (methods/grid_method.h).
    std::vector<Light> environmentLights_, gridEnvironmentLights_;
    std::shared_ptr<const EnvironmentMap> environment_;  // the map those came from
    double environmentFactor_ = 1.0;                     // its radiance times this is at scale 1

    bool environmentProjected_ = false;  // given to setEnvironment rather than setLights

    // The map's turn about +y, as the panel and the script set it.
    glm::dmat3 environmentTurn() const {
        return makeSimilarity(1.0, Vec3(0.0, 1.0, 0.0), state_.environmentTurnDegrees, Vec3(0.0)).rotation;
    }
    // What the background is drawn with: the objects where they stand now, the map turned and scaled.
    BackgroundEdits backgroundEdits() const {
        BackgroundEdits edits;
        edits.placements = state_.placements;
        edits.extinctionScale = state_.extinctionScale;
        edits.turn = environmentTurn();
        edits.scale = environmentFactor_ * state_.environmentScale;
        return edits;
    }
    // The environment's lights scaled and turned as the state says.
    std::vector<Light> environmentNow(std::vector<Light> environment) const {
        const glm::dmat3 turn = environmentTurn();
        for (Light& l : environment) {
            l.direction = turn * l.direction;
            l.power *= state_.environmentScale;
        }
        return environment;
    }
    // The state's lights and those.
    std::vector<Light> withEnvironment(const std::vector<Light>& environment) const {
        std::vector<Light> out = state_.lights;
        for (const Light& l : environmentNow(environment)) out.push_back(l);
        return out;
    }
    std::unique_ptr<OffscreenFrame> frame_;
    int frameWidth_ = 0, frameHeight_ = 0;
    double frameMs_ = 0.0;
    std::vector<double> drawTimes_, loopTimes_;  // drawing, and the whole loop: for the summary on closing
    glm::dvec2 lastMouse_{0.0};
    bool tabWasDown_ = false;
    bool screenshotPanel_ = false;  // the panel's own screenshot button: with the panel?
};

}  // namespace

void runViewer(const SceneDesc& scene, const ViewerOptions& options) {
    std::vector<std::string> script = readScript(options.script);  // cheap: its errors come first
    // The viewer draws with the interactive method of the table, in its own window.
    const MethodEntry& method = findMethod("ss");
    if (const std::string why = method.unavailableReason(); !why.empty())
        throw Error("lucent view: method '" + method.name + "' cannot run here: " + why);
    LoadedScene loaded = loadScene(scene, method.needsSamples);
    for (const auto& w : loaded.warnings) std::fprintf(stderr, "lucent: warning: %s\n", w.c_str());
    Viewer(scene, options, std::move(script), loaded, method.name).run();
}

}  // namespace lucent

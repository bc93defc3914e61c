#include "viewer/viewer.h"

#include "runtime/internal/gl.h"  // glad before GLFW, and GLFW without its own GL header
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <glm/gtc/type_ptr.hpp>

#include "core/error.h"
#include "core/image.h"
#include "core/input_file.h"
#include "core/loaded_scene.h"
#include "methods/method_table.h"
#include "runtime/internal/gl_program.h"
#include "runtime/offscreen_context.h"
#include "runtime/offscreen_frame.h"
#include "runtime/scattering_renderer.h"
#include "viewer/scattering_grids.h"
#include "viewer/viewer_shaders.h"
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

std::vector<std::string> readScript(const std::filesystem::path& file) {
    std::vector<std::string> lines;
    if (file.empty()) return lines;
    std::istringstream in(readTextFile(file, "viewer script"));
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

void lightsPanel(ViewerState& state) {
    for (size_t i = 0; i < state.lights.size(); ++i) {
        Light& light = state.lights[i];
        ImGui::PushID(int(i));
        const bool point = light.type == Light::Type::Point;
        ImGui::Text("%s light %zu", point ? "point" : "directional", i);
        glm::vec3 position(point ? light.position : light.direction);
        glm::vec3 power(light.power);
        if (ImGui::DragFloat3(point ? "position" : "direction", glm::value_ptr(position), 0.02f)) {
            if (point) light.position = Vec3(position);
            else if (glm::length(position) > 0.0f) light.direction = glm::normalize(Vec3(position));
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
    if (ImGui::Button("add directional light")) {
        Light l;
        l.type = Light::Type::Directional;
        l.direction = Vec3(0, -1, 0);
        l.power = Rgb(1.0);
        state.lights.push_back(l);
        state.lightsChanged = true;
    }
}

// The selected object's placement: which object, where it stands, its scale,
// and turns of 15 degrees about the world's axes through its origin.
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
    float scale = float(p.scale);
    if (ImGui::SliderFloat("scale", &scale, 0.1f, 10.0f, "%.3f", ImGuiSliderFlags_Logarithmic) && scale > 0.0f) {
        p.scale = scale;
        state.placementsChanged = true;
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
            bounds.extend(placements[i].point(Vec3(corner & 1 ? own.max.x : own.min.x, corner & 2 ? own.max.y : own.min.y,
                                                   corner & 4 ? own.max.z : own.min.z)));
    }
    return bounds;
}

}  // namespace

// The control panel's width in pixels, docked at the left of the window beside
// the view (wide enough for its labels).
constexpr int kPanelWidth = 380;

// What the window shows, panel included, read back before it is swapped: PNG
// bytes as displayed (the tone mapping already applied).
void saveWindow(const std::string& file, int width, int height) {
    std::vector<float> rgb(size_t(width) * height * 3);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGB, GL_FLOAT, rgb.data());
    Image image(width, height);
    // Rows bottom-up in GL; sRGB values back to linear, so that writing with
    // exposure 1 encodes them again as they were shown.
    auto linear = [](float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); };
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const float* p = &rgb[(size_t(height - 1 - y) * width + x) * 3];
            image.at(x, y) = glm::vec3(linear(p[0]), linear(p[1]), linear(p[2]));
        }
    writeImage(file, image, 1.0f);
}

void runViewer(const SceneDesc& scene, const ViewerOptions& options) {
    const std::vector<std::string> script = readScript(options.script);  // cheap: its errors come first
    // The viewer draws with the interactive method of the table, in its own window.
    const MethodEntry& method = findMethod("ss");
    if (const std::string why = method.unavailableReason(); !why.empty())
        throw Error("lucent view: method '" + method.name + "' cannot run here: " + why);
    const LoadedScene loaded = loadScene(scene, method.needsSamples);
    for (const auto& w : loaded.warnings) std::fprintf(stderr, "lucent: warning: %s\n", w.c_str());
    Bounds3 bounds = loaded.bounds();

    ViewerState state(scene);
    const int width = options.width ? options.width : scene.camera.width;
    const int height = options.height ? options.height : scene.camera.height;
    state.camera.resize(width, height);
    GlfwWindow window(width + kPanelWidth, height);  // the view keeps its size beside the panel

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;
    ImGui_ImplGlfw_InitForOpenGL(window.get(), true);
    ImGui_ImplOpenGL3_Init("#version 450 core");
    {
        ScatteringRenderer renderer;
        for (size_t i = 0; i < loaded.objects.size(); ++i)
            renderer.addObject(translucentObjectFor(loaded.objects[i], loaded.samples[i]));
        std::unique_ptr<OffscreenFrame> frame;
        int frameWidth = 0, frameHeight = 0;
        GlProgram tonemap{{GL_VERTEX_SHADER, "fullscreen.vert"},
                          {GL_FRAGMENT_SHADER, "tonemap.frag", viewerShader("tonemap.frag")}};
        GLuint emptyVao;
        glCreateVertexArrays(1, &emptyVao);
        double frameMs = 0.0;
        std::vector<double> frameTimes, loopTimes;  // drawing, and the whole loop: for the summary on closing
        auto loopStart = std::chrono::steady_clock::now();
        // Multiple scattering: solved on the OpenCL device when asked for, again when the lights or objects move.
        ScatteringGrids grids(loaded);
        size_t scriptLine = 0;
        glm::dvec2 lastMouse(0.0);
        bool tabWasDown = false;
        bool screenshotPanel = false;  // the panel's own screenshot button: with the panel?

        while (!glfwWindowShouldClose(window.get()) && !state.quit) {
            const auto now = std::chrono::steady_clock::now();
            if (!frameTimes.empty()) loopTimes.push_back(std::chrono::duration<double, std::milli>(now - loopStart).count());
            loopStart = now;
            glfwPollEvents();
            if (state.waiting && !grids.solving()) state.waiting = false;
            if (state.waiting) {
                // a script's `wait`: the next line when the solve is done
            } else if (scriptLine < script.size()) {
                applyScriptLine(state, script[scriptLine], options.script.string() + ":" + std::to_string(scriptLine + 1));
                ++scriptLine;
            } else if (!options.screenshot.empty()) {
                state.screenshots.push_back({options.screenshot.string(), false});
                state.quit = true;
            }

            // Mouse: left drag orbits, right drag pans, wheel zooms (unless over the panel).
            glm::dvec2 mouse;
            glfwGetCursorPos(window.get(), &mouse.x, &mouse.y);
            if (!ImGui::GetIO().WantCaptureMouse) {
                const glm::dvec2 delta = mouse - lastMouse;
                if (glfwGetMouseButton(window.get(), GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS) state.camera.orbit(-0.3 * delta.x, 0.3 * delta.y);
                if (glfwGetMouseButton(window.get(), GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS) state.camera.pan(-1e-3 * delta.x, 1e-3 * delta.y);
                const float wheel = ImGui::GetIO().MouseWheel;
                if (wheel != 0.0f) state.camera.zoom(std::pow(0.9, wheel));
            }
            lastMouse = mouse;
            // Tab shows or hides the panel.
            const bool tabDown = glfwGetKey(window.get(), GLFW_KEY_TAB) == GLFW_PRESS;
            if (tabDown && !tabWasDown && !ImGui::GetIO().WantCaptureKeyboard) state.panel = !state.panel;
            tabWasDown = tabDown;

            int fbWidth, fbHeight;
            glfwGetFramebufferSize(window.get(), &fbWidth, &fbHeight);
            // The view fills the window beside the docked panel, or all of it.
            const int panelWidth = state.panel ? std::min(kPanelWidth, fbWidth - 1) : 0;
            const int viewWidth = fbWidth - panelWidth;
            if (viewWidth <= 0 || fbHeight <= 0) continue;
            if (!frame || viewWidth != frameWidth || fbHeight != frameHeight) {
                frame = std::make_unique<OffscreenFrame>(viewWidth, fbHeight);
                frameWidth = viewWidth;
                frameHeight = fbHeight;
                state.camera.resize(viewWidth, fbHeight);
            }
            if (state.lightsChanged) {
                renderer.setLights(state.lights);
                state.lightsChanged = false;
                grids.invalidate();
            }
            if (state.placementsChanged) {
                for (size_t i = 0; i < state.placements.size(); ++i) renderer.setPlacement(i, state.placements[i]);
                bounds = placedBounds(loaded, state.placements);
                state.placementsChanged = false;
                grids.invalidate();  // solved for where the objects stood
            }
            grids.update(state, renderer);

            const auto start = std::chrono::steady_clock::now();
            frame->bindAndClear();
            DrawOptions drawOptions;
            drawOptions.surface = state.surface;
            drawOptions.scattering = state.scattering;
            drawOptions.extinctionScale = state.extinctionScale;
            drawOptions.tracedLight = state.tracedLight;
            renderer.draw(viewSetupFor(state.camera.camera(), bounds), drawOptions);
            glFinish();
            frameMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
            frameTimes.push_back(frameMs);
            if (std::isnan(state.exposureStops)) state.exposureStops = std::log2(autoExposure(frame->read()));
            const float exposure = std::exp2(state.exposureStops);

            std::vector<std::string> withPanel;
            for (const auto& shot : state.screenshots) {
                if (shot.withPanel) {
                    withPanel.push_back(shot.file);
                    continue;
                }
                writeImage(shot.file, frame->read(), exposure);
                std::fprintf(stderr, "lucent: view: saved %s\n", shot.file.c_str());
            }
            state.screenshots.clear();

            // Display: tone-mapped frame beside the panel, then the panel.
            glBindFramebuffer(GL_FRAMEBUFFER, 0);
            glViewport(0, 0, fbWidth, fbHeight);
            glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
            glClear(GL_COLOR_BUFFER_BIT);
            glViewport(panelWidth, 0, viewWidth, fbHeight);
            glDisable(GL_DEPTH_TEST);
            glDisable(GL_BLEND);
            glUseProgram(tonemap.id());
            glBindTextureUnit(0, frame->colourTexture());
            glUniform1i(tonemap.uniform("radiance"), 0);
            glUniform1f(tonemap.uniform("exposure"), exposure);
            glUniform2i(tonemap.uniform("offset"), panelWidth, 0);
            glBindVertexArray(emptyVao);
            glDrawArrays(GL_TRIANGLES, 0, 3);

            ImGui_ImplOpenGL3_NewFrame();
            ImGui_ImplGlfw_NewFrame();
            ImGui::NewFrame();
            if (state.panel) {
                ImGui::SetNextWindowPos(ImVec2(0, 0), ImGuiCond_Always);
                ImGui::SetNextWindowSize(ImVec2(float(panelWidth), float(fbHeight)), ImGuiCond_Always);
                ImGui::Begin("Lucent (Tab hides)", nullptr,
                             ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
                ImGui::PushItemWidth(-150.0f);  // room for the labels
                ImGui::Text("method %s: %.1f ms per frame, %zu samples", method.name.c_str(), frameMs, renderer.sampleCount());
                ImGui::Checkbox("surface", &state.surface);
                ImGui::SameLine();
                ImGui::Checkbox("scattering", &state.scattering);
                ImGui::SameLine();
                ImGui::Checkbox("traced light", &state.tracedLight);
#ifdef LUCENT_HAVE_OPENCL
                int multiple = int(state.multiple);
                ImGui::Combo("multiple", &multiple, "off\0lbl\0mdom\0");
                state.multiple = ViewerState::Multiple(multiple);
                if (!grids.status().empty()) ImGui::Text("%s", grids.status().c_str());
#endif
                ImGui::SliderFloat("medium scale", &state.extinctionScale, 0.1f, 10.0f, "%.2f", ImGuiSliderFlags_Logarithmic);
                ImGui::SliderFloat("exposure (stops)", &state.exposureStops, -20.0f, 20.0f, "%+.1f");
                if (ImGui::Button("save screenshot"))
                    state.screenshots.push_back({"lucent-screenshot.png", screenshotPanel});
                ImGui::SameLine();
                ImGui::Checkbox("with the panel", &screenshotPanel);
                ImGui::Separator();
                objectsPanel(state, loaded);
                ImGui::Separator();
                lightsPanel(state);
                ImGui::PopItemWidth();
                ImGui::End();
            }
            ImGui::Render();
            ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
            for (const std::string& file : withPanel) {
                saveWindow(file, fbWidth, fbHeight);
                std::fprintf(stderr, "lucent: view: saved %s (with the panel)\n", file.c_str());
            }
            glfwSwapBuffers(window.get());
        }
        glDeleteVertexArrays(1, &emptyVao);
        if (!loopTimes.empty()) {
            auto median = [](std::vector<double> v) {
                std::sort(v.begin(), v.end());
                return v[v.size() / 2];
            };
            const double shown = median(loopTimes);
            std::fprintf(stderr, "lucent: view: %zu frames at %dx%d: median %.1f ms to draw, %.1f ms per frame shown (%.1f fps)\n",
                         loopTimes.size(), frameWidth, frameHeight, median(frameTimes), shown, 1e3 / shown);
        }
    }
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
}

}  // namespace lucent

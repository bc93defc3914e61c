// A windowed host, as a game engine would embed Lucent: GLFW opens the window,
// the host loads OpenGL itself (libepoxy) and draws its own floor into its own
// framebuffer; Lucent, with its own loader beside the host's, adds a translucent
// cube that the host builds in memory, preprocesses in memory (no files) and
// moves and turns every frame (ScatteringRenderer::setPlacement: nothing is
// preprocessed or uploaded again).
//
//   lucent-example-window [--frames N] [--first FIRST.pfm] [--last LAST.pfm]
//
// Draws N frames (default: until the window closes) and can save the first and
// the last as linear images. The cube travels from x = -0.5 to x = +0.5 over
// the N frames, turning about y.
#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/image.h"
#include "core/volume_object.h"
#include "preprocess/preprocessor.h"
#include "runtime/opengl.h"
#include "runtime/scattering_renderer.h"

namespace {

constexpr int kSize = 256;

// The host's floor: one quad, drawn with the host's own program.
const char* kVertex = R"(#version 450 core
layout(location = 0) in vec3 position;
uniform mat4 viewProjection;
void main() { gl_Position = viewProjection * vec4(position, 1.0); })";
const char* kFragment = R"(#version 450 core
out vec4 result;
void main() { result = vec4(0.02, 0.02, 0.025, 1.0); })";

GLuint program() {
    GLuint p = glCreateProgram();
    for (const auto& [type, source] :
         {std::pair{GL_VERTEX_SHADER, kVertex}, std::pair{GL_FRAGMENT_SHADER, kFragment}}) {
        GLuint s = glCreateShader(type);
        glShaderSource(s, 1, &source, nullptr);
        glCompileShader(s);
        glAttachShader(p, s);
    }
    glLinkProgram(p);
    return p;
}

// A unit cube built in memory, as a host holds its meshes.
lucent::TriangleMesh cube() {
    std::vector<lucent::Vec3> corners;
    for (int i = 0; i < 8; ++i) corners.emplace_back(i & 4 ? 0.4 : -0.4, i & 2 ? 0.4 : -0.4, i & 1 ? 0.4 : -0.4);
    const uint32_t quads[6][4] = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
    std::vector<std::array<uint32_t, 3>> triangles;
    for (const auto& q : quads) {
        triangles.push_back({q[0], q[1], q[2]});
        triangles.push_back({q[0], q[2], q[3]});
    }
    std::vector<std::string> warnings;
    return lucent::closedMesh(corners, triangles, "cube", warnings);
}

lucent::Image readColour(GLuint texture) {
    std::vector<float> rgba(size_t(kSize) * kSize * 4);
    glGetTextureImage(texture, 0, GL_RGBA, GL_FLOAT, GLsizei(rgba.size() * sizeof(float)), rgba.data());
    lucent::Image image(kSize, kSize);
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const float* p = &rgba[(size_t(kSize - 1 - y) * kSize + x) * 4];
            image.at(x, y) = {p[0], p[1], p[2]};
        }
    return image;
}

}  // namespace

int main(int argc, char** argv) {
    int frames = 0;
    std::string first, last;
    for (int a = 1; a < argc; ++a) {
        const std::string arg = argv[a];
        if (arg == "--frames" && a + 1 < argc)
            frames = std::atoi(argv[++a]);
        else if (arg == "--first" && a + 1 < argc)
            first = argv[++a];
        else if (arg == "--last" && a + 1 < argc)
            last = argv[++a];
        else {
            std::fprintf(stderr, "usage: %s [--frames N] [--first FIRST.pfm] [--last LAST.pfm]\n", argv[0]);
            return 2;
        }
    }
    if (!glfwInit()) {
        std::fprintf(stderr, "lucent-example-window: error: glfw cannot start (is DISPLAY set?)\n");
        return 1;
    }
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    GLFWwindow* window = glfwCreateWindow(kSize, kSize, "Lucent in a host", nullptr, nullptr);
    if (!window) {
        std::fprintf(stderr, "lucent-example-window: error: no OpenGL 4.5 core window\n");
        glfwTerminate();
        return 1;
    }
    glfwMakeContextCurrent(window);
    int status = 0;
    try {
        // Lucent loads its own functions from the host's context.
        lucent::loadGl("glfw", [](const char* name) { return reinterpret_cast<void*>(glfwGetProcAddress(name)); });

        // The translucent object, from memory to samples: no file is read or written.
        lucent::MediumDesc wax;
        wax.sigmaT = lucent::Rgb(3.0, 4.0, 6.0);
        wax.albedo = lucent::Rgb(0.9);
        const lucent::VolumeObject object = lucent::memoryObject("cube", cube(), wax);
        lucent::PreprocessSettings settings = lucent::qualityPreset("draft");
        settings.samples = 3000;
        const lucent::SampleSet samples = lucent::preprocessObject(object, settings);

        lucent::Camera camera;
        camera.position = lucent::Vec3(0, 1.2, 3.5);
        camera.target = lucent::Vec3(0, 0, 0);
        camera.width = camera.height = kSize;
        lucent::Bounds3 bounds;
        bounds.extend(lucent::Vec3(-3, -1, -3));
        bounds.extend(lucent::Vec3(3, 1, 3));
        const lucent::ViewSetup view = lucent::viewSetupFor(camera, bounds);
        lucent::Light bulb;
        bulb.position = lucent::Vec3(2, 3, 2);
        bulb.power = lucent::Rgb(30.0);

        lucent::ScatteringRenderer renderer;
        renderer.addObject(lucent::translucentObjectFor(object, samples));
        renderer.setLights({bulb});

        // The host's framebuffer: float colour and a depth texture Lucent reads.
        GLuint colour, depth, framebuffer;
        glCreateTextures(GL_TEXTURE_2D, 1, &colour);
        glTextureStorage2D(colour, 1, GL_RGBA32F, kSize, kSize);
        glCreateTextures(GL_TEXTURE_2D, 1, &depth);
        glTextureStorage2D(depth, 1, GL_DEPTH_COMPONENT32F, kSize, kSize);
        glCreateFramebuffers(1, &framebuffer);
        glNamedFramebufferTexture(framebuffer, GL_COLOR_ATTACHMENT0, colour, 0);
        glNamedFramebufferTexture(framebuffer, GL_DEPTH_ATTACHMENT, depth, 0);
        const GLuint floorProgram = program();
        const glm::vec3 floor[6] = {{-3, -0.5f, -3}, {3, -0.5f, -3}, {3, -0.5f, 3},
                                    {-3, -0.5f, -3}, {3, -0.5f, 3},  {-3, -0.5f, 3}};
        GLuint vao, buffer;
        glCreateVertexArrays(1, &vao);
        glCreateBuffers(1, &buffer);
        glNamedBufferStorage(buffer, sizeof floor, floor, 0);
        glVertexArrayVertexBuffer(vao, 0, buffer, 0, sizeof(glm::vec3));
        glEnableVertexArrayAttrib(vao, 0);
        glVertexArrayAttribFormat(vao, 0, 3, GL_FLOAT, GL_FALSE, 0);
        glVertexArrayAttribBinding(vao, 0, 0);
        const glm::mat4 viewProjection = view.projection * view.view;

        for (int frame = 0; !glfwWindowShouldClose(window) && (frames == 0 || frame < frames); ++frame) {
            glfwPollEvents();
            // The host's frame: its floor, with depth.
            glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
            glViewport(0, 0, kSize, kSize);
            glClearColor(0, 0, 0, 0);
            glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
            glEnable(GL_DEPTH_TEST);
            glUseProgram(floorProgram);
            glUniformMatrix4fv(glGetUniformLocation(floorProgram, "viewProjection"), 1, GL_FALSE,
                               glm::value_ptr(viewProjection));
            glBindVertexArray(vao);
            glDrawArrays(GL_TRIANGLES, 0, 6);

            // Lucent's cube, moved and turned this frame.
            const double travel = frames > 1 ? double(frame) / double(frames - 1) : 0.5;
            renderer.setPlacement(0, lucent::makeSimilarity(1.0, lucent::Vec3(0, 1, 0), 90.0 * travel,
                                                            lucent::Vec3(travel - 0.5, 0.0, 0.0)));
            lucent::DrawOptions options;
            options.hostDepthTexture = depth;
            renderer.draw(view, options);

            if (frame == 0 && !first.empty()) lucent::writeImage(first, readColour(colour));
            if (frame == frames - 1 && !last.empty()) lucent::writeImage(last, readColour(colour));
            glBlitNamedFramebuffer(framebuffer, 0, 0, 0, kSize, kSize, 0, 0, kSize, kSize, GL_COLOR_BUFFER_BIT,
                                   GL_NEAREST);
            glfwSwapBuffers(window);
        }
        std::fprintf(stderr, "lucent-example-window: drew %d frames, %zu samples\n", frames, renderer.sampleCount());
    } catch (const lucent::Error& e) {
        std::fprintf(stderr, "lucent-example-window: error: %s\n", e.what());
        status = 1;
    }
    glfwDestroyWindow(window);
    glfwTerminate();
    return status;
}

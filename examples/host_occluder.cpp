// A host program that draws its own frame with plain OpenGL (a floor and an
// opaque box) and lets Lucent add a translucent sphere to it. The box stands in
// front of the sphere: Lucent reads the host's depth texture, so the light the
// sphere scatters behind the box stays hidden.
//
//   lucent-example-host SCENE.json OUT.pfm [--no-occluder] [--depth32f] [--full-resolution]
//
// --full-resolution draws Lucent's scattering at every pixel instead of its
// default, reduced where the samples allow (DrawOptions::scatterScale).
//
// --depth32f gives the host a GL_DEPTH_COMPONENT32F depth texture instead of
// GL_DEPTH24_STENCIL8: Lucent reads either.
//
// SCENE.json is a Lucent scene whose first object has been preprocessed.
//
// The host reaches OpenGL through its own loader, libepoxy, as an engine would;
// Lucent keeps its own (runtime/opengl.h), and the two never meet.
#include <epoxy/gl.h>
#include <glm/gtc/type_ptr.hpp>

#include <cstdio>
#include <cstring>
#include <vector>

#include "core/error.h"
#include "core/image.h"
#include "core/sample_set.h"
#include "core/scene.h"
#include "core/volume_object.h"
#include "runtime/offscreen_context.h"
#include "runtime/scattering_renderer.h"

namespace {

const char* kVertex = R"(#version 450 core
layout(location = 0) in vec3 position;
uniform mat4 viewProjection;
void main() { gl_Position = viewProjection * vec4(position, 1.0); })";
const char* kFragment = R"(#version 450 core
uniform vec3 colour;
out vec4 result;
void main() { result = vec4(colour, 1.0); })";

GLuint compile(GLenum type, const char* source) {
    GLuint s = glCreateShader(type);
    glShaderSource(s, 1, &source, nullptr);
    glCompileShader(s);
    return s;
}

// A box as 12 triangles.
std::vector<glm::vec3> box(glm::vec3 lo, glm::vec3 hi) {
    std::vector<glm::vec3> c;
    for (int i = 0; i < 8; ++i) c.emplace_back(i & 4 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 1 ? hi.z : lo.z);
    const int quads[6][4] = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
    std::vector<glm::vec3> t;
    for (const auto& q : quads)
        for (int k : {0, 1, 2, 0, 2, 3}) t.push_back(c[q[k]]);
    return t;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: %s SCENE.json OUT.pfm [--no-occluder] [--depth32f] [--full-resolution]\n",
                     argv[0]);
        return 2;
    }
    bool occluder = true, depth32f = false, fullResolution = false;
    for (int a = 3; a < argc; ++a) {
        if (std::strcmp(argv[a], "--no-occluder") == 0)
            occluder = false;
        else if (std::strcmp(argv[a], "--depth32f") == 0)
            depth32f = true;
        else if (std::strcmp(argv[a], "--full-resolution") == 0)
            fullResolution = true;
        else {
            std::fprintf(stderr, "lucent-example-host: unknown option %s\n", argv[a]);
            return 2;
        }
    }
    try {
        const lucent::SceneDesc scene = lucent::parseScene(argv[1]);
        std::vector<std::string> warnings;
        const lucent::VolumeObject object(scene.objects.front(), warnings);
        const lucent::SampleSet samples = lucent::readSampleFile(scene.objects.front().samples);

        const auto context = lucent::OffscreenContext::create(lucent::GlBackend::Auto);
        const int w = scene.camera.width, h = scene.camera.height;
        lucent::Bounds3 bounds = object.mesh().bounds();
        bounds.extend(lucent::Vec3(-4, -1.2, -4));
        bounds.extend(lucent::Vec3(4, 1.2, 4));
        const lucent::ViewSetup view = lucent::viewSetupFor(scene.camera, bounds);

        // The host's own framebuffer: float colour and a depth texture.
        GLuint colour, depth, framebuffer;
        glCreateTextures(GL_TEXTURE_2D, 1, &colour);
        glTextureStorage2D(colour, 1, GL_RGBA32F, w, h);
        glCreateTextures(GL_TEXTURE_2D, 1, &depth);
        glTextureStorage2D(depth, 1, depth32f ? GL_DEPTH_COMPONENT32F : GL_DEPTH24_STENCIL8, w, h);
        glCreateFramebuffers(1, &framebuffer);
        glNamedFramebufferTexture(framebuffer, GL_COLOR_ATTACHMENT0, colour, 0);
        glNamedFramebufferTexture(framebuffer, depth32f ? GL_DEPTH_ATTACHMENT : GL_DEPTH_STENCIL_ATTACHMENT, depth, 0);
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
        glViewport(0, 0, w, h);
        glClearColor(0, 0, 0, 0);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

        // The host's geometry: a dim floor under the sphere and a dark box in front of it.
        GLuint program = glCreateProgram();
        glAttachShader(program, compile(GL_VERTEX_SHADER, kVertex));
        glAttachShader(program, compile(GL_FRAGMENT_SHADER, kFragment));
        glLinkProgram(program);
        std::vector<glm::vec3> floor = box({-4, -1.2f, -4}, {4, -1.1f, 4});
        std::vector<glm::vec3> block = box({-1.2f, -1.1f, 1.3f}, {0.0f, 1.2f, 1.6f});
        GLuint vao, buffer;
        glCreateVertexArrays(1, &vao);
        glCreateBuffers(1, &buffer);
        std::vector<glm::vec3> all = floor;
        if (occluder) all.insert(all.end(), block.begin(), block.end());
        glNamedBufferStorage(buffer, GLsizeiptr(all.size() * sizeof(glm::vec3)), all.data(), 0);
        glVertexArrayVertexBuffer(vao, 0, buffer, 0, sizeof(glm::vec3));
        glEnableVertexArrayAttrib(vao, 0);
        glVertexArrayAttribFormat(vao, 0, 3, GL_FLOAT, GL_FALSE, 0);
        glVertexArrayAttribBinding(vao, 0, 0);
        glUseProgram(program);
        const glm::mat4 viewProjection = view.projection * view.view;
        glUniformMatrix4fv(glGetUniformLocation(program, "viewProjection"), 1, GL_FALSE,
                           glm::value_ptr(viewProjection));
        glEnable(GL_DEPTH_TEST);
        glBindVertexArray(vao);
        glUniform3f(glGetUniformLocation(program, "colour"), 0.02f, 0.02f, 0.025f);
        glDrawArrays(GL_TRIANGLES, 0, GLsizei(floor.size()));
        if (occluder) {
            glUniform3f(glGetUniformLocation(program, "colour"), 0.001f, 0.0f, 0.0f);
            glDrawArrays(GL_TRIANGLES, GLsizei(floor.size()), GLsizei(block.size()));
        }

        // Lucent adds the translucent sphere, occluded by the host's depth.
        lucent::ScatteringRenderer lucentRenderer;
        lucentRenderer.addObject(lucent::translucentObjectFor(object, samples));
        lucentRenderer.setLights(scene.lights);
        lucent::DrawOptions options;
        options.hostDepthTexture = depth;
        if (fullResolution) options.scatterScale = 1;
        lucentRenderer.draw(view, options);

        std::vector<float> rgba(size_t(w) * h * 4);
        glGetTextureImage(colour, 0, GL_RGBA, GL_FLOAT, GLsizei(rgba.size() * sizeof(float)), rgba.data());
        lucent::Image image(w, h);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const float* p = &rgba[(size_t(h - 1 - y) * w + x) * 4];
                image.at(x, y) = {p[0], p[1], p[2]};
            }
        lucent::writeImage(argv[2], image);
        std::fprintf(stderr, "lucent-example-host: wrote %s (%s)\n", argv[2], context->backendName());
    } catch (const lucent::Error& e) {
        std::fprintf(stderr, "lucent-example-host: error: %s\n", e.what());
        return 1;
    }
    return 0;
}

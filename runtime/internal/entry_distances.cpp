#include "runtime/internal/entry_distances.h"

#include <glm/gtc/type_ptr.hpp>

#include <array>

#include "core/error.h"
#include "runtime/internal/blocker_shadow_views.h"
#include "runtime/internal/gpu_layout.h"
#include "runtime/internal/placement_uniforms.h"

namespace lucent {

EntryDistances::EntryDistances(const Bounds3& bounds)
    : bounds_(bounds), program_{{GL_VERTEX_SHADER, "mesh.vert"}, {GL_FRAGMENT_SHADER, "entry_distances.frag"}} {}

EntryDistances::~EntryDistances() { release(); }

void EntryDistances::release() {
    if (framebuffer_) glDeleteFramebuffers(1, &framebuffer_);
    for (GLuint* t : {&planes_, &exits_, &next_, &depth_})
        if (*t) glDeleteTextures(1, t);
    if (views_) glDeleteBuffers(1, &views_);
    framebuffer_ = planes_ = exits_ = next_ = depth_ = views_ = 0;
    layers_ = size_ = 0;
}

void EntryDistances::allocate(int layers, int size) {
    if (layers == layers_ && size == size_) return;
    release();
    layers_ = layers;
    size_ = size;
    for (auto [texture, format] : {std::pair{&planes_, GLenum(GL_RGBA32F)}, std::pair{&exits_, GLenum(GL_R32F)},
                                   std::pair{&next_, GLenum(GL_R32F)}}) {
        glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, texture);
        glTextureStorage3D(*texture, 1, format, size, size, layers);
        glTextureParameteri(*texture, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTextureParameteri(*texture, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    }
    // The entries' depth test, one layer at a time.
    glCreateTextures(GL_TEXTURE_2D, 1, &depth_);
    glTextureStorage2D(depth_, 1, GL_DEPTH_COMPONENT32F, size, size);
    glCreateFramebuffers(1, &framebuffer_);
    glCreateBuffers(1, &views_);
    glNamedBufferStorage(views_, GLsizeiptr(layers * sizeof(glm::mat4)), nullptr, GL_DYNAMIC_STORAGE_BIT);
}

void EntryDistances::render(const GpuMesh& mesh, const std::vector<Light>& lights, const Similarity& placement) {
    allocate(blockerShadowLayers(lights.size()), entryMapResolution(lights.size()));
    const std::vector<glm::mat4> views = blockerShadowViews(lights, placedBox(bounds_, placement));
    glNamedBufferSubData(views_, 0, GLsizeiptr(views.size() * sizeof(glm::mat4)), views.data());

    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer_);
    glViewport(0, 0, size_, size_);
    glDisable(GL_CULL_FACE);
    glUseProgram(program_.id());
    setMeshPlacement(program_, placement);
    // Entries: the nearest by the depth test (a plane is not MIN-blended).
    glNamedFramebufferTexture(framebuffer_, GL_DEPTH_ATTACHMENT, depth_, 0);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    drawLayers(mesh, lights, views, 0);
    // Exits, then the entries beyond them: distances, MIN-blended.
    glNamedFramebufferTexture(framebuffer_, GL_DEPTH_ATTACHMENT, 0, 0);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    glBlendEquation(GL_MIN);
    drawLayers(mesh, lights, views, 1);
    glBindTextureUnit(0, exits_);  // read by the last pass only: drawn into by the one before
    glUniform1i(program_.uniform("exits"), 0);
    drawLayers(mesh, lights, views, 2);
    glBlendEquation(GL_FUNC_ADD);
    glDisable(GL_BLEND);
}

void EntryDistances::drawLayers(const GpuMesh& mesh, const std::vector<Light>& lights,
                                const std::vector<glm::mat4>& views, int pass) {
    // None: a zero normal (optically_thick.frag tests it), no exit, no next entry.
    const std::array<float, 4> none = pass == 0 ? std::array<float, 4>{0.0f, 0.0f, 0.0f, 0.0f}
                                                : std::array<float, 4>{3.0e38f, 3.0e38f, 3.0e38f, 3.0e38f};
    const GLuint target = pass == 0 ? planes_ : (pass == 1 ? exits_ : next_);
    glUniform1i(program_.uniform("pass"), pass);
    for (int layer = 0; layer < layers_; ++layer) {
        glNamedFramebufferTextureLayer(framebuffer_, GL_COLOR_ATTACHMENT0, target, 0, layer);
        glClearNamedFramebufferfv(framebuffer_, GL_COLOR, 0, none.data());
        if (pass == 0) {
            const float far = 1.0f;
            glClearNamedFramebufferfv(framebuffer_, GL_DEPTH, 0, &far);
        }
        const Light* l = layerLight(lights, layer);
        if (!l) continue;
        if (layer % 6 == 0 && glCheckNamedFramebufferStatus(framebuffer_, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
            throw Error("OpenGL: the entry distances' framebuffer is incomplete");
        glUniform4fv(program_.uniform("light"), 1, glm::value_ptr(packedLight(*l)));
        glUniform1i(program_.uniform("layer"), layer);
        glUniformMatrix4fv(program_.uniform("viewProjection"), 1, GL_FALSE, glm::value_ptr(views[size_t(layer)]));
        mesh.draw();
    }
}

void EntryDistances::bind() const {
    glBindTextureUnit(gpu::kUnitEntryPlanes, planes_);
    glBindTextureUnit(gpu::kUnitEntryExits, exits_);
    glBindTextureUnit(gpu::kUnitNextEntries, next_);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingShadowViews, views_);
}

}  // namespace lucent

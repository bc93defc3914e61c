#include "runtime/scattering_renderer.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/mesh_raycaster.h"
#include "runtime/blocker_shadows.h"
#include "runtime/embedded_shaders.h"
#include "runtime/gl_program.h"
#include "runtime/mesh_pass.h"
#include "runtime/scattering_pass.h"

namespace lucent {

TranslucentObject translucentObjectFor(const VolumeObject& object, const SampleSet& samples) {
    TranslucentObject t{&object.mesh(), &samples, object.desc().medium.g, object.desc().surface, {},
                        object.desc().medium.albedo};
    for (const TriangleMesh& blocker : object.blockerMeshes()) t.blockers.push_back(&blocker);
    return t;
}

ViewSetup viewSetupFor(const Camera& camera, const Bounds3& sceneBounds) {
    ViewSetup v;
    v.width = camera.width;
    v.height = camera.height;
    v.cameraPosition = glm::vec3(camera.position);
    v.view = glm::lookAt(camera.position, camera.target, camera.up);
    // Near and far planes hug the scene so that depth keeps its precision.
    const double radius = 0.5 * sceneBounds.diagonal();
    const double distance = glm::length(sceneBounds.center() - camera.position);
    const double farPlane = distance + 2.0 * radius + 1e-6;
    const double nearPlane = std::max(distance - 2.0 * radius, farPlane * 1e-5);
    v.projection = glm::perspective(glm::radians(camera.fovYDegrees), double(camera.width) / camera.height,
                                    nearPlane, farPlane);
    return v;
}

namespace {

// A framebuffer with one texture the later passes sample: a depth texture
// (GL_DEPTH_COMPONENT32F) or a colour one (the RG32F ray segments).
struct TextureTarget {
    GLenum format;
    GLuint framebuffer = 0, texture = 0;
    int width = 0, height = 0;
    explicit TextureTarget(GLenum textureFormat) : format(textureFormat) {}
    bool isDepth() const { return format == GL_DEPTH_COMPONENT32F; }
    void resize(int w, int h) {
        if (w == width && h == height) return;
        release();
        width = w;
        height = h;
        glCreateTextures(GL_TEXTURE_2D, 1, &texture);
        glTextureStorage2D(texture, 1, format, w, h);
        glTextureParameteri(texture, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTextureParameteri(texture, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glCreateFramebuffers(1, &framebuffer);
        glNamedFramebufferTexture(framebuffer, isDepth() ? GL_DEPTH_ATTACHMENT : GL_COLOR_ATTACHMENT0, texture, 0);
        if (isDepth()) glNamedFramebufferDrawBuffer(framebuffer, GL_NONE);
        if (glCheckNamedFramebufferStatus(framebuffer, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
            throw Error("OpenGL: an internal framebuffer is incomplete");
    }
    void clearDepth(float depth) const { glClearNamedFramebufferfv(framebuffer, GL_DEPTH, 0, &depth); }
    void release() {
        if (framebuffer) glDeleteFramebuffers(1, &framebuffer);
        if (texture) glDeleteTextures(1, &texture);
        framebuffer = texture = 0;
        width = height = 0;
    }
};

// GLSL has no #include: insert the shared sample-and-light code after the #version line.
std::string withSampleLight(const char* source) {
    const std::string text = source;
    const size_t eol = text.find('\n') + 1;
    return text.substr(0, eol) + shaders::sample_light_glsl + text.substr(eol);
}

std::string withDefine(const char* source, const char* name) {
    const std::string text = source;
    const size_t eol = text.find('\n') + 1;
    return text.substr(0, eol) + "#define " + name + "\n" + text.substr(eol);
}

void setShNormalisation(const GlProgram& program) {
    // sqrt(2) K_lm (K_l0 for m = 0), so the shaders need no factorials.
    float normalisation[64];
    for (int l = 0; l < 8; ++l)
        for (int m = 0; m <= l; ++m) {
            double ratio = 1.0;  // (l-m)! / (l+m)!
            for (int j = l - m + 1; j <= l + m; ++j) ratio /= double(j);
            const double k = std::sqrt((2.0 * l + 1.0) / (4.0 * kPi) * ratio);
            normalisation[l * l + l + m] = float(m == 0 ? k : std::sqrt(2.0) * k);
        }
    glProgramUniform1fv(program.id(), program.uniform("shNormalisation"), 64, normalisation);
}

struct Object {
    std::unique_ptr<GpuMesh> mesh;
    std::unique_ptr<GpuSamples> samples;
    double g;
    std::optional<SurfaceDesc> surface;
    std::vector<std::unique_ptr<GpuMesh>> blockers;
    std::unique_ptr<MeshRaycaster> boundary;  // is the camera inside?
    std::unique_ptr<BlockerShadows> shadows;  // the Lucent scheme's blockers, shadowed per light
    bool shadowsValid = false;
    Rgb albedo{0.0};
    bool skin = false;  // optically thick: drawn by shaders/skin.frag, no samples
};

// Texture unit of the blocker shadow maps in both sample programs (unit 0 holds the ray segments).
constexpr GLuint kShadowUnit = 1;

}  // namespace

struct ScatteringRenderer::Impl {
    double cutoffSigmas;
    GlProgram depthProgram{{GL_VERTEX_SHADER, "shaders/mesh.vert", shaders::mesh_vert},
                           {GL_FRAGMENT_SHADER, "shaders/depth_only.frag", shaders::depth_only_frag}};
    GlProgram surfaceProgram{{GL_VERTEX_SHADER, "shaders/mesh.vert", shaders::mesh_vert},
                             {GL_FRAGMENT_SHADER, "shaders/surface.frag", shaders::surface_frag}};
    GlProgram skinProgram{{GL_VERTEX_SHADER, "shaders/mesh.vert", shaders::mesh_vert},
                          {GL_FRAGMENT_SHADER, "shaders/skin.frag", shaders::skin_frag}};
    std::string scatterVertex = withSampleLight(shaders::scatter_vert);
    std::string receivedCompute = withSampleLight(shaders::received_comp);
    GlProgram scatterProgram{{GL_VERTEX_SHADER, "shaders/scatter.vert", scatterVertex.c_str()},
                             {GL_GEOMETRY_SHADER, "shaders/scatter.geom", shaders::scatter_geom},
                             {GL_FRAGMENT_SHADER, "shaders/scatter.frag", shaders::scatter_frag}};
    // The same for objects of density slabs (shaders/scatter.frag, DENSITY_SLABS).
    std::string scatterSlabsFragment = withDefine(shaders::scatter_frag, "DENSITY_SLABS");
    GlProgram scatterSlabsProgram{{GL_VERTEX_SHADER, "shaders/scatter.vert", scatterVertex.c_str()},
                                  {GL_GEOMETRY_SHADER, "shaders/scatter.geom", shaders::scatter_geom},
                                  {GL_FRAGMENT_SHADER, "shaders/scatter.frag", scatterSlabsFragment.c_str()}};
    GlProgram receivedProgram{{GL_COMPUTE_SHADER, "shaders/received.comp", receivedCompute.c_str()}};
    GlProgram copyDepthProgram{{GL_VERTEX_SHADER, "shaders/fullscreen.vert", shaders::fullscreen_vert},
                               {GL_FRAGMENT_SHADER, "shaders/copy_depth.frag", shaders::copy_depth_frag}};
    GlProgram segmentProgram{{GL_VERTEX_SHADER, "shaders/fullscreen.vert", shaders::fullscreen_vert},
                             {GL_FRAGMENT_SHADER, "shaders/segment.frag", shaders::segment_frag}};
    std::vector<Object> objects;
    GLuint lightBuffer = 0;
    int lightCount = 0;
    std::vector<Light> lights;
    TextureTarget front{GL_DEPTH_COMPONENT32F}, back{GL_DEPTH_COMPONENT32F}, host{GL_DEPTH_COMPONENT32F};
    TextureTarget segments{GL_RG32F};
    GLuint emptyVao = 0;

    explicit Impl(double cutoff) : cutoffSigmas(std::sqrt(2.0 * std::log(1.0 / cutoff))) {
        glCreateVertexArrays(1, &emptyVao);
        for (const GlProgram* p : {&scatterProgram, &scatterSlabsProgram, &receivedProgram}) {
            setShNormalisation(*p);
            glProgramUniform1i(p->id(), p->uniform("shadowDistances"), GLint(kShadowUnit));
        }
    }
    ~Impl() {
        front.release();
        back.release();
        host.release();
        segments.release();
        if (lightBuffer) glDeleteBuffers(1, &lightBuffer);
        glDeleteVertexArrays(1, &emptyVao);
    }

    void drawMeshes() const {
        for (const Object& o : objects) o.mesh->draw();
    }
};

ScatteringRenderer::ScatteringRenderer(double cutoff) {
    if (!(cutoff > 0.0 && cutoff < 1.0)) throw Error("Gaussian cut-off must lie in (0, 1)");
    impl_ = std::make_unique<Impl>(cutoff);
}

ScatteringRenderer::~ScatteringRenderer() = default;

void ScatteringRenderer::addObject(const TranslucentObject& object) {
    Object o{std::make_unique<GpuMesh>(*object.mesh), std::make_unique<GpuSamples>(*object.samples), object.g,
             object.surface, {}, std::make_unique<MeshRaycaster>(*object.mesh), nullptr};
    for (const TriangleMesh* blocker : object.blockers) o.blockers.push_back(std::make_unique<GpuMesh>(*blocker));
    if (!object.blockers.empty() && object.samples->parameters.scheme == SampleScheme::Lucent)
        o.shadows = std::make_unique<BlockerShadows>(object.blockers);
    o.albedo = object.albedo;
    o.skin = object.samples->parameters.scheme == SampleScheme::Skin;
    impl_->objects.push_back(std::move(o));
}

size_t ScatteringRenderer::sampleCount() const {
    size_t n = 0;
    for (const Object& o : impl_->objects) n += o.samples->size();
    return n;
}

void ScatteringRenderer::setLights(const std::vector<Light>& lights) {
    std::vector<glm::vec4> packed;
    for (const Light& l : lights) {
        if (l.type == Light::Type::Point) packed.emplace_back(glm::vec3(l.position), 1.0f);
        else packed.emplace_back(glm::vec3(l.direction), 0.0f);
        packed.emplace_back(glm::vec3(l.power), 0.0f);
    }
    if (impl_->lightBuffer) glDeleteBuffers(1, &impl_->lightBuffer);
    glCreateBuffers(1, &impl_->lightBuffer);
    glNamedBufferStorage(impl_->lightBuffer, GLsizeiptr(std::max<size_t>(packed.size(), 1) * sizeof(glm::vec4)),
                         packed.empty() ? nullptr : packed.data(), 0);
    impl_->lightCount = int(lights.size());
    impl_->lights = lights;
    for (Object& o : impl_->objects) {
        o.samples->receivedValid = false;
        o.shadowsValid = false;
    }
}

void ScatteringRenderer::draw(const ViewSetup& view, const DrawOptions& options) {
    Impl& r = *impl_;
    GLint target = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &target);
    const glm::mat4 viewProjection = view.projection * view.view;
    for (Object& o : r.objects)
        if (o.shadows && !o.shadowsValid) {
            o.shadows->render(r.lights);
            o.shadowsValid = true;
        }
    r.front.resize(view.width, view.height);
    r.back.resize(view.width, view.height);
    r.host.resize(view.width, view.height);
    r.segments.resize(view.width, view.height);
    glViewport(0, 0, view.width, view.height);
    glDisable(GL_BLEND);
    glEnable(GL_DEPTH_TEST);
    glDepthMask(GL_TRUE);

    // The host's depth, copied so that no pass samples a texture it draws into.
    r.host.clearDepth(1.0f);
    if (options.hostDepthTexture) {
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, r.host.framebuffer);
        glDepthFunc(GL_ALWAYS);
        glUseProgram(r.copyDepthProgram.id());
        glBindTextureUnit(0, options.hostDepthTexture);
        glUniform1i(r.copyDepthProgram.uniform("source"), 0);
        glBindVertexArray(r.emptyVao);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    // Blockers are opaque: the camera's rays stop at their front faces as at the host's geometry.
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glDepthFunc(GL_LESS);
    glUseProgram(r.depthProgram.id());
    glUniformMatrix4fv(r.depthProgram.uniform("viewProjection"), 1, GL_FALSE, glm::value_ptr(viewProjection));
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, r.host.framebuffer);
    for (const Object& o : r.objects)
        for (const auto& blocker : o.blockers) blocker->draw();

    // Where each pixel's ray enters the objects (nearest front face) and finally
    // leaves them (farthest back face).
    r.front.clearDepth(1.0f);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, r.front.framebuffer);
    glCullFace(GL_BACK);
    glDepthFunc(GL_LESS);
    r.drawMeshes();
    r.back.clearDepth(0.0f);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, r.back.framebuffer);
    glCullFace(GL_FRONT);
    glDepthFunc(GL_GREATER);
    r.drawMeshes();
    glCullFace(GL_BACK);
    glDepthFunc(GL_LESS);

    // Each pixel's ray segment inside the objects, once, so that the scattering
    // fragments read one texel instead of three depths and three unprojections.
    const glm::mat4 inverseProjection = glm::inverse(view.projection);
    if (options.scattering) {
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, r.segments.framebuffer);
        glDisable(GL_DEPTH_TEST);
        glDisable(GL_CULL_FACE);
        const GlProgram& p = r.segmentProgram;
        glUseProgram(p.id());
        glUniformMatrix4fv(p.uniform("inverseProjection"), 1, GL_FALSE, glm::value_ptr(inverseProjection));
        glUniform2f(p.uniform("viewportSize"), float(view.width), float(view.height));
        // A camera inside an object sees no front face in front of it: its rays start inside.
        bool cameraInside = false;
        for (const Object& o : r.objects) cameraInside = cameraInside || o.boundary->contains(Vec3(view.cameraPosition));
        glUniform1i(p.uniform("cameraInside"), cameraInside ? 1 : 0);
        glBindTextureUnit(0, r.front.texture);
        glBindTextureUnit(1, r.back.texture);
        glBindTextureUnit(2, r.host.texture);
        glUniform1i(p.uniform("frontDepth"), 0);
        glUniform1i(p.uniform("backDepth"), 1);
        glUniform1i(p.uniform("hostDepth"), 2);
        glBindVertexArray(r.emptyVao);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glEnable(GL_DEPTH_TEST);
    }

    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(target));
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, r.lightBuffer);

    // Pass 1: reflected surface, tested against the host's depth, writing none.
    // Both passes over the meshes' nearest front faces add light, writing no depth.
    auto beginMeshPass = [&](const GlProgram& p) {
        glUseProgram(p.id());
        glUniformMatrix4fv(p.uniform("viewProjection"), 1, GL_FALSE, glm::value_ptr(viewProjection));
        glUniform1i(p.uniform("lightCount"), r.lightCount);
        glUniform3fv(p.uniform("cameraPosition"), 1, glm::value_ptr(view.cameraPosition));
        glBindTextureUnit(0, r.front.texture);
        glUniform1i(p.uniform("frontDepth"), 0);
        glDisable(GL_CULL_FACE);
        glDepthMask(GL_FALSE);
        glEnable(GL_BLEND);
        glBlendFunc(GL_ONE, GL_ONE);
    };
    if (options.surface) {
        const GlProgram& p = r.surfaceProgram;
        beginMeshPass(p);
        for (const Object& o : r.objects) {
            if (!o.surface) continue;
            glUniform3fv(p.uniform("diffuse"), 1, glm::value_ptr(glm::vec3(o.surface->diffuse)));
            glUniform3fv(p.uniform("specular"), 1, glm::value_ptr(glm::vec3(o.surface->specular)));
            glUniform1f(p.uniform("shininess"), float(o.surface->shininess));
            o.mesh->draw();
        }
    }

    // Optically thick objects: the single scattering of the sliver under their
    // surface, in closed form, tested against the host's depth like the surface.
    if (options.scattering && std::any_of(r.objects.begin(), r.objects.end(), [](const Object& o) { return o.skin; })) {
        const GlProgram& p = r.skinProgram;
        beginMeshPass(p);
        for (const Object& o : r.objects) {
            if (!o.skin) continue;
            glUniform3fv(p.uniform("albedo"), 1, glm::value_ptr(glm::vec3(o.albedo)));
            glUniform1f(p.uniform("g"), float(o.g));
            o.mesh->draw();
        }
    }

    // Pass 2: every sample's Gaussian, integrated along each pixel's ray, summed.
    if (options.scattering) {
        glDisable(GL_DEPTH_TEST);
        glDisable(GL_CULL_FACE);
        glDepthMask(GL_FALSE);
        glEnable(GL_BLEND);
        glBlendFunc(GL_ONE, GL_ONE);
        const glm::mat3 viewToWorld = glm::transpose(glm::mat3(view.view));
        // View-space direction through pixel (x, y) at z = -1 for this projection.
        const glm::mat4& P = view.projection;
        const glm::vec4 pixelToView(2.0f / (view.width * P[0][0]), 2.0f / (view.height * P[1][1]),
                                    (P[2][0] - 1.0f) / P[0][0], (P[2][1] - 1.0f) / P[1][1]);
        for (const GlProgram* program : {&r.scatterProgram, &r.scatterSlabsProgram}) {
            const GLuint id = program->id();
            glProgramUniformMatrix4fv(id, program->uniform("view"), 1, GL_FALSE, glm::value_ptr(view.view));
            glProgramUniformMatrix4fv(id, program->uniform("projection"), 1, GL_FALSE, glm::value_ptr(view.projection));
            glProgramUniform3fv(id, program->uniform("cameraPosition"), 1, glm::value_ptr(view.cameraPosition));
            glProgramUniformMatrix3fv(id, program->uniform("viewToWorld"), 1, GL_FALSE, glm::value_ptr(viewToWorld));
            glProgramUniform4fv(id, program->uniform("pixelToView"), 1, glm::value_ptr(pixelToView));
            glProgramUniform1i(id, program->uniform("lightCount"), r.lightCount);
            glProgramUniform1f(id, program->uniform("cutoffSigmas"), float(r.cutoffSigmas));
            glProgramUniform1f(id, program->uniform("discardBelow"), options.discardBelow);
            glProgramUniform1f(id, program->uniform("extinctionScale"), options.extinctionScale);
            glProgramUniform1i(id, program->uniform("raySegments"), 0);
        }
        glBindTextureUnit(0, r.segments.texture);
        for (const Object& o : r.objects) {
            const auto& slabs = o.samples->slabBounds();
            const GlProgram& p = slabs.empty() ? r.scatterProgram : r.scatterSlabsProgram;
            o.samples->bind();
            if (o.shadows) o.shadows->bind(kShadowUnit);
            for (const GlProgram* program : {&p, static_cast<const GlProgram*>(&r.receivedProgram)})
                glProgramUniform1i(program->id(), program->uniform("blockerShadows"), o.shadows ? 1 : 0);
            // Isotropic media: the received light does not depend on the view, so it
            // is computed when the lights or the medium scale change, not every frame.
            const bool cache = o.g == 0.0;
            if (cache && (!o.samples->receivedValid || o.samples->receivedScale != options.extinctionScale)) {
                const GlProgram& c = r.receivedProgram;
                glUseProgram(c.id());
                glUniform1i(c.uniform("shOrder"), o.samples->shOrder());
                glUniform1i(c.uniform("channels"), o.samples->channels());
                glUniform1f(c.uniform("g"), 0.0f);
                glUniform1i(c.uniform("lightCount"), r.lightCount);
                glUniform1f(c.uniform("extinctionScale"), options.extinctionScale);
                glUniform1i(c.uniform("sampleCount"), GLint(o.samples->size()));
                o.samples->computeReceived();
                o.samples->receivedValid = true;
                o.samples->receivedScale = options.extinctionScale;
            }
            glUseProgram(p.id());
            glUniform1i(p.uniform("receivedIsCached"), cache ? 1 : 0);
            glUniform1i(p.uniform("shOrder"), o.samples->shOrder());
            glUniform1i(p.uniform("channels"), o.samples->channels());
            glUniform1f(p.uniform("g"), float(o.g));
            glUniform1i(p.uniform("regionAxis"), int(o.samples->parameters().regionAxis));
            glUniform1i(p.uniform("exactViewAttenuation"), o.samples->homogeneous() || !slabs.empty() ? 1 : 0);
            if (!slabs.empty()) {
                glUniform1i(p.uniform("slabCount"), GLint(slabs.size()));
                glUniform4fv(p.uniform("slabBounds"), GLsizei(slabs.size()), glm::value_ptr(slabs[0]));
                std::vector<glm::vec4> extinction = o.samples->slabExtinction();
                for (glm::vec4& e : extinction) e *= options.extinctionScale;
                glUniform4fv(p.uniform("slabExtinction"), GLsizei(slabs.size()), glm::value_ptr(extinction[0]));
            }
            glUniform1i(p.uniform("lightVaries"), o.samples->parameters().scheme == SampleScheme::Lucent ? 1 : 0);
            o.samples->draw();
        }
    }
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
    glEnable(GL_DEPTH_TEST);
}

}  // namespace lucent

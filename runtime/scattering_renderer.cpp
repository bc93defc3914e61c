#include "runtime/scattering_renderer.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.h"
#include "core/limits.h"
#include "runtime/internal/frame_targets.h"
#include "runtime/internal/grid_pass.h"
#include "runtime/internal/gpu_layout.h"
#include "runtime/internal/render_pass.h"
#include "runtime/internal/sample_pass.h"
#include "runtime/internal/surface_pass.h"
#include "runtime/internal/thick_pass.h"

namespace lucent {

TranslucentObject translucentObjectFor(const VolumeObject& object, const SampleSet& samples) {
    TranslucentObject t{&object.objectMesh(),  &samples, object.desc().medium.g,
                        object.desc().surface, {},       object.desc().medium.albedo,
                        object.placement(),    &object};
    for (const TriangleMesh& blocker : object.objectBlockerMeshes()) t.blockers.push_back(&blocker);
    return t;
}

struct ScatteringRenderer::Impl {
    std::vector<GpuObject> objects;
    GpuLights lights;
    FrameTargets targets;
    FrameTargets scatterTargets;  // at the scattering's reduced resolution, when it is reduced
    // In drawing order: the reflected surface, then single scattering (marched, then samples), then multiple.
    std::vector<std::unique_ptr<RenderPass>> passes;
    GridPass* grids = nullptr;

    explicit Impl(double cutoff) {
        passes.push_back(std::make_unique<SurfacePass>());
        passes.push_back(std::make_unique<ThickPass>());
        passes.push_back(std::make_unique<SamplePass>(cutoff));
        auto gridPass = std::make_unique<GridPass>();
        grids = gridPass.get();
        passes.push_back(std::move(gridPass));
    }
    ~Impl() {
        if (lights.buffer) glDeleteBuffers(1, &lights.buffer);
    }
    void retraceAll();
    void uploadLights();
};

int environmentShBands(double g) {
    static_assert(kEnvironmentShMaxBands == gpu::kEnvironmentShMaxBands, "sample_light.glsl's arrays hold them");
    int bands = 1;
    for (double weight = std::abs(g); bands < kEnvironmentShMaxBands && weight > kEnvironmentShBandWeight; ++bands)
        weight *= std::abs(g);
    return bands;
}

bool environmentShHolds(double g) { return std::pow(std::abs(g), kEnvironmentShMaxBands) <= kEnvironmentShBandWeight; }

int scatterScaleFor(double radiusPixels) {
    int scale = 1;
    while (scale < 4 && 2 * scale <= kReducedPixelPerRadius * radiusPixels) scale *= 2;
    return scale;
}

namespace {
// The smallest mean Poisson radius of the objects' samples, in pixels at each
// object's distance (its placed bounding box's centre); infinity without samples.
double sampleRadiusPixels(const std::vector<GpuObject>& objects, const ViewSetup& view) {
    // A pixel spans 2 / (P[1][1] height) per unit of distance.
    const double pixelPerDistance = 2.0 / (double(view.projection[1][1]) * view.height);
    double smallest = kInfinity;
    for (const GpuObject& o : objects) {
        if (o.opticallyThick || o.samples->size() == 0) continue;
        const Vec3 centre = o.placement.point(o.bounds.center());
        const double distance = std::max(glm::length(centre - Vec3(view.cameraPosition)), 1e-30);
        const double radius = o.samples->parameters().meanRadius * o.placement.scale;
        smallest = std::min(smallest, radius / (pixelPerDistance * distance));
    }
    return smallest;
}

// An optically thick object's sigma_t where its density is least, the most
// penetrating light (as the preprocessor decided it thick): ThickPass follows
// its view rays with it. Zero for an object with samples.
Rgb thickExtinction(bool opticallyThick, const VolumeObject* volume) {
    if (!opticallyThick) return Rgb(0.0);
    if (!volume)
        throw Error(
            "ScatteringRenderer: an optically thick object (no samples) needs its medium: set "
            "TranslucentObject::volume (translucentObjectFor does)");
    return volume->desc().medium.sigmaT * volume->density().minimum();
}
}  // namespace

ScatteringRenderer::ScatteringRenderer(double cutoff) {
    if (!(cutoff > 0.0 && cutoff < 1.0)) throw Error("Gaussian cut-off must lie in (0, 1)");
    if (!glLoaded())
        throw Error(
            "ScatteringRenderer: Lucent's OpenGL functions are not loaded: call lucent::loadGl with the "
            "context current first (runtime/opengl.h)");
    impl_ = std::make_unique<Impl>(cutoff);
}

ScatteringRenderer::~ScatteringRenderer() = default;

void ScatteringRenderer::addObject(const TranslucentObject& object) {
    GpuObject o;
    o.mesh = std::make_unique<GpuMesh>(*object.mesh);
    o.samples = std::make_unique<GpuSamples>(*object.samples);
    o.sampleSet = object.samples;
    o.volume = object.volume;
    o.placement = object.placement;
    o.g = object.g;
    o.surface = object.surface;
    o.boundaryMesh = object.mesh;
    o.bounds = object.mesh->bounds();
    for (const TriangleMesh* blocker : object.blockers) o.blockers.push_back(std::make_unique<GpuMesh>(*blocker));
    if (!object.blockers.empty() && object.samples->parameters.scheme == SampleScheme::Lucent)
        o.shadows = std::make_unique<BlockerShadows>(object.blockers);
    o.albedo = object.albedo;
    o.opticallyThick = object.samples->parameters.scheme == SampleScheme::OpticallyThick;
    o.extinction = thickExtinction(o.opticallyThick, object.volume);
    impl_->objects.push_back(std::move(o));
    impl_->retraceAll();
}

size_t ScatteringRenderer::objectCount() const { return impl_->objects.size(); }

namespace {
void checkIndex(const char* call, size_t index, size_t count) {
    if (index >= count)
        throw Error(std::string(call) + ": no object " + std::to_string(index) + " (" + std::to_string(count) +
                    " added)");
}
}  // namespace

// Every object's traced light crosses the others: adding, removing, moving or
// refilling one traces them all again.
void ScatteringRenderer::Impl::retraceAll() {
    for (GpuObject& o : objects) {
        o.samples->tracedValid = false;
        o.samples->receivedValid = false;
        o.samples->environmentValid = false;
    }
}

void ScatteringRenderer::removeObject(size_t index) {
    checkIndex("removeObject", index, impl_->objects.size());
    impl_->objects.erase(impl_->objects.begin() + long(index));
    impl_->retraceAll();
}

void ScatteringRenderer::setSamples(size_t index, const SampleSet& samples, const VolumeObject* volume) {
    checkIndex("setSamples", index, impl_->objects.size());
    GpuObject& o = impl_->objects[index];
    o.samples = std::make_unique<GpuSamples>(samples);
    o.sampleSet = &samples;
    o.volume = volume;
    o.refractedView = RefractedView{};  // traced for the medium it had (its ior, say)
    impl_->retraceAll();
    o.opticallyThick = samples.parameters.scheme == SampleScheme::OpticallyThick;
    o.extinction = thickExtinction(o.opticallyThick, volume);
    o.shadowsValid = false;
    o.entryDistancesValid = false;
}

void ScatteringRenderer::setAlbedoAndG(size_t index, const Rgb& albedo, double g) {
    checkIndex("setAlbedoAndG", index, impl_->objects.size());
    GpuObject& o = impl_->objects[index];
    o.albedo = albedo;
    o.g = g;
    o.samples->receivedValid = false;     // cached with the phase function of its g
    o.samples->environmentValid = false;  // projected onto the bands its g needs
}

void ScatteringRenderer::setPlacement(size_t index, const Similarity& placement) {
    checkIndex("setPlacement", index, impl_->objects.size());
    bool finite = placement.scale > 0.0 && std::isfinite(placement.scale) && isFinite(placement.translation);
    for (int c = 0; c < 3; ++c) finite = finite && isFinite(placement.rotation[c]);
    if (!finite)
        throw Error("setPlacement: the scale must be positive and finite, the rotation and translation finite");
    GpuObject& o = impl_->objects[index];
    if (placement == o.placement) return;
    o.placement = placement;
    o.shadowsValid = false;
    o.entryDistancesValid = false;
    impl_->retraceAll();
}

void ScatteringRenderer::addScatteringGrid(const ScatteringGrid& grid) { impl_->grids->add(grid); }
void ScatteringRenderer::clearScatteringGrids() { impl_->grids->clear(); }

size_t ScatteringRenderer::sampleCount() const {
    size_t n = 0;
    for (const GpuObject& o : impl_->objects) n += o.samples->size();
    return n;
}

void ScatteringRenderer::setLights(const std::vector<Light>& lights) {
    if (lights.size() + impl_->lights.environment.size() > kMaxLights)
        throw Error("ScatteringRenderer::setLights: " + std::to_string(lights.size()) + " lights and " +
                    std::to_string(impl_->lights.environment.size()) + " of the environment; at most " +
                    std::to_string(kMaxLights) + " in all");
    impl_->lights.lights = lights;
    impl_->uploadLights();
    for (GpuObject& o : impl_->objects) {
        o.samples->receivedValid = false;
        o.samples->tracedValid = false;
        o.shadowsValid = false;
        o.entryDistancesValid = false;
    }
}

void ScatteringRenderer::setEnvironment(const std::vector<Light>& directions) {
    if (impl_->lights.lights.size() + directions.size() > kMaxLights)
        throw Error("ScatteringRenderer::setEnvironment: " + std::to_string(directions.size()) + " directions and " +
                    std::to_string(impl_->lights.lights.size()) + " lights; at most " + std::to_string(kMaxLights) +
                    " in all");
    for (const Light& l : directions)
        if (l.type != Light::Type::Directional)
            throw Error("ScatteringRenderer::setEnvironment: the environment's lights must be directional");
    impl_->lights.environment = directions;
    impl_->uploadLights();
    for (GpuObject& o : impl_->objects) {
        o.samples->environmentValid = false;
        o.samples->receivedValid = false;
        o.entryDistancesValid = false;  // the thick pass loops over the environment's directions too
    }
}

void ScatteringRenderer::Impl::uploadLights() {
    static_assert(gpu::kMaxLights == kMaxLights, "lights.glsl's block holds the scene's limit");
    std::vector<gpu::Light> packed;
    packed.reserve(kMaxLights);
    for (const std::vector<Light>* list : {&lights.lights, &lights.environment})
        for (const Light& l : *list) {
            const bool point = l.type == Light::Type::Point;
            packed.push_back({glm::vec4(glm::vec3(point ? l.position : l.direction), point ? 1.0f : 0.0f),
                              glm::vec4(glm::vec3(l.power), float(l.radius)), glm::vec4(spotCoefficients(l))});
        }
    if (lights.buffer) glDeleteBuffers(1, &lights.buffer);
    glCreateBuffers(1, &lights.buffer);
    packed.resize(kMaxLights);  // the uniform block's whole size, as lights.glsl declares it
    glNamedBufferStorage(lights.buffer, GLsizeiptr(packed.size() * sizeof(gpu::Light)), packed.data(), 0);
}

void ScatteringRenderer::draw(const ViewSetup& view, const DrawOptions& options) {
    Impl& r = *impl_;
    GLint target = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &target);
    FrameContext frame{view, options, r.objects, r.lights, r.targets, view.projection * view.view, GLuint(target)};
    int scale = options.scatterScale == 0 ? scatterScaleFor(sampleRadiusPixels(r.objects, view)) : options.scatterScale;
    if (scale != 1 && scale != 2 && scale != 4) throw Error("DrawOptions::scatterScale must be 0, 1, 2 or 4");
    ViewSetup reduced = view;
    reduced.width = std::max((view.width + scale - 1) / scale, 1);
    reduced.height = std::max((view.height + scale - 1) / scale, 1);
    frame.scatterScale = scale;
    frame.scatterView = scale == 1 ? &view : &reduced;
    frame.scatterTargets = scale == 1 ? &r.targets : &r.scatterTargets;
    for (const auto& pass : r.passes) pass->prepare(frame);
    // Drawn reduced, the scattering asks of the full targets only the first
    // interval; the grids march the whole segment at full resolution, and so
    // do the optically thick objects' rays (ThickPass). The reduced targets'
    // layers come from one mesh pass: no surface reads them.
    const bool anyThick =
        std::any_of(r.objects.begin(), r.objects.end(), [](const GpuObject& o) { return o.opticallyThick; });
    r.targets.draw(frame, view,
                   scale != 1 && r.grids->empty() && !anyThick ? FrameTargets::Layers::FirstInterval
                                                               : FrameTargets::Layers::Peeled);
    if (scale != 1 && options.scattering) r.scatterTargets.draw(frame, reduced, FrameTargets::Layers::OnePass);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(target));
    glViewport(0, 0, view.width, view.height);
    glBindBufferBase(GL_UNIFORM_BUFFER, gpu::kBindingLights, r.lights.buffer);
    for (const auto& pass : r.passes) pass->draw(frame);
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
    glEnable(GL_DEPTH_TEST);
}

}  // namespace lucent

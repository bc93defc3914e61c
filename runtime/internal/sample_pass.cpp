#include "runtime/internal/sample_pass.h"

#include <glm/gtc/type_ptr.hpp>

#include <cmath>
#include <iterator>
#include <utility>

#include "core/error.h"
#include "core/math.h"
#include "runtime/internal/frame_targets.h"
#include "runtime/internal/gpu_layout.h"
#include "runtime/internal/placement_uniforms.h"
#include "runtime/internal/traced_light.h"

namespace lucent {
namespace {

// ARB_pipeline_statistics_query (core in 4.6; the loader is 4.5).
constexpr GLenum kFragmentShaderInvocations = 0x82F4;

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

}  // namespace

SamplePass::SamplePass(double cutoff)
    : cutoffSigmas_(std::sqrt(2.0 * std::log(1.0 / cutoff))),
      keptMassInverse_(1.0 / std::pow(std::erf(cutoffSigmas_ / std::sqrt(2.0)), 2)) {}

const GlProgram& SamplePass::receivedProgram(bool tracedLight, bool refracted, bool environment) const {
    std::vector<std::string> defines;
    if (tracedLight || refracted) defines.push_back("TRACED_LIGHT");
    if (refracted) defines.push_back("REFRACTED_LIGHT");
    if (environment) defines.push_back("ENVIRONMENT_SH");
    return receivedPrograms_.get(defines);
}

void SamplePass::setSampleUnits(const GlProgram& p) {
    setShNormalisation(p);
    glProgramUniform1i(p.id(), p.uniform("shadowDistances"), GLint(gpu::kUnitShadowDistances));
    glProgramUniform1i(p.id(), p.uniform("coefficients"), GLint(gpu::kUnitCoefficients));
    glProgramUniform1i(p.id(), p.uniform("refractedRays"), GLint(gpu::kUnitRefractedRays));
}

const GlProgram& SamplePass::scatterProgram(const ScatterVariant& variant) const {
    const std::pair<bool, const char*> features[] = {{variant.slabs, "DENSITY_SLABS"},
                                                     {variant.regions, "SAMPLE_REGIONS"},
                                                     {variant.viewFromFront, "VIEW_FROM_FRONT"},
                                                     {variant.countUseful, "COUNT_USEFUL_FRAGMENTS"},
                                                     {variant.receivedCached, "RECEIVED_CACHED"},
                                                     {variant.oneChannel, "ONE_CHANNEL"},
                                                     {variant.tracedLight, "TRACED_LIGHT"},
                                                     {variant.pointProxies, "POINT_PROXIES"},
                                                     {variant.refracted, "REFRACTED_LIGHT"},
                                                     {variant.refracted, "REFRACTED_VIEW"},
                                                     {variant.environmentSh, "ENVIRONMENT_SH"}};
    std::vector<std::string> defines;
    for (const auto& [wanted, define] : features)
        if (wanted) defines.push_back(define);
    return scatterPrograms_.get(defines);
}

bool SamplePass::pointProxiesCover(int width, int height) const {
    const float covered = float(gpu::kPointProxyTiles) * largestPoint_;
    return float(width) <= covered && float(height) <= covered;
}

namespace {

// The boundary refracts and the frame draws it so when the light is traced (drawnRefracted).
bool boundaryRefracts(const GpuObject& o) {
    return o.volume && !o.opticallyThick &&
           drawnRefracted(o.volume->desc().medium.ior, o.samples->attenuatesFromFront(), true);
}

}  // namespace

bool SamplePass::traced(const GpuObject& o, const FrameContext& frame) {
    return frame.options.tracedLight && o.volume && !o.opticallyThick && frame.lights.count() > 0 &&
           o.samples->tracedDepthsFit(frame.lights.count(), boundaryRefracts(o) ? 2 : 1);
}

bool SamplePass::refracted(const GpuObject& o, const FrameContext& frame) {
    return boundaryRefracts(o) && traced(o, frame);
}

void SamplePass::prepare(FrameContext& frame) {
    startTraces(frame);
    for (GpuObject& o : frame.objects)
        if (o.shadows && !o.shadowsValid && !traced(o, frame)) {
            o.shadows->render(frame.lights.lights, o.placement);
            o.shadowsValid = true;
        }
}

// Traced on the CPU while the frame's targets are drawn, which leave a core
// idle while llvmpipe loads their programs (docs/runtime.md); draw() waits.
void SamplePass::startTraces(FrameContext& frame) {
    pendingTraces_.clear();  // a frame that threw before draw(): waits for its traces, drops them
    pendingViews_.clear();
    std::vector<TracedVolume> volumes;
    for (const GpuObject& o : frame.objects)
        if (o.volume) volumes.push_back({o.volume, o.placement});
    size_t own = 0;  // o's place among the volumes
    for (GpuObject& o : frame.objects) {
        const bool bent = refracted(o, frame);
        if (traced(o, frame) && !o.samples->tracedValid)
            pendingTraces_.push_back(
                {o.samples.get(),
                 std::async(std::launch::async, [volumes, own, bent, samples = o.sampleSet, placement = o.placement,
                                                 lights = frame.lights.lights] {
                     return bent ? tracedRefractedLight(volumes, own, *samples, lights)
                                 : tracedOpticalDepths(volumes, *samples, placement, lights);
                 })});
        if (bent && !o.refractedView.current(*o.volume, o.placement, *frame.scatterView))
            pendingViews_.push_back({&o, std::async(std::launch::async, [volume = o.volume, placement = o.placement,
                                                                         view = *frame.scatterView] {
                                         return refractedViewRays(*volume, placement, view);
                                     })});
        if (o.volume) ++own;
    }
}

void SamplePass::setFrameUniforms(const GlProgram& program, const FrameContext& frame) const {
    const ViewSetup& view = *frame.scatterView;
    // View-space direction through pixel (x, y) at z = -1 for this projection.
    const glm::mat4& P = view.projection;
    const glm::vec4 pixelToView(2.0f / (view.width * P[0][0]), 2.0f / (view.height * P[1][1]),
                                (P[2][0] - 1.0f) / P[0][0], (P[2][1] - 1.0f) / P[1][1]);
    const GLuint id = program.id();
    glProgramUniformMatrix4fv(id, program.uniform("view"), 1, GL_FALSE, glm::value_ptr(view.view));
    glProgramUniformMatrix4fv(id, program.uniform("projection"), 1, GL_FALSE, glm::value_ptr(view.projection));
    glProgramUniform3fv(id, program.uniform("cameraPosition"), 1, glm::value_ptr(view.cameraPosition));
    glProgramUniform4fv(id, program.uniform("pixelToView"), 1, glm::value_ptr(pixelToView));
    glProgramUniform1i(id, program.uniform("lightCount"), frame.lights.count());
    glProgramUniform1f(id, program.uniform("cutoffSigmas"), float(cutoffSigmas_));
    glProgramUniform1f(id, program.uniform("keptMassInverse"), float(keptMassInverse_));
    if (frame.options.discardBelow > 0.0f)
        glProgramUniform1f(id, program.uniform("discardBelow"), frame.options.discardBelow);
    glProgramUniform1f(id, program.uniform("extinctionScale"), frame.options.extinctionScale);
    glProgramUniform1i(id, program.uniform("raySegments"), GLint(gpu::kUnitRaySegments));
    glProgramUniform1i(id, program.uniform("insideSegments"), GLint(gpu::kUnitInsideSegments));
    glProgramUniform2f(id, program.uniform("viewportSize"), float(view.width), float(view.height));
    glProgramUniform1f(id, program.uniform("largestPoint"), largestPoint_);
}

// Isotropic media: the received light does not depend on the view, so it is
// computed when the lights or the medium scale change, not every frame.
void SamplePass::updateReceived(GpuObject& o, const FrameContext& frame) const {
    const float scale = frame.options.extinctionScale;
    const bool tracedLight = traced(o, frame);
    if (o.samples->receivedValid && o.samples->receivedScale == scale && o.samples->receivedTraced == tracedLight)
        return;
    const GlProgram& c = receivedProgram(tracedLight, refracted(o, frame), environmentSh(o, frame));
    glUseProgram(c.id());
    glUniform1i(c.uniform("shOrder"), o.samples->shOrder());
    glUniform1i(c.uniform("channels"), o.samples->channels());
    glUniform1f(c.uniform("g"), 0.0f);
    glUniform1i(c.uniform("lightCount"), frame.lights.count());
    glUniform1f(c.uniform("extinctionScale"), scale);
    glUniform1i(c.uniform("sampleCount"), GLint(o.samples->size()));
    o.samples->computeReceived();
    o.samples->receivedValid = true;
    o.samples->receivedScale = scale;
    o.samples->receivedTraced = tracedLight;
}

bool SamplePass::environmentSh(const GpuObject& o, const FrameContext& frame) {
    return frame.lights.environmentCount() > 0 && !o.opticallyThick && o.samples->size() > 0;
}

// Once per change of the environment, the placements or the medium scale.
void SamplePass::updateEnvironment(GpuObject& o, const FrameContext& frame) const {
    const float scale = frame.options.extinctionScale;
    if (!environmentSh(o, frame) || (o.samples->environmentValid && o.samples->environmentScale == scale)) return;
    const int bands = environmentShBands(o.g);
    if (!o.samples->environmentFits(bands))
        throw Error("the environment's light in " + std::to_string(bands) + " SH bands for " +
                    std::to_string(o.samples->size()) +
                    " samples needs more shader storage than this OpenGL allows: preprocess with fewer samples, "
                    "or trace the light (--light traced)");
    const GlProgram& c = environmentPrograms_.get();
    setSamplePlacement(c, o.placement, o.samples->parameters().placementScale);
    o.samples->bind(true);
    glUseProgram(c.id());
    glUniform1i(c.uniform("shOrder"), o.samples->shOrder());
    glUniform1i(c.uniform("channels"), o.samples->channels());
    glUniform1f(c.uniform("extinctionScale"), scale);
    glUniform1i(c.uniform("sampleCount"), GLint(o.samples->size()));
    glUniform1i(c.uniform("environmentFirst"), frame.lights.count());
    glUniform1i(c.uniform("environmentCount"), frame.lights.environmentCount());
    glUniform1i(c.uniform("environmentBands"), bands);
    o.samples->computeEnvironment(bands);
    o.samples->environmentValid = true;
    o.samples->environmentScale = scale;
    o.samples->receivedValid = false;  // which holds it for isotropic media
}

void SamplePass::draw(FrameContext& frame) {
    for (auto& [samples, depths] : pendingTraces_) samples->setTracedDepths(depths.get());
    pendingTraces_.clear();
    for (PendingView& v : pendingViews_)
        v.object->refractedView.upload(v.rays.get(), *v.object->volume, v.object->placement, *frame.scatterView);
    pendingViews_.clear();
    if (!frame.options.scattering) return;
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glDepthMask(GL_FALSE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    // The proxies go to the pass's own target at the scattering's resolution,
    // depth-tested against the reach of each pixel (FrameTargets::reachDepth):
    // fragments beyond the objects or beside them are rejected before shading.
    const ViewSetup& target = *frame.scatterView;
    light_.resize(target.width, target.height);
    glNamedFramebufferTexture(light_.framebuffer(), GL_DEPTH_ATTACHMENT, frame.scatterTargets->reachDepth(), 0);
    const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glClearNamedFramebufferfv(light_.framebuffer(), GL_COLOR, 0, zero);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, light_.framebuffer());
    glViewport(0, 0, target.width, target.height);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glEnable(GL_DEPTH_CLAMP);  // the proxies' depth is clamped, never clipped (scatter.geom)
    glBindTextureUnit(gpu::kUnitRaySegments, frame.scatterTargets->raySegments());
    glBindTextureUnit(gpu::kUnitInsideSegments, frame.scatterTargets->insideSegments());
    if (largestPoint_ == 0.0f) {
        GLfloat range[2] = {1.0f, 1.0f};
        glGetFloatv(GL_POINT_SIZE_RANGE, range);
        largestPoint_ = range[1];
    }
    const bool points = pointProxiesCover(target.width, target.height);
    if (points) glEnable(GL_PROGRAM_POINT_SIZE);
    if (frame.options.fragments)
        countFragments(frame, points);
    else
        drawProxies(frame, points, false);
    glDisable(GL_PROGRAM_POINT_SIZE);
    glDisable(GL_DEPTH_CLAMP);
    glDisable(GL_DEPTH_TEST);
    glNamedFramebufferTexture(light_.framebuffer(), GL_DEPTH_ATTACHMENT, 0, 0);
    if (frame.scatterScale > 1)
        upsample(frame);
    else
        addLight(frame);
}

void SamplePass::drawProxies(FrameContext& frame, bool points, bool countUseful) {
    const glm::dmat3 viewToWorld = glm::transpose(glm::dmat3(glm::dmat4(frame.view.view)));
    for (GpuObject& o : frame.objects) {
        const SlabTable& slabs = o.samples->slabs();
        const SampleParameters& parameters = o.samples->parameters();
        const bool lightVaries = parameters.scheme == SampleScheme::Lucent;
        updateEnvironment(o, frame);
        ScatterVariant variant;
        variant.slabs = !slabs.empty();
        variant.regions = parameters.regionAxis != kNoRegionAxis;
        // sigma_t constant, or constant in slabs the fragments integrate through.
        variant.viewFromFront = lightVaries && (o.samples->homogeneous() || !slabs.empty());
        variant.countUseful = countUseful;
        variant.receivedCached = o.g == 0.0;
        variant.oneChannel = o.samples->channels() == 1;
        variant.tracedLight = traced(o, frame);
        variant.pointProxies = points;
        variant.refracted = refracted(o, frame);
        variant.environmentSh = environmentSh(o, frame);
        const GlProgram& p = scatterProgram(variant);
        const GlProgram& received = receivedProgram(variant.tracedLight, variant.refracted, variant.environmentSh);
        if (variant.refracted) o.refractedView.bind(gpu::kUnitRefractedRays);
        setFrameUniforms(p, frame);
        const float preprocessedScale = o.samples->parameters().placementScale;
        setSamplePlacement(p, o.placement, preprocessedScale);
        setSamplePlacement(received, o.placement, preprocessedScale);
        const glm::vec3 objectCamera(o.placement.inversePoint(Vec3(frame.view.cameraPosition)));
        const glm::mat3 viewToObject(glm::transpose(o.placement.rotation) * viewToWorld / o.placement.scale);
        glProgramUniform3fv(p.id(), p.uniform("objectCamera"), 1, glm::value_ptr(objectCamera));
        glProgramUniformMatrix3fv(p.id(), p.uniform("viewToObject"), 1, GL_FALSE, glm::value_ptr(viewToObject));
        // psi_i's SH: for the light, unless traced, and for the view, unless from the front face.
        o.samples->bind(!(variant.tracedLight && variant.viewFromFront));
        if (o.shadows) o.shadows->bind(gpu::kUnitShadowDistances);
        for (const GlProgram* program : {&p, &received}) {
            glProgramUniform1i(program->id(), program->uniform("blockerShadows"), o.shadows ? 1 : 0);
            glProgramUniform1i(program->id(), program->uniform("environmentBands"), o.samples->environmentBands());
        }
        if (variant.receivedCached) updateReceived(o, frame);
        glUseProgram(p.id());
        glUniform1i(p.uniform("shOrder"), o.samples->shOrder());
        glUniform1i(p.uniform("channels"), o.samples->channels());
        glUniform1f(p.uniform("g"), float(o.g));
        glUniform3fv(p.uniform("albedo"), 1, glm::value_ptr(glm::vec3(o.albedo)));
        if (variant.regions) glUniform1i(p.uniform("regionAxis"), int(parameters.regionAxis));
        if (!slabs.empty()) {
            glUniform1i(p.uniform("slabCount"), GLint(slabs.bounds.size()));
            glUniform4fv(p.uniform("slabBounds"), GLsizei(slabs.bounds.size()), glm::value_ptr(slabs.bounds[0]));
            std::vector<glm::vec4> extinction = slabs.extinction;
            for (glm::vec4& e : extinction) e *= frame.options.extinctionScale;
            glUniform4fv(p.uniform("slabExtinction"), GLsizei(extinction.size()), glm::value_ptr(extinction[0]));
        }
        glUniform1i(p.uniform("lightVaries"), lightVaries ? 1 : 0);
        if (!variant.refracted) {
            o.samples->draw();
            continue;
        }
        // Along each stretch of the pixels' rays inside, one draw each (refracted_view.h).
        for (int k = 0; k < o.refractedView.stretches(); ++k) {
            glUniform1i(p.uniform("stretch"), k);
            o.samples->draw();
        }
    }
}

void SamplePass::addLight(const FrameContext& frame) const {
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, frame.hostFramebuffer);
    glViewport(0, 0, frame.view.width, frame.view.height);
    glUseProgram(addProgram_.id());
    glBindTextureUnit(0, light_.texture());
    glUniform1i(addProgram_.uniform("light"), 0);
    glBindVertexArray(frame.targets.emptyVertexArray());
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

// The render benchmark's diagnostic, drawn twice. First without colour, to count
// the fragments the proxies generate that pass the early depth test: those the
// fragment shader runs for. Not GL_FRAGMENT_SHADER_INVOCATIONS: llvmpipe counts
// it in whole 4x4 blocks, so the pixels of a block beside a proxy's edge count
// too (kept as invocations, for comparison). Then with the variant that discards
// a fragment whose Gaussian's line integral is below the cut-off: the useful ones.
void SamplePass::countFragments(FrameContext& frame, bool points) {
    ScatterFragments& fragments = *frame.options.fragments;
    GLuint queries[3] = {0, 0, 0};
    glGenQueries(3, queries);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glBeginQuery(GL_SAMPLES_PASSED, queries[0]);
    drawProxies(frame, points, false);
    glEndQuery(GL_SAMPLES_PASSED);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glBeginQuery(kFragmentShaderInvocations, queries[1]);
    glBeginQuery(GL_SAMPLES_PASSED, queries[2]);
    drawProxies(frame, points, frame.options.discardBelow > 0.0f);
    glEndQuery(kFragmentShaderInvocations);
    glEndQuery(GL_SAMPLES_PASSED);
    GLuint64 counts[3] = {0, 0, 0};
    for (int i = 0; i < 3; ++i) glGetQueryObjectui64v(queries[i], GL_QUERY_RESULT, &counts[i]);
    glDeleteQueries(3, queries);
    fragments.shaded += counts[0];
    fragments.invocations += counts[1];
    fragments.kept += counts[2];
}

void SamplePass::upsample(const FrameContext& frame) const {
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, frame.hostFramebuffer);
    glViewport(0, 0, frame.view.width, frame.view.height);
    const GlProgram& p = upsampleProgram_;
    glUseProgram(p.id());
    glBindTextureUnit(0, light_.texture());
    glBindTextureUnit(1, frame.scatterTargets->insideSegments());
    glBindTextureUnit(2, frame.targets.insideSegments());
    glUniform1i(p.uniform("reducedLight"), 0);
    glUniform1i(p.uniform("reducedInside"), 1);
    glUniform1i(p.uniform("fullInside"), 2);
    glUniform2f(p.uniform("reducedPerPixel"), float(frame.scatterView->width) / float(frame.view.width),
                float(frame.scatterView->height) / float(frame.view.height));
    glBindVertexArray(frame.targets.emptyVertexArray());
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

}  // namespace lucent

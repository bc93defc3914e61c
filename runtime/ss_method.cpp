#include "runtime/ss_method.h"

#include <algorithm>
#include <future>

#include "core/sphere_light.h"
#include "core/environment_background.h"
#include "core/error.h"
#include "core/limits.h"
#include "core/sample_set.h"
#include "core/surface_shape.h"
#include "runtime/offscreen_context.h"
#include "runtime/internal/refracted_view.h"
#include "runtime/grazing_light.h"
#include "runtime/internal/sample_packing.h"
#include "runtime/offscreen_frame.h"
#include "runtime/preprocessed_size.h"
#include "runtime/scattering_renderer.h"

namespace lucent {

// The width factors the accuracy benchmark measured (docs/accuracy.md: 1 to 2.5).
constexpr float kMeasuredWidthFactors[2] = {1.0f, 2.5f};

namespace {

// What the frame is drawn with. The context must be current wherever the
// renderer and the frame are destroyed, so the destructor takes it first.
struct GlSession {
    std::unique_ptr<OffscreenContext> context;
    std::unique_ptr<OffscreenFrame> frame;
    std::unique_ptr<ScatteringRenderer> renderer;
    ~GlSession() {
        try {
            if (context) context->makeCurrent();
        } catch (const Error&) {
            // Deleting GL objects with no current context does nothing: nothing to do.
        }
        renderer.reset();
        frame.reset();
    }
};

// What a session depends on: another scene size or setting needs another one.
struct SessionKey {
    std::string backend;
    double cutoff;
    int width, height;
    bool operator==(const SessionKey&) const = default;
};

SessionKey sessionKey(const SceneDesc& desc, const MethodSettings& settings, const SsOptions& options) {
    return {options.backend, settings.cutoff, desc.camera.width, desc.camera.height};
}

std::unique_ptr<GlSession> openSession(const SessionKey& key) {
    auto session = std::make_unique<GlSession>();
    session->context = OffscreenContext::create(parseGlBackend(key.backend));
    session->frame = std::make_unique<OffscreenFrame>(key.width, key.height);
    session->renderer = std::make_unique<ScatteringRenderer>(key.cutoff);
    return session;
}

// session: the prepared one or null (one is opened); holds the session drawn with on return.
Image renderSingleScattering(const LoadedScene& scene, const MethodSettings& settings, const SsOptions& options,
                             const std::vector<ScatteringGrid>& grids, std::string& backend,
                             std::unique_ptr<GlSession>& session);

}  // namespace

struct SsMethod::Prepared {
    SessionKey key;
    std::future<std::unique_ptr<GlSession>> session;
};

struct SsMethod::Retiring {
    std::future<void> done;
};

std::vector<OptionSpec> SsOptions::specs() {
    return {
        OptionSpec::choice("light", "traced", {"traced", "sh"},
                           "the light reaching each sample traced through the objects (and refracted at their "
                           "boundary), or read from its SH attenuation (sh: the thesis; blurs narrow shadows, no "
                           "shadows between objects, boundaries index-matched; an environment projected onto "
                           "SH per sample, about one light's cost a frame)"),
        OptionSpec::choice("backend", "auto", {"auto", "egl", "osmesa"}, "the OpenGL backend (auto: EGL, then OSMesa)"),
        OptionSpec::integer("env-lights", SsOptions().environmentLights, 1, int(kMaxEnvironmentLights),
                            "directional lights an environment light is drawn as, drawn from its map by "
                            "importance; time grows with them")};
}

SsOptions SsOptions::from(const MethodOptions& options) {
    const std::string& backend = options.choice("backend");
    return {options.choice("light") == "traced", backend == "auto" ? std::string() : backend,
            options.integer("env-lights")};
}

SsMethod::SsMethod(SsOptions options) : options_(std::move(options)) {}
SsMethod::~SsMethod() = default;  // waits for retiring_

std::unique_ptr<Method> SsMethod::create(const MethodOptions& options) {
    return std::make_unique<SsMethod>(SsOptions::from(options));
}

void SsMethod::prepare(const SceneDesc& desc, const MethodSettings& settings) {
    const SessionKey key = sessionKey(desc, settings, options_);
    prepared_ = std::make_unique<Prepared>(Prepared{key, std::async(std::launch::async, [key] {
                                                        std::unique_ptr<GlSession> session = openSession(key);
                                                        session->context->release();
                                                        return session;
                                                    })});
}

std::vector<std::string> SsMethod::limitations(const LoadedScene& scene, const MethodSettings& settings) const {
    std::vector<std::string> out = boundaryLimitations(scene, options_);
    for (std::string& line : sampleLimitations(scene, options_)) out.push_back(std::move(line));
    return out;
}

namespace {

// What ss's refracted view misses on a surface of this shape. Each sample is
// drawn where the one pixel whose refracted ray passes nearest sees it; where
// the view folds (flat faces joined by bends, sharp edges, concave parts) a
// point inside is seen through two faces or two parts, and ss draws it once.
// Measured against the refracting reference (docs/accuracy.md, ss through a
// refracting boundary; docs/results/refraction.md and refraction-back.md).
std::string refractedViewLimitation(const SurfaceShape& shape) {
    const std::string common =
        ": --method ss refracts the view and the light at its boundary, but follows no view ray into another "
        "part of it, nor the camera ray reflected off it, nor a second reflection inside";
    if (smoothConvex(shape))
        return common +
               ": 3-6% from the refracting reference on a sphere, an ellipsoid and a capsule at optical "
               "radius 1 to 4, 5-8% at 0.5 (smooth and convex, as this surface is; "
               "docs/results/refraction-shapes.md)";
    return common + ", and draws each point inside once where its " +
           (shape.convex ? std::string(shape.sharpestDegrees >= kCreaseDegrees ? "sharp edges" : "flat faces")
                         : std::string("concave parts")) +
           " may show it twice, too dark, the more so the thinner the medium: from the refracting reference at "
           "optical radius 0.5 to 4, 4-10% on a lens with a sharp rim and on a torus (82% on the lens at 0.5 and "
           "ior 1.5, from two pixels where the light's caustic falls), 5-26% on a box with rounded edges, 9-31% on "
           "a sharp box, 9-41% on CAD solids with holes, slots, dimples, letters and ribs "
           "(docs/results/refraction-shapes.md); 12-13% on the wax bunny lit from the front at ior 1.33-1.5 "
           "(10-12% over pixel means), and 25-29% lit from behind (docs/results/refraction-back.md)";
}

}  // namespace

std::vector<std::string> SsMethod::boundaryLimitations(const LoadedScene& scene, const SsOptions& options) {
    std::vector<std::string> out;
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const VolumeObject& o = scene.objects[i];
        const double ior = o.desc().medium.ior;
        if (ior == 1.0 || !scene.hasSamples()) continue;
        const std::string object = "object '" + o.desc().name + "': ior " + std::to_string(ior).substr(0, 4);
        const bool fromFront = attenuatesFromFront(scene.samples[i]);
        if (!drawnRefracted(ior, fromFront, options.tracedLight)) {
            const bool thick = scene.samples[i].parameters.scheme == SampleScheme::OpticallyThick;
            const std::string why = !options.tracedLight ? "with --light sh"
                                    : thick              ? "optically thick, each pixel's ray marched"
                                                         : "its density varies within the object";
            // Measured where optically thick solids refract (docs/results/refraction-shapes.md, optical radius 8).
            const std::string measured = thick ? ", 2.2-4.7x too bright where the boundary's light refracts (110-400% "
                                                 "from the refracting reference on solids at optical radius 8)"
                                               : "";
            out.push_back(object + " is drawn index-matched (" + why +
                          "): no refraction, no reflection at the boundary (--method path and reference refract)" +
                          measured);
            continue;
        }
        out.push_back(object + refractedViewLimitation(surfaceShape(o.objectMesh())));
        // The refracted view starts where the camera's ray enters the object.
        if (o.contains(scene.desc.camera.position))
            out.push_back(object + ": the camera stands inside it, and --method ss draws nothing of it");
        if (scene.objects.size() > 1)
            out.push_back(object +
                          ": where another object stands in front of it, --method ss draws nothing of it through "
                          "that object");
    }
    return out;
}

std::vector<std::string> SsMethod::sampleLimitations(const LoadedScene& scene, const SsOptions& options) {
    std::vector<std::string> out = sphereLightsThroughBoundaries(scene.desc);
    // Measured on the sphere under two skies with a sun at 96x96, against the
    // reference (32 directions; traced and --light sh alike): 3-9% for g in
    // [-0.3, 0.8), 10.7% at 0.8 under one of them.
    for (const VolumeObject& o : scene.objects)
        if (scene.environment && (o.desc().medium.g < -0.3 || o.desc().medium.g >= 0.8))
            out.push_back("object '" + o.desc().name + "': g " + std::to_string(o.desc().medium.g).substr(0, 5) +
                          " under an environment light, which ss draws as " +
                          std::to_string(options.environmentLights) +
                          " directions that a peaked phase function sees one by one (16% from the reference at "
                          "g = -0.5, 11% at 0.8 and 28% at 0.9 with 32; --env-lights 128 gave 3.1%, 6.4% and 21%)");
    for (const VolumeObject& o : scene.objects)
        if (scene.environment && !options.tracedLight && !o.desc().medium.blockers.empty() &&
            environmentShHolds(o.desc().medium.g))
            out.push_back("object '" + o.desc().name +
                          "': --light sh projects the environment onto SH without its blockers' shadows "
                          "(--light traced casts them)");
    for (size_t j = 0; j < scene.desc.lights.size() && !options.tracedLight; ++j)
        if (scene.desc.lights[j].radius > 0.0)
            out.push_back("light " + std::to_string(j) +
                          " is a sphere: --light sh takes its shadows from its centre alone (hard shadows; "
                          "--light traced follows 16 rays over it)");
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const VolumeObject& o = scene.objects[i];
        const std::string& name = o.desc().name;
        const double spacing = scene.hasSamples() ? scene.samples[i].parameters.meanRadius : 0.0;
        for (size_t j = 0; j < scene.desc.lights.size(); ++j) {
            const Light& l = scene.desc.lights[j];
            if (l.type != Light::Type::Point) continue;
            // Farther from the box than a spacing: neither case (and no distance
            // tree to build, which costs more than the check).
            const Bounds3 box = o.mesh().bounds();
            if (glm::length(glm::max(glm::max(box.min - l.position, l.position - box.max), Vec3(0.0))) > spacing)
                continue;
            const bool inside = o.contains(l.position);
            const double depth = glm::length(o.boundary().closestPoint(l.position) - l.position);
            if (inside || depth < spacing)
                out.push_back("light " + std::to_string(j) + " lies " + (inside ? "inside" : "at the surface of") +
                              " object '" + name +
                              "': --method ss averages its 1/r^2 peak over the Gaussians there "
                              "(0.34 to 1.23 of the light measured; --method reference is exact)");
        }
        // The samples' SH hold each object's own attenuation only: light that crosses
        // another object on its way is not dimmed by it (measured on two spheres,
        // one in the other's light: 24% relative RMSE against 5% without). Traced
        // light crosses every object.
        const Bounds3 mine = o.mesh().bounds();
        for (size_t k = 0; k < scene.objects.size() && !options.tracedLight; ++k) {
            if (k == i) continue;
            const Bounds3 other = scene.objects[k].mesh().bounds();
            const double reach = 0.5 * other.diagonal();  // the other's bounding sphere
            for (size_t j = 0; j < scene.desc.lights.size(); ++j) {
                const Light& l = scene.desc.lights[j];
                // The segment from the light towards this object's centre (a directional light: from far away).
                const Vec3 to = mine.center();
                const Vec3 from = l.type == Light::Type::Point ? l.position : to - 1e6 * reach * l.direction;
                const Vec3 d = to - from;
                const double t =
                    std::clamp(glm::dot(other.center() - from, d) / std::max(glm::dot(d, d), 1e-300), 0.0, 1.0);
                if (glm::length(from + t * d - other.center()) < reach && t > 0.0 && t < 1.0)
                    out.push_back("object '" + scene.objects[k].desc().name + "' may lie between light " +
                                  std::to_string(j) + " and object '" + name +
                                  "': --light sh does not dim one object's light by another (24% relative RMSE "
                                  "measured on two spheres; --light traced is exact)");
            }
        }
        if (!scene.hasSamples()) continue;
        const SampleParameters& p = scene.samples[i].parameters;
        std::string size = preprocessedSizeLimitation(name, o.placement().scale, p);
        if (!size.empty()) out.push_back(std::move(size));
        if (p.scheme == SampleScheme::OpticallyThick) {
            std::string grazing = grazingLightLimitation(
                name, seenSurfaceLighting(o.mesh(), scene.desc.camera.position, scene.desc.lights));
            if (!grazing.empty()) out.push_back(std::move(grazing));
        }
        if (p.scheme == SampleScheme::Lucent &&
            (p.widthFactor < 0.5f * kMeasuredWidthFactors[0] || p.widthFactor > 2.0f * kMeasuredWidthFactors[1]))
            out.push_back("object '" + name + "': Gaussians " + std::to_string(p.widthFactor) +
                          " times their spacing wide, far outside the measured 1 to 2.5: narrow ones miss pixel rays, "
                          "wide ones blur the light's fall-off (0.88 and 0.12 of the light measured at 0.05 and 20)");
    }
    return out;
}

Image SsMethod::render(const LoadedScene& scene, const MethodSettings& settings) {
    std::unique_ptr<GlSession> session;
    if (prepared_) {
        const std::unique_ptr<Prepared> prepared = std::move(prepared_);
        if (prepared->key == sessionKey(scene.desc, settings, options_)) session = prepared->session.get();
    }
    Image image = renderSingleScattering(scene, settings, options_, {}, backend_, session);
    // Torn down in a thread of its own while the caller writes the image; the
    // destructor waits for it.
    session->context->release();
    retiring_ = std::make_unique<Retiring>(
        Retiring{std::async(std::launch::async, [retired = std::move(session)]() mutable { retired.reset(); })});
    return image;
}

void setSsLights(ScatteringRenderer& renderer, const LoadedScene& scene, const SsOptions& options) {
    const bool projected = scene.environment && !options.tracedLight &&
                           std::all_of(scene.objects.begin(), scene.objects.end(),
                                       [](const VolumeObject& o) { return environmentShHolds(o.desc().medium.g); });
    renderer.setEnvironment({});
    renderer.setLights(projected ? scene.desc.lights : scene.lightsWithEnvironment(options.environmentLights));
    if (projected) renderer.setEnvironment(scene.environment->asDirectionalLights(options.environmentLights));
}

Image renderSingleScattering(const LoadedScene& scene, const MethodSettings& settings, const SsOptions& options,
                             const std::vector<ScatteringGrid>& grids, std::string& backend) {
    std::unique_ptr<GlSession> session;
    return renderSingleScattering(scene, settings, options, grids, backend, session);
}

namespace {

Image renderSingleScattering(const LoadedScene& scene, const MethodSettings& settings, const SsOptions& ssOptions,
                             const std::vector<ScatteringGrid>& grids, std::string& backend,
                             std::unique_ptr<GlSession>& session) {
    if (!scene.hasSamples()) throw Error(scene.desc.file.string(), "single scattering needs the objects' sample sets");
    // The traced light casts rays into every object: their ray casters (a BVH
    // over every face) are built while the OpenGL context comes up and the
    // samples are uploaded. The future's destructor waits for it on every path.
    std::future<void> casters;
    if (ssOptions.tracedLight)
        casters = std::async(std::launch::async, [&scene] {
            for (const VolumeObject& o : scene.objects) o.boundary();
        });
    // The SH light reads the samples' coefficients, which stay in the sample file
    // until asked for (core/sample_set.h): read here, while the context comes up
    // and the passes before the samples' run, rather than where the upload asks
    // for them and the frame would wait. An error is
    // met again there, and thrown.
    std::future<void> coefficients;
    if (!ssOptions.tracedLight)
        coefficients = std::async(std::launch::async, [&scene] {
            try {
                for (const SampleSet& s : scene.samples) (void)s.coefficients();
            } catch (const Error&) {
            }
        });
    // The environment behind and through the objects ("background": true) is
    // found on the CPU from the objects' meshes while the frame is drawn.
    std::future<Image> background;
    if (scene.environment && scene.desc.render.background)
        background = std::async(std::launch::async,
                                [&scene, &settings] { return environmentBackground(scene, settings.threads); });
    if (session)
        session->context->makeCurrent();
    else
        session = openSession(sessionKey(scene.desc, settings, ssOptions));
    backend = session->context->backendName();
    const ViewSetup view = viewSetupFor(scene.desc.camera, scene.bounds());
    const OffscreenFrame& frame = *session->frame;
    ScatteringRenderer& renderer = *session->renderer;
    for (size_t i = 0; i < scene.objects.size(); ++i)
        renderer.addObject(translucentObjectFor(scene.objects[i], scene.samples[i]));
    for (const ScatteringGrid& g : grids) renderer.addScatteringGrid(g);
    setSsLights(renderer, scene, ssOptions);
    frame.bindAndClear();
    DrawOptions options;
    options.surface = settings.surface;
    options.tracedLight = ssOptions.tracedLight;
    renderer.draw(view, options);
    Image image = frame.read();
    if (background.valid()) {
        const Image behind = background.get();
        for (size_t p = 0; p < image.pixels.size(); ++p) image.pixels[p] += behind.pixels[p];
    }
    return image;
}

}  // namespace

}  // namespace lucent

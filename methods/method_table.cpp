#include "methods/method_table.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/surface_shape.h"
#include "core/volume_object.h"
#include "runtime/offscreen_context.h"
#include "reference/path_method.h"
#include "reference/reference_method.h"
#include "runtime/ss_method.h"
#ifdef LUCENT_HAVE_OPENCL
#include "hybrid/multiple_scattering.h"
#include "methods/lbl_method.h"
#include "methods/mdom_method.h"
#endif

namespace lucent {

const std::vector<MethodEntry>& methodTable() {
    const auto always = [] { return std::string(); };
    static const std::vector<MethodEntry> table = {
        {"ss", "single scattering from the preprocessed samples, on OpenGL (thesis 3.4), refraction included", true,
         true, always, SsOptions::specs(), SsMethod::create},
        {"reference", "exact single scattering by quadrature on the CPU, refraction included (the ground truth of ss)",
         false, false, always, ReferenceMethod::options(), ReferenceMethod::create, true},
        {"path", "full transport by volumetric path tracing on the CPU (the ground truth of multiple scattering)",
         false, false, always, PathMethod::options(), PathMethod::create, true},
#ifdef LUCENT_HAVE_OPENCL
        {"lbl",
         "single scattering plus multiple scattering by photon marching and Lattice-Boltzmann lighting on OpenCL "
         "(thesis ch. 4)",
         true, false, hybrid::MultipleScattering::unavailableReason, GridMethod::options(), LblMethod::create},
        {"mdom",
         "single scattering plus multiple scattering by the modified discrete ordinates method on OpenCL, "
         "anisotropic media included (thesis ch. 5)",
         true, false, hybrid::MultipleScattering::unavailableReason, MdomMethod::options(), MdomMethod::create, false,
         true},
#endif
    };
    return table;
}

std::vector<std::string> methodNames() {
    std::vector<std::string> names;
    for (const MethodEntry& m : methodTable()) names.push_back(m.name);
    names.push_back("auto");
    return names;
}

const MethodEntry& findMethod(const std::string& name) {
    std::string built;
    for (const MethodEntry& m : methodTable()) {
        if (m.name == name) return m;
        built += (built.empty() ? "" : ", ") + m.name;
    }
    throw Error("method '" + name + "' is not built into this binary (built: " + built + ", auto)");
}

namespace {

bool available(const std::string& name) {
    for (const MethodEntry& m : methodTable())
        if (m.name == name) return m.unavailableReason().empty();
    return false;
}

std::string percent(double x) { return std::to_string(int(std::lround(100.0 * x))) + "%"; }

double largestAlbedo(const ObjectDesc& o) {
    return std::max({o.medium.albedo.r, o.medium.albedo.g, o.medium.albedo.b});
}

// What keeps lbl from the goal at o's refracting boundary, measured on the
// shapes of docs/accuracy.md (What auto picks), or empty. Its view bends through
// a smoothed index and ss's samples are drawn where one pixel's refracted ray
// passes nearest: both hold where the refracted view rays cross nowhere inside,
// a smooth convex surface (core/surface_shape.h).
std::string latticeMisses(const SceneDesc& scene, const ObjectDesc& o) {
    if (scene.objects.size() > 1)
        return std::to_string(scene.objects.size() - 1) +
               " other object(s) beside it, where lbl was measured on one alone";
    std::vector<std::string> ignored;  // loading the scene says them
    const TriangleMesh mesh = loadObjectMesh(o, ignored);
    const SurfaceShape shape = surfaceShape(mesh);
    if (!shape.convex)
        return "concave parts, through which the refracted view may fold (lbl 7-12% from full transport on a "
               "torus, 13-16% on the bunny, 19-67% on CAD solids with holes, slots, dimples, letters and ribs)";
    if (shape.sharpestDegrees >= kCreaseDegrees)
        return "sharp edges, where the refracted view folds (lbl 10-49% on a lens with a sharp rim, 26-60% on a box)";
    if (!smoothConvex(shape))
        return "flat faces, " + percent(shape.largestFlatShare) +
               " of its area in one, joined by bends that fold the refracted view (lbl 11-32% on a box with rounded "
               "edges)";
    if (o.medium.density.type != DensityDesc::Type::Constant)
        return "a density that varies, where lbl was measured in constant media alone";
    const Vec3 half = 0.5 * (mesh.bounds().max - mesh.bounds().min);
    const double radius = std::min({o.medium.sigmaT.r, o.medium.sigmaT.g, o.medium.sigmaT.b}) * o.transform.scale *
                          std::min({half.x, half.y, half.z});
    if (radius < kRefractingLatticeOpticalRadius[0] || radius > kRefractingLatticeOpticalRadius[1])
        return "optical radius " + std::to_string(radius).substr(0, 5) +
               " (sigma_t times the smallest half-extent of its box), where lbl misses outside " +
               std::to_string(kRefractingLatticeOpticalRadius[0]).substr(0, 1) + " to " +
               std::to_string(kRefractingLatticeOpticalRadius[1]).substr(0, 1) +
               " (9-11% from full transport at 0.5, 9-13% at 8 and more where ss draws the object "
               "optically thick)";
    const double albedo = largestAlbedo(o);
    if (albedo > kRefractingLatticeAlbedo)
        return "albedo " + std::to_string(albedo).substr(0, 4) +
               ", and lbl's light held in by the boundary drifts above albedo " +
               std::to_string(kRefractingLatticeAlbedo).substr(0, 3) +
               " (9-13% from full transport at 0.95; by hand, 8-10% at 0.9)";
    if (o.medium.g > kRefractingLatticeMaxG || o.medium.g < kRefractingLatticeMinG)
        return "g " + std::to_string(o.medium.g).substr(0, 5) +
               ", and lbl's diffusion inside a reflecting boundary misses forward scattering (9-16% from full "
               "transport at g 0.3; by hand, 10% at 0.15 and 33% at 0.5)";
    if (!available("lbl")) return "a smooth convex surface, but this build has no lbl";
    return {};
}

// A scene with a refracting boundary: lbl where it is within the goal, else the path tracer.
MethodChoice refractingChoice(const SceneDesc& scene, const ObjectDesc& o) {
    const std::string object = "object '" + o.name + "' has ior " + std::to_string(o.medium.ior).substr(0, 4);
    const std::string misses = latticeMisses(scene, o);
    if (misses.empty())
        return {"lbl", object +
                           " and a smooth convex surface: lbl refracts and reflects at its boundary within 4-10% of "
                           "full transport on a sphere, an ellipsoid and a capsule at ior 1.33 and 1.5, optical "
                           "radius 1 to 4, albedo up to " +
                           std::to_string(kRefractingLatticeAlbedo).substr(0, 3) + " and g from " +
                           std::to_string(kRefractingLatticeMinG).substr(0, 4) + " to " +
                           std::to_string(kRefractingLatticeMaxG).substr(0, 3)};
    return {"path", object + " and " + misses +
                        ": only the path tracer gives full transport through it within 10%; it is slow: lower "
                        "--samples or set --noise for a draft"};
}

}  // namespace

bool openGlIsSoftware() {
    static const bool software = [] {
        try {
            const auto context = OffscreenContext::create(GlBackend::Auto);
            return glIsSoftware();
        } catch (const Error&) {
            return true;  // no OpenGL at all: the CPU reference is what is left
        }
    }();
    return software;
}

MethodChoice chooseMethod(const SceneDesc& scene) {
    // The goal: within kAutoGoal relative RMSE of full transport (the path
    // tracer) at the least time, from the measurements of docs/accuracy.md
    // ("What auto picks"). Single scattering alone misses light that grows with
    // the albedo; below kSingleScatteringAlbedo it stays within the goal.
    // A refracting boundary has rules of its own (refractingChoice).
    for (const ObjectDesc& o : scene.objects)
        if (o.medium.ior != 1.0) return refractingChoice(scene, o);
    double albedo = 0.0;
    for (const ObjectDesc& o : scene.objects) albedo = std::max(albedo, largestAlbedo(o));
    const std::string a = std::to_string(albedo).substr(0, 4);
    if (albedo <= kSingleScatteringAlbedo) {
        const std::string why =
            "albedo at most " + a + ": single scattering alone is within " + percent(kAutoGoal) + " of full transport";
        const long pixels = long(scene.camera.width) * scene.camera.height;
        if (pixels <= kReferenceAsFastPixels && openGlIsSoftware())
            return {"reference", why +
                                     "; OpenGL here is a software rasteriser, on which the exact CPU reference is as "
                                     "fast as ss for an image this small, and it needs no sample files"};
        return {"ss", why};
    }
    const std::string misses = "albedo " + a +
                               ": single scattering alone leaves out the light scattered more than "
                               "once (11-14% of full transport at albedo 0.2, 27-30% at 0.5)";
    // The lattice is a diffusion model: forward-scattering media defeat it.
    double g = 0.0;
    for (const ObjectDesc& o : scene.objects) g = std::max(g, std::abs(o.medium.g));
    if (g > kLatticeMaxG) {
        const std::string gs = std::to_string(g).substr(0, 4);
        const std::string beyondLbl =
            misses + ", and |g| " + gs +
            " is beyond what lbl's diffusion holds (33-137% from full transport measured at g 0.8)";
        if (available("mdom") && g <= kMdomMaxG)
            return {"mdom",
                    beyondLbl + "; mdom follows forward scattering (6.6-8.8% measured at g 0.8, 2-4% up to g 0.4)"};
        // The path tracer is noisy in such media: 17% per pixel at 1024 paths
        // on the sphere at g 0.8, so the goal takes thousands of paths.
        return {"path", beyondLbl +
                            (available("mdom") ? ", and mdom misses the goal past |g| " +
                                                     std::to_string(kMdomMaxG).substr(0, 3) + " (32% measured at g 0.9)"
                                               : ", and this build has no mdom") +
                            ": the path tracer is the ground truth, but noisy in forward scattering (17% per pixel at "
                            "1024 paths at g 0.8): use --samples 4096 --noise 0.05"};
    }
    if (available("lbl"))
        return {"lbl", misses +
                           "; lbl adds it (3-8% measured on the sphere and the bunny, but 12-21% on the bundled "
                           "cubes: --method mdom is within 2-6% on all of them, at 3-5x the time)"};
    return {"ss", misses +
                      ", and this build cannot add it (no lbl): expect a dark image; --method path is the "
                      "ground truth"};
}

std::vector<OfferedOption> offeredOptions() {
    std::vector<OfferedOption> out;
    for (const MethodEntry& m : methodTable())
        for (const OptionSpec& spec : m.options) {
            auto same =
                std::find_if(out.begin(), out.end(), [&](const OfferedOption& o) { return o.spec.name == spec.name; });
            if (same == out.end()) {
                out.push_back({spec, {m.name}});
            } else if (same->spec == spec) {
                same->methods.push_back(m.name);
            } else {
                throw Error("methods " + same->methods.front() + " and " + m.name + " declare option --" + spec.name +
                            " differently");
            }
        }
    return out;
}

MethodOptions methodOptions(const MethodEntry& entry, const std::map<std::string, std::string>& given,
                            bool chosenByAuto, std::vector<std::string>& warnings) {
    MethodOptions options(entry.options);
    for (const auto& [name, value] : given) {
        if (options.declares(name)) {
            options.set(name, value);
            continue;
        }
        std::string takers;
        for (const OfferedOption& o : offeredOptions())
            if (o.spec.name == name)
                for (const std::string& m : o.methods) takers += (takers.empty() ? "" : ", ") + m;
        const std::string problem = "--" + name + " is an option of --method " + takers + ", not of " + entry.name;
        if (!chosenByAuto) throw Error(problem);
        warnings.push_back(problem + " (chosen by auto): left out");
    }
    return options;
}

ResolvedMethod resolveMethod(const std::string& name, const SceneDesc& scene) {
    if (name != "auto" && std::none_of(methodTable().begin(), methodTable().end(),
                                       [&](const MethodEntry& m) { return m.name == name; })) {
        try {
            findMethod(name);
        } catch (const Error& e) {
            throw Error(scene.file.string(), std::string("/render/method: ") + e.what());
        }
    }
    ResolvedMethod r;
    std::string chosen = name;
    if (name == "auto") {
        MethodChoice choice = chooseMethod(scene);
        chosen = choice.method;
        r.reason = std::move(choice.reason);
    }
    r.entry = &findMethod(chosen);
    const std::string why = r.entry->unavailableReason();
    if (!why.empty()) throw Error("method '" + chosen + "' cannot run here: " + why);
    return r;
}

Image renderWith(const MethodEntry& entry, const LoadedScene& scene, const MethodSettings& settings,
                 std::string* servedBy) {
    return renderWith(entry, *entry.createDefault(), scene, settings, servedBy);
}

Image renderWith(const MethodEntry& entry, Method& method, const LoadedScene& scene, const MethodSettings& settings,
                 std::string* servedBy) {
    if (entry.needsSamples && !scene.hasSamples())
        throw Error(scene.desc.file.string(), "method '" + entry.name + "' needs the objects' sample sets");
    Image image = method.render(scene, settings);
    if (servedBy) *servedBy = method.servedBy();
    return image;
}

}  // namespace lucent

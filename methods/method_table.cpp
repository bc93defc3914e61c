#include "methods/method_table.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
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
    // Only the path tracer gives full transport through a boundary whose ior is
    // not 1 within the goal on every bundled scene: lbl and mdom refract and
    // reflect at the boundary (3-6% on the sphere up to albedo 0.8) but miss it
    // on the bunny at every albedo, where ss's single scattering misses its own
    // (docs/accuracy.md, What auto picks).
    for (const ObjectDesc& o : scene.objects)
        if (o.medium.ior != 1.0)
            return {"path",
                    "object '" + o.name + "' has ior " + std::to_string(o.medium.ior).substr(0, 4) +
                        ": only the path tracer gives full transport through a refracting boundary within 10% on "
                        "every measured scene (lbl is 3-5% from it on the sphere up to albedo 0.8, but 13-16% on "
                        "the bunny at every albedo from 0.1 to 0.95, where ss's own view of the bunny misses: "
                        "docs/results/lbl-refraction.md); it is slow: lower --samples or set --noise for a draft"};
    double albedo = 0.0;
    for (const ObjectDesc& o : scene.objects)
        albedo = std::max({albedo, o.medium.albedo.r, o.medium.albedo.g, o.medium.albedo.b});
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

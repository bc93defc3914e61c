#include "methods/method_table.h"

#include <algorithm>

#include "core/error.h"
#include "reference/path_method.h"
#include "reference/reference_method.h"
#include "runtime/ss_method.h"
#ifdef LUCENT_HAVE_OPENCL
#include "hybrid/multiple_scattering.h"
#include "methods/lbl_method.h"
#endif

namespace lucent {

const std::vector<MethodEntry>& methodTable() {
    static const std::vector<MethodEntry> table = {
        {"ss", "single scattering from the preprocessed samples, on OpenGL (thesis 3.4)", true, true,
         [] { return std::string(); }, [] { return std::make_unique<SsMethod>(); }},
        {"reference", "exact single scattering by quadrature on the CPU (the ground truth of ss)", false, false,
         [] { return std::string(); }, [] { return std::make_unique<ReferenceMethod>(); }},
        {"path", "full transport by volumetric path tracing on the CPU (the ground truth of multiple scattering)",
         false, false, [] { return std::string(); }, [] { return std::make_unique<PathMethod>(); }},
#ifdef LUCENT_HAVE_OPENCL
        {"lbl",
         "single scattering plus multiple scattering by photon marching and Lattice-Boltzmann lighting on OpenCL "
         "(thesis ch. 4)",
         true, false, [] { return hybrid::MultipleScattering::unavailableReason(); },
         [] { return std::make_unique<LblMethod>(); }},
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

MethodChoice chooseMethod(const SceneDesc&) {
    // Single scattering is the only interactive method built so far; auto will
    // weigh the multiple-scattering methods against the media when they land.
    return {"ss", "the only interactive method built"};
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
    const std::string chosen = name == "auto" ? chooseMethod(scene).method : name;
    if (name == "auto") r.reason = chooseMethod(scene).reason;
    r.entry = &findMethod(chosen);
    const std::string why = r.entry->unavailableReason();
    if (!why.empty()) throw Error("method '" + chosen + "' cannot run here: " + why);
    return r;
}

Image renderWith(const MethodEntry& entry, const LoadedScene& scene, const MethodSettings& settings,
                 std::string* servedBy) {
    if (entry.needsSamples && !scene.hasSamples())
        throw Error(scene.desc.file.string(), "method '" + entry.name + "' needs the objects' sample sets");
    const std::unique_ptr<Method> method = entry.create();
    Image image = method->render(scene, settings);
    if (servedBy) *servedBy = method->servedBy();
    return image;
}

}  // namespace lucent

#include "viewer/scattering_grids.h"

#include <cstdio>

#include "core/error.h"
#ifdef LUCENT_HAVE_OPENCL
#include "hybrid/mdom_scattering.h"
#include "hybrid/multiple_scattering.h"
#endif

namespace lucent {
namespace {

// Voxels along each object's longest side when the viewer solves multiple
// scattering: about a second per solve here (docs/hybrid.md), then free per frame.
constexpr int kViewerGridResolution = 48;

// The objects as the hybrid solves them: where they now stand. One moved since
// the scene was read is loaded again there (mesh, blockers, density), once per
// placement; the others are the scene's own.
class PlacedObjects {
public:
    explicit PlacedObjects(const LoadedScene& loaded) : loaded_(loaded), moved_(loaded.objects.size()) {}
    std::vector<const VolumeObject*> at(const std::vector<Similarity>& placements) {
        std::vector<const VolumeObject*> objects;
        std::vector<std::string> warnings;
        for (size_t i = 0; i < loaded_.objects.size(); ++i) {
            const VolumeObject& own = loaded_.objects[i];
            if (placements[i] == own.placement()) {
                objects.push_back(&own);
                continue;
            }
            if (!moved_[i] || !(moved_[i]->placement() == placements[i])) {
                ObjectDesc desc = own.desc();
                desc.transform = placements[i];
                moved_[i] = std::make_unique<VolumeObject>(desc, warnings);
            }
            objects.push_back(moved_[i].get());
        }
        return objects;
    }

private:
    const LoadedScene& loaded_;
    // Replaced only when the object moves, which ends any solve begun with it.
    std::vector<std::unique_ptr<VolumeObject>> moved_;
};

}  // namespace

struct ScatteringGrids::Solvers {
    explicit Solvers(const LoadedScene& loaded) : placedObjects(loaded) {}
    PlacedObjects placedObjects;
#ifdef LUCENT_HAVE_OPENCL
    std::unique_ptr<hybrid::MultipleScattering> lbl;
    std::unique_ptr<hybrid::MdomScattering> mdom;
    std::vector<std::unique_ptr<hybrid::MdomProgress>> mdomRuns;  // one per object while iterating
    std::vector<hybrid::MdomSolution> mdomSolutions;              // the latest per object
    Vec3 bakedFor = Vec3(kInfinity);                              // the eye the mdom grids were baked for
#endif
};

ScatteringGrids::ScatteringGrids(const LoadedScene& loaded) : solvers_(std::make_unique<Solvers>(loaded)) {}
ScatteringGrids::~ScatteringGrids() = default;

void ScatteringGrids::update(ViewerState& state, ScatteringRenderer& renderer, const std::vector<Light>& lights) {
    using Multiple = ViewerState::Multiple;
    if (state.multiple != shown_ || (shown_ != Multiple::Off && !valid_)) begin(state, renderer, lights);
    if (shown_ == Multiple::Mdom) iterate(state, renderer);
}

void ScatteringGrids::begin(ViewerState& state, ScatteringRenderer& renderer, const std::vector<Light>& lights) {
    using Multiple = ViewerState::Multiple;
    renderer.clearScatteringGrids();
    shown_ = Multiple::Off;
    solving_ = false;
    status_.clear();
    if (state.multiple == Multiple::Off) return;
#ifdef LUCENT_HAVE_OPENCL
    Solvers& s = *solvers_;
    // No device (or a failing one) leaves the viewer running, without the grids.
    try {
        if (state.multiple == Multiple::Lbl) {
            if (!s.lbl) s.lbl = std::make_unique<hybrid::MultipleScattering>();
            hybrid::HybridSettings hs;
            hs.resolution = kViewerGridResolution;
            for (const VolumeObject* object : s.placedObjects.at(state.placements))
                renderer.addScatteringGrid(s.lbl->solve(*object, lights, hs));
        } else {
            if (!s.mdom) s.mdom = std::make_unique<hybrid::MdomScattering>();
            hybrid::MdomSettings ms;
            ms.resolution = kViewerGridResolution;
            ms.directions = 24;
            s.mdomRuns.clear();
            for (const VolumeObject* object : s.placedObjects.at(state.placements))
                s.mdomRuns.push_back(s.mdom->begin(*object, lights, ms));
            solving_ = true;
        }
        shown_ = state.multiple;
        valid_ = true;
    } catch (const Error& e) {
        renderer.clearScatteringGrids();
        std::fprintf(stderr, "lucent: warning: view: no multiple scattering: %s\n", e.what());
        state.multiple = Multiple::Off;
    }
#else
    (void)lights;
    std::fprintf(stderr, "lucent: view: this build has no OpenCL: no multiple scattering\n");
    state.multiple = Multiple::Off;
#endif
}

// mdom: one more iteration per frame (thesis 5.3.3: each iteration's image
// shown as it comes), its grids baked towards the eye, and baked again
// whenever the eye moves.
void ScatteringGrids::iterate(ViewerState& state, ScatteringRenderer& renderer) {
#ifdef LUCENT_HAVE_OPENCL
    Solvers& s = *solvers_;
    try {
        const Vec3 eye = state.camera.camera().position;
        if (solving_) {
            bool more = false;
            s.mdomSolutions.clear();
            for (auto& run : s.mdomRuns) {
                more = run->iterate() || more;
                s.mdomSolutions.push_back(run->solution());
            }
            const hybrid::MdomStats& st = s.mdomRuns.front()->stats();
            status_ = "mdom: iteration " + std::to_string(st.iterations) + (more ? "" : ", done");
            solving_ = more;
            s.bakedFor = Vec3(kInfinity);
        }
        if (eye != s.bakedFor) {
            renderer.clearScatteringGrids();
            for (const hybrid::MdomSolution& solution : s.mdomSolutions)
                renderer.addScatteringGrid(solution.towards(eye));
            s.bakedFor = eye;
        }
    } catch (const Error& e) {
        renderer.clearScatteringGrids();
        std::fprintf(stderr, "lucent: warning: view: no multiple scattering: %s\n", e.what());
        state.multiple = shown_ = ViewerState::Multiple::Off;
        solving_ = false;
    }
#else
    (void)state;
    (void)renderer;
#endif
}

}  // namespace lucent

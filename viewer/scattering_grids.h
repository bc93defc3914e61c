#pragma once
// The multiple scattering the viewer adds to its frame, as the panel or a
// script asks for it (ViewerState::multiple): lbl solved at once (thesis ch. 4),
// mdom one iteration per frame with each iteration's image shown as it comes
// (thesis 5.3.3), both solved again when the lights or the objects move. A
// build without OpenCL, or a machine without a device, says so once and
// leaves the viewer running with single scattering alone.
#include <memory>
#include <string>

#include "core/loaded_scene.h"
#include "runtime/scattering_renderer.h"
#include "viewer/viewer_state.h"

namespace lucent {

class ScatteringGrids {
public:
    explicit ScatteringGrids(const LoadedScene& loaded);
    ~ScatteringGrids();

    // The lights or the objects' placements changed: solve again on the next update.
    void invalidate() { valid_ = false; }
    // Before a frame: gives the renderer the grids state.multiple asks for,
    // solved for lights (state's and its environment's), state's placements and
    // eye. A solve that fails prints a warning and sets state.multiple to Off.
    void update(ViewerState& state, ScatteringRenderer& renderer, const std::vector<Light>& lights);
    // mdom still iterating (a script's `wait` waits for it).
    bool solving() const { return solving_; }
    // "mdom: iteration N", ", done" once converged; empty for lbl and off.
    const std::string& status() const { return status_; }

private:
    struct Solvers;  // OpenCL's, in a build with it
    void begin(ViewerState& state, ScatteringRenderer& renderer, const std::vector<Light>& lights);
    void iterate(ViewerState& state, ScatteringRenderer& renderer);

    std::unique_ptr<Solvers> solvers_;
    ViewerState::Multiple shown_ = ViewerState::Multiple::Off;
    bool valid_ = false, solving_ = false;
    std::string status_;
};

}  // namespace lucent

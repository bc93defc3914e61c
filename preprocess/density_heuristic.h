#pragma once
// The sampling-density heuristic of thesis 3.2.3. The first moment of the
// attenuation, T(x) = integral exp(-tau(x,w)) w dw (eq. 3.5), points to where
// light comes from; its divergence is large where that changes fast (near the
// surface, at corners), so rho = |div T| says where samples are needed. Points
// that receive almost no light (integral exp(-tau) dw / 4 pi < epsilon) are culled.
//
// T is estimated by stratified Monte Carlo at every voxel of the distance field's
// band, with one randomly rotated lattice of d directions shared by all voxels (so
// the quadrature error is smooth in x and cancels in differences); OpenVDB takes
// its divergence by second-order central differences, and each layer vertex reads
// the result trilinearly. Sharing T between neighbouring vertices costs one
// estimate per voxel instead of six per vertex.
//
// Note: along any ray w . grad tau(x, w) = -sigma_t(x), so div T = sigma_t(x) *
// integral exp(-tau) dw exactly; the tests use this identity as an independent check.
//
// The grids are OpenVDB's, in the plug-in with the distance field (distance_field.h).
#include <cstdint>
#include <memory>
#include <vector>

#include "core/volume_object.h"
#include "preprocess/distance_field.h"

namespace lucent {

struct HeuristicSettings {
    int directions = 64;      // d of thesis 3.2.3
    double extinction = 1.0;  // scalar sigma_t the heuristic attenuates with
    double cullEpsilon = 1e-3;
    uint64_t seed = 1;
};

struct HeuristicPoint {
    double density = 0.0;     // |div T|
    double receivable = 0.0;  // integral exp(-tau) dw / (4 pi), in [0, 1]
    bool culled = true;
};

// T and the receivable light on the distance field's band.
class HeuristicField {
public:
    virtual ~HeuristicField();
    // div T by central differences, then rho and culling at each point.
    virtual std::vector<HeuristicPoint> densityAtPoints(const std::vector<Vec3>& points,
                                                        const HeuristicSettings& settings) const = 0;
    // T, trilinearly interpolated.
    virtual Vec3 firstMomentAt(const Vec3& point) const = 0;
    uint64_t raysCast = 0;
};

// The expensive part (d rays per voxel).
std::unique_ptr<HeuristicField> sampleFirstMoment(const VolumeObject& object, const DistanceField& field,
                                                  const HeuristicSettings& settings);

}  // namespace lucent

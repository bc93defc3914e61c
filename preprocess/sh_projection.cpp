#include "preprocess/sh_projection.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "core/progress.h"
#include "core/rng.h"
#include "core/sphere_directions.h"
#include "core/spherical_harmonics.h"

namespace lucent {

ProjectionResult projectAttenuation(const VolumeObject& object, const std::vector<Vec3>& positions,
                                    const ProjectionSettings& settings, int channels) {
    const int n = shCoefficientCount(settings.order);
    ProjectionResult result;
    result.channels = channels;
    result.coefficients.assign(positions.size() * size_t(channels) * n, 0.0f);
    result.truncationError.assign(positions.size(), 0.0f);
    // One randomly rotated lattice for every sample: its basis values are computed
    // once, and every sample's quadrature error has the same structure.
    std::vector<Vec3> lattice = fibonacciSphere(settings.directions);
    Rng rng(settings.seed ^ 0x5348ull, 0);
    const glm::dmat3 rotation = randomRotation(rng);
    std::vector<double> basisTable(lattice.size() * n);
    for (size_t k = 0; k < lattice.size(); ++k) {
        lattice[k] = rotation * lattice[k];
        evaluateSh(settings.order, lattice[k], std::span<double>(&basisTable[k * n], n));
    }
    const double weight = 4.0 * kPi / settings.directions;
    const Rgb sigmaT = object.desc().medium.sigmaT;
    Progress progress("SH projection", positions.size());

    tbb::parallel_for(tbb::blocked_range<size_t>(0, positions.size(), 32), [&](const tbb::blocked_range<size_t>& range) {
        std::vector<double> coefficients(size_t(channels) * n);
        for (size_t i = range.begin(); i < range.end(); ++i) {
            std::fill(coefficients.begin(), coefficients.end(), 0.0);
            double squaredNorm[3] = {0, 0, 0};
            for (size_t d = 0; d < lattice.size(); ++d) {
                const Rgb psi = transmittance(sigmaT, object.densityPath(positions[i], lattice[d]));
                const double* basis = &basisTable[d * n];
                for (int c = 0; c < channels; ++c) {
                    squaredNorm[c] += weight * psi[c] * psi[c];
                    for (int k = 0; k < n; ++k) coefficients[size_t(c) * n + k] += weight * psi[c] * basis[k];
                }
            }
            float* out = &result.coefficients[i * size_t(channels) * n];
            double worst = 0.0;
            for (int c = 0; c < channels; ++c) {
                double captured = 0.0;
                for (int k = 0; k < n; ++k) {
                    const double v = coefficients[size_t(c) * n + k];
                    captured += v * v;
                    out[c * n + k] = float(v);
                }
                // Parseval: sum of squared coefficients -> integral of psi^2 as the order grows.
                if (squaredNorm[c] > 0.0) worst = std::max(worst, 1.0 - captured / squaredNorm[c]);
            }
            result.truncationError[i] = float(std::clamp(worst, 0.0, 1.0));
            progress.advance();
        }
    });
    result.raysCast = uint64_t(positions.size()) * lattice.size();
    return result;
}

}  // namespace lucent

#include "preprocess/sh_projection.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "core/progress.h"
#include "core/rng.h"
#include "core/sphere_directions.h"
#include "core/spherical_harmonics.h"

namespace lucent {

double ballExitDistance(double cosine, double depth, double curvature) {
    // |x + s w| = R with |x| = R - d, x . w = (R - d) cos, solved for s >= 0 in a
    // form that stays exact as the curvature goes to 0 (the half-space, s = d / cos).
    if (curvature <= 0.0) return cosine > 0.0 ? depth / cosine : kInfinity;
    const double kd = std::min(curvature * depth, 1.0);
    const double a = (1.0 - kd) * cosine, b = kd * (2.0 - kd);
    const double root = std::sqrt(a * a + b);
    if (a >= 0.0) return a + root > 0.0 ? depth * (2.0 - kd) / (a + root) : kInfinity;
    return (root - a) / curvature;
}

Rgb ballTransmittance(const Rgb& sigmaT, const BoundaryBall& ball, const Vec3& w) {
    if (!ball.valid()) return Rgb(0.0);
    const double s = ballExitDistance(glm::dot(w, Vec3(ball.normal)), ball.depth, ball.curvature);
    if (!std::isfinite(s)) return Rgb(0.0);
    return glm::exp(-sigmaT * s);
}

ProjectionResult projectAttenuation(const VolumeObject& object, const std::vector<Vec3>& positions,
                                    const std::vector<BoundaryBall>& balls, const ProjectionSettings& settings,
                                    int channels) {
    const int n = shCoefficientCount(settings.order);
    ProjectionResult result;
    result.channels = channels;
    result.coefficients.assign(positions.size() * size_t(channels) * n, 0.0f);
    result.truncationError.assign(positions.size(), 0.0f);
    result.balls = balls;
    if (result.balls.empty()) result.balls.assign(positions.size(), BoundaryBall{});
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

    tbb::parallel_for(
        tbb::blocked_range<size_t>(0, positions.size(), 32), [&](const tbb::blocked_range<size_t>& range) {
            const size_t D = lattice.size();
            const size_t C = size_t(channels);
            std::vector<double> psi(D * C), model(D * C), psiRest(D * C), modelRest(D * C);
            std::vector<double> psiCoefficients(C * n), modelCoefficients(C * n);
            // Coefficients of f, and f minus its truncated expansion on the lattice.
            auto project = [&](const std::vector<double>& f, std::vector<double>& coefficients,
                               std::vector<double>& rest) {
                std::fill(coefficients.begin(), coefficients.end(), 0.0);
                for (size_t d = 0; d < D; ++d)
                    for (size_t c = 0; c < C; ++c)
                        for (int k = 0; k < n; ++k)
                            coefficients[c * n + k] += weight * f[d * C + c] * basisTable[d * n + k];
                for (size_t d = 0; d < D; ++d)
                    for (size_t c = 0; c < C; ++c) {
                        double v = f[d * C + c];
                        for (int k = 0; k < n; ++k) v -= coefficients[c * n + k] * basisTable[d * n + k];
                        rest[d * C + c] = v;
                    }
            };
            for (size_t i = range.begin(); i < range.end(); ++i) {
                for (size_t d = 0; d < D; ++d) {
                    const Rgb t =
                        transmittance(sigmaT, settings.shadowBlockersAtRuntime
                                                  ? object.densityPathThroughBlockers(positions[i], lattice[d])
                                                  : object.densityPath(positions[i], lattice[d]));
                    for (size_t c = 0; c < C; ++c) psi[d * C + c] = t[c];
                }
                project(psi, psiCoefficients, psiRest);
                double norm = 0.0, lost = 0.0;
                for (size_t j = 0; j < D * C; ++j) {
                    norm += psi[j] * psi[j];
                    lost += psiRest[j] * psiRest[j];
                }
                // The share of the ball's transmittance that leaves the least of psi
                // outside the SH bands (least squares on the lattice): close to 1 where
                // the ball is a good model of the object around the sample, 0 where not.
                BoundaryBall& ball = result.balls[i];
                ball.share = 0.0f;
                if (ball.valid()) {
                    const Rgb localSigmaT = object.extinction(positions[i]);
                    BoundaryBall full = ball;
                    full.share = 1.0f;
                    for (size_t d = 0; d < D; ++d) {
                        const Rgb t = ballTransmittance(localSigmaT, full, lattice[d]);
                        for (size_t c = 0; c < C; ++c) model[d * C + c] = t[c];
                    }
                    project(model, modelCoefficients, modelRest);
                    double cross = 0.0, modelNorm = 0.0;
                    for (size_t j = 0; j < D * C; ++j) {
                        cross += psiRest[j] * modelRest[j];
                        modelNorm += modelRest[j] * modelRest[j];
                    }
                    if (modelNorm > 0.0) {
                        const double share = std::clamp(cross / modelNorm, 0.0, 1.0);
                        lost += -2.0 * share * cross + share * share * modelNorm;
                        ball.share = float(share);
                    }
                }
                float* out = &result.coefficients[i * C * n];
                for (size_t k = 0; k < C * n; ++k)
                    out[k] = float(psiCoefficients[k] -
                                   (ball.share > 0.0f ? double(ball.share) * modelCoefficients[k] : 0.0));
                result.truncationError[i] = norm > 0.0 ? float(std::clamp(lost / norm, 0.0, 1.0)) : 0.0f;
                progress.advance();
            }
        });
    result.raysCast = uint64_t(positions.size()) * lattice.size();
    return result;
}

}  // namespace lucent

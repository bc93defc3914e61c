#include "preprocess/sh_projection.h"

#include <algorithm>
#include <array>
#include <span>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "core/progress.h"
#include "core/rng.h"
#include "core/spatial_order.h"
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

namespace {

// The directions every sample is projected on: one randomly rotated lattice, so
// that its basis values are computed once and every sample's quadrature error
// has the same structure.
struct Lattice {
    int n = 0;            // coefficients a channel
    double weight = 0.0;  // the quadrature's weight, 4 pi / D
    std::vector<Vec3> directions;
    std::vector<double> basis;  // [direction][coefficient]: the matrix B
    std::vector<double> gram;   // B^T B, n x n
};

Lattice makeLattice(const ProjectionSettings& settings) {
    Lattice lattice;
    lattice.n = shCoefficientCount(settings.order);
    const size_t n = size_t(lattice.n);
    lattice.weight = 4.0 * kPi / settings.directions;
    lattice.directions = fibonacciSphere(settings.directions);
    Rng rng(settings.seed ^ 0x5348ull, 0);
    const glm::dmat3 rotation = randomRotation(rng);
    lattice.basis.resize(lattice.directions.size() * n);
    for (size_t d = 0; d < lattice.directions.size(); ++d) {
        lattice.directions[d] = rotation * lattice.directions[d];
        evaluateSh(settings.order, lattice.directions[d], std::span<double>(&lattice.basis[d * n], n));
    }
    lattice.gram.assign(n * n, 0.0);
    for (size_t d = 0; d < lattice.directions.size(); ++d)
        for (size_t a = 0; a < n; ++a)
            for (size_t b = 0; b < n; ++b)
                lattice.gram[a * n + b] += lattice.basis[d * n + a] * lattice.basis[d * n + b];
    return lattice;
}

// out[c][k] += scale sum_r x[r][c] rows[r][k] for C channels: a block of eight
// coefficients a channel stays in registers while every row adds to it.
template <size_t C>
[[gnu::always_inline]] inline void accumulateRowsOf(const double* x, double scale, const double* rows, size_t rowCount,
                                                    size_t n, double* out) {
    constexpr size_t B = 8;
    size_t k0 = 0;
    for (; k0 + B <= n; k0 += B) {
        double sum[C][B];
        for (size_t c = 0; c < C; ++c)
            for (size_t j = 0; j < B; ++j) sum[c][j] = out[c * n + k0 + j];
        for (size_t r = 0; r < rowCount; ++r) {
            const double* row = rows + r * n + k0;
            for (size_t c = 0; c < C; ++c) {
                const double v = scale * x[r * C + c];
                for (size_t j = 0; j < B; ++j) sum[c][j] += v * row[j];
            }
        }
        for (size_t c = 0; c < C; ++c)
            for (size_t j = 0; j < B; ++j) out[c * n + k0 + j] = sum[c][j];
    }
    for (size_t r = 0; r < rowCount; ++r)
        for (size_t c = 0; c < C; ++c)
            for (size_t k = k0; k < n; ++k) out[c * n + k] += scale * x[r * C + c] * rows[r * n + k];
}

// The projection's whole arithmetic, for 1 or 3 channels. GCC builds it for AVX2
// with FMA as well, where the processor has them, and picks at load time.
#if defined(__GNUC__) && defined(__x86_64__)
__attribute__((target_clones("arch=x86-64-v3", "default")))
#endif
void accumulateRows(const double* x, size_t channels, double scale, const double* rows, size_t rowCount, size_t n,
                    double* out) {
    if (channels == 3)
        accumulateRowsOf<3>(x, scale, rows, rowCount, n, out);
    else
        accumulateRowsOf<1>(x, scale, rows, rowCount, n, out);
}

// One thread's work: psi for a packet of samples, then each sample's projection.
class SampleProjector {
public:
    SampleProjector(const VolumeObject& object, const Lattice& lattice, int channels)
        : object_(object),
          lattice_(lattice),
          D_(lattice.directions.size()),
          C_(size_t(channels)),
          psi_(MeshRaycaster::kPacket * D_ * C_),
          model_(D_ * C_) {}

    // psi of each origin in every lattice direction, a packet of rays a direction.
    void trace(std::span<const Vec3> origins, bool throughBlockers) {
        std::array<Vec3, MeshRaycaster::kPacket> dirs;
        std::array<double, MeshRaycaster::kPacket> paths;
        const Rgb sigmaT = object_.desc().medium.sigmaT;
        for (size_t d = 0; d < D_; ++d) {
            std::fill(dirs.begin(), dirs.end(), lattice_.directions[d]);
            object_.densityPaths(origins, std::span(dirs.data(), origins.size()), throughBlockers,
                                 std::span(paths.data(), origins.size()));
            for (size_t k = 0; k < origins.size(); ++k) {
                const Rgb t = transmittance(sigmaT, paths[k]);
                for (size_t c = 0; c < C_; ++c) psi_[(k * D_ + d) * C_ + c] = t[c];
            }
        }
    }

    // The coefficients of packet sample k at position, less the share of its
    // ball's transmittance that leaves the least of psi outside the SH bands
    // (least squares on the lattice): close to 1 where the ball is a good model
    // of the object around the sample, 0 where not. Sets ball.share and returns
    // the fraction of psi's squared norm that the bands and the ball miss.
    float fit(size_t k, const Vec3& position, BoundaryBall& ball, float* out) {
        const std::span<const double> psi(&psi_[k * D_ * C_], D_ * C_);
        project(psi, psiProjection_);
        double norm = 0.0;
        for (double v : psi) norm += v * v;
        double lost = restProduct(psi, psi, psiProjection_, psiProjection_);
        ball.share = 0.0f;
        if (ball.valid()) {
            const Rgb localSigmaT = object_.extinction(position);
            BoundaryBall full = ball;
            full.share = 1.0f;
            double modelValues = 0.0;
            for (size_t d = 0; d < D_; ++d) {
                const Rgb t = ballTransmittance(localSigmaT, full, lattice_.directions[d]);
                for (size_t c = 0; c < C_; ++c) {
                    model_[d * C_ + c] = t[c];
                    modelValues += t[c] * t[c];
                }
            }
            project(model_, modelProjection_);
            const double cross = restProduct(psi, model_, psiProjection_, modelProjection_);
            const double modelNorm = restProduct(model_, model_, modelProjection_, modelProjection_);
            if (modelNorm > 1e-9 * modelValues) {  // a model the bands hold (to rounding) fits nothing of the rest
                const double share = std::clamp(cross / modelNorm, 0.0, 1.0);
                lost += -2.0 * share * cross + share * share * modelNorm;
                ball.share = float(share);
            }
        }
        const std::vector<double>& c = psiProjection_.coefficients;
        const std::vector<double>& m = modelProjection_.coefficients;
        for (size_t j = 0; j < c.size(); ++j)
            out[j] = float(c[j] - (ball.share > 0.0f ? double(ball.share) * m[j] : 0.0));
        return norm > 0.0 ? float(std::clamp(lost / norm, 0.0, 1.0)) : 0.0f;
    }

private:
    // The coefficients c_f = w B^T f of f, and G c_f. On the lattice, the least-
    // squares rest of f is r_f = f - B c_f, and
    //   <r_f, r_g> = <f, g> - 2 c_f . c_g / w + c_f . G c_g,
    // which is all the fit reads of the rests: n^2 operations a vector, not the
    // D n of forming them.
    struct Projection {
        std::vector<double> coefficients, gramTimes;  // [channel][coefficient]
    };

    void project(std::span<const double> f, Projection& p) const {
        const size_t n = size_t(lattice_.n);
        p.coefficients.assign(C_ * n, 0.0);
        accumulateRows(f.data(), C_, lattice_.weight, lattice_.basis.data(), D_, n, p.coefficients.data());
        p.gramTimes.assign(C_ * n, 0.0);
        for (size_t c = 0; c < C_; ++c)
            accumulateRows(&p.coefficients[c * n], 1, 1.0, lattice_.gram.data(), n, n, &p.gramTimes[c * n]);
    }

    double restProduct(std::span<const double> f, std::span<const double> g, const Projection& pf,
                       const Projection& pg) const {
        double values = 0.0, plain = 0.0, gramForm = 0.0;
        for (size_t j = 0; j < f.size(); ++j) values += f[j] * g[j];
        for (size_t k = 0; k < pf.coefficients.size(); ++k) {
            plain += pf.coefficients[k] * pg.coefficients[k];
            gramForm += pf.coefficients[k] * pg.gramTimes[k];
        }
        return values - 2.0 * plain / lattice_.weight + gramForm;
    }

    const VolumeObject& object_;
    const Lattice& lattice_;
    size_t D_, C_;
    std::vector<double> psi_;    // [packet sample][direction][channel]
    std::vector<double> model_;  // [direction][channel]
    Projection psiProjection_, modelProjection_;
};

}  // namespace

ProjectionResult projectAttenuation(const VolumeObject& object, const std::vector<Vec3>& positions,
                                    const std::vector<BoundaryBall>& balls, const ProjectionSettings& settings,
                                    int channels) {
    ProjectionResult result;
    result.channels = channels;
    const Lattice lattice = makeLattice(settings);
    const size_t n = size_t(lattice.n), C = size_t(channels), P = MeshRaycaster::kPacket;
    result.coefficients.assign(positions.size() * C * n, 0.0f);
    result.truncationError.assign(positions.size(), 0.0f);
    result.balls = balls;
    if (result.balls.empty()) result.balls.assign(positions.size(), BoundaryBall{});
    Progress progress("SH projection", positions.size());
    // Samples in packets of neighbours: the rays of one direction from each then
    // run side by side, and Embree traces them together.
    const std::vector<uint32_t> order = spatialOrder(positions);
    const size_t packets = (positions.size() + P - 1) / P;
    tbb::parallel_for(tbb::blocked_range<size_t>(0, packets, 4), [&](const tbb::blocked_range<size_t>& range) {
        SampleProjector projector(object, lattice, channels);
        std::array<Vec3, MeshRaycaster::kPacket> origins;
        for (size_t packet = range.begin(); packet < range.end(); ++packet) {
            const size_t first = packet * P, count = std::min(P, positions.size() - first);
            for (size_t k = 0; k < count; ++k) origins[k] = positions[order[first + k]];
            projector.trace(std::span(origins.data(), count), settings.shadowBlockersAtRuntime);
            for (size_t k = 0; k < count; ++k) {
                const size_t i = order[first + k];
                result.truncationError[i] =
                    projector.fit(k, positions[i], result.balls[i], &result.coefficients[i * C * n]);
                progress.advance();
            }
        }
    });
    result.raysCast = uint64_t(positions.size()) * lattice.directions.size();
    return result;
}

}  // namespace lucent

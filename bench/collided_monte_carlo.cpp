#include "bench/collided_monte_carlo.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <random>
#include <stdexcept>
#include <thread>

#include "bench/least_optical_depth.h"
#include "bench/unfolded_problem.h"

namespace lucent {

namespace {

constexpr int kBatches = 32;  // independent batches per point, for the standard error

struct Random {
    std::mt19937_64 engine;
    double operator()() { return double(engine() >> 11) * 0x1.0p-53; }  // [0, 1)
    Vec3 direction() {
        const double z = 1.0 - 2.0 * (*this)(), phi = 2.0 * kPi * (*this)(), s = std::sqrt(std::max(0.0, 1.0 - z * z));
        return {s * std::cos(phi), s * std::sin(phi), z};
    }
    Vec3 inCone(const UnfoldedProblem::Cone& c) {
        const double mu = c.lowest + (*this)() * (1.0 - c.lowest);
        return c.direction(mu, 2.0 * kPi * (*this)());
    }
};

// The fraction of the sphere a cone holds: the 1 / (4 pi) of a scalar flux
// over the pdf of a direction drawn uniformly in the cone.
double coneShare(const UnfoldedProblem::Cone& c) { return 0.5 * (1.0 - c.lowest); }

class Reciprocal {
public:
    explicit Reciprocal(const UnfoldedProblem& u) : u_(u), depth_(u), domain_(u.unfoldedDomain()) {
        for (const TransportRegion& r : u.problem().regions) {
            if (r.g != 0.0) throw std::invalid_argument("collidedMonteCarlo: anisotropic scattering (g other than 0)");
            majorant_ = std::max(majorant_, r.sigmaT);
        }
    }
    // One history from the point: its estimate of the collided flux there.
    double run(Random& random, const Vec3& point) const {
        const Bounds3& sources = u_.sources();
        if (!(sources.min.x <= sources.max.x) || !(majorant_ > 0.0)) return 0.0;
        const double start = depth_(point);
        double score = nextAmongSources(random, point, u_.sourceCone(point));
        thread_local std::vector<Particle> stack;
        stack.assign(1, {point, random.direction(), 1.0, 1.0});
        while (!stack.empty()) {
            Particle particle = stack.back();
            stack.pop_back();
            follow(random, particle, start, stack, score);
        }
        return score;
    }

private:
    struct Particle {
        Vec3 x, w;
        double weight, importance;  // importance relative to the start's
        bool split = false;         // a copy yet to be tested for a collision where it was split off
    };

    // The sources' uncollided flux at x, by one direction in their cone from x.
    double uncollided(Random& random, const Vec3& x, const UnfoldedProblem::Cone& cone) const {
        return coneShare(cone) * u_.emission(x, random.inCone(cone));
    }

    // The expected score of the next collision from x where it falls among
    // the sources: int over the sources along one direction of their cone of
    // sigma_s e^{-tau} times the uncollided flux, by one point drawn
    // uniformly along the pieces among them.
    double nextAmongSources(Random& random, const Vec3& x, const UnfoldedProblem::Cone& cone) const {
        const Vec3 w = random.inCone(cone);
        double t0 = 0.0, end = kInfinity;
        if (!clipToBox(u_.sources(), x, w, t0, end)) return 0.0;
        struct Piece {
            double t0, length, tau;
            const TransportRegion* r;
        };
        thread_local std::vector<Piece> pieces;
        pieces.clear();
        double tau = 0.0, length = 0.0;
        u_.walk(x, w, end, [&](const TransportRegion* r, double a, double b) {
            if (r && r->source > 0.0) {
                pieces.push_back({a, b - a, tau, r});
                length += b - a;
            }
            if (r) tau += r->sigmaT * (b - a);
        });
        double pick = random() * length;
        for (const Piece& p : pieces) {
            if (pick > p.length) {
                pick -= p.length;
                continue;
            }
            const double collided = p.r->sigmaS * std::exp(-(p.tau + p.r->sigmaT * pick));
            const Vec3 y = x + w * (p.t0 + pick);
            return coneShare(cone) * length * collided * uncollided(random, y, u_.sourceCone(y));
        }
        return 0.0;
    }

    // Split where the importance rose, roulette where it fell (at every step,
    // virtual collisions too: a particle that crossed a wall in one flight
    // would reach its far side with the weight it had). False: killed.
    bool splitOrRoulette(Random& random, Particle& p, double start, std::vector<Particle>& stack) const {
        const double now = std::exp(start - depth_(p.x)), ratio = now / p.importance;
        p.importance = now;
        if (ratio > 1.0) {
            const int copies = std::min(int(ratio + random()), 64);
            p.weight /= copies;
            Particle copy = p;
            copy.split = true;
            for (int c = 1; c < copies; ++c) stack.push_back(copy);
        } else if (ratio < 1.0) {
            if (random() >= ratio) return false;
            p.weight /= ratio;
        }
        return true;
    }

    // A particle until it escapes or dies; the copies it splits into go on the stack.
    void follow(Random& random, Particle& p, double start, std::vector<Particle>& stack, double& score) const {
        for (;;) {
            if (!p.split) {  // a copy split off here has flown already
                const Vec3 y = p.x + p.w * (-std::log(1.0 - random()) / majorant_);
                if (!domain_.contains(y)) return;  // through a vacuum face
                p.x = u_.fold(y);
                for (int a = 0; a < 3; ++a)
                    if (p.x[a] != y[a]) p.w[a] = -p.w[a];  // reflected
                if (!splitOrRoulette(random, p, start, stack)) return;
            }
            p.split = false;
            const TransportRegion* r = u_.at(p.x);
            if (!r || random() * majorant_ >= r->sigmaT) continue;  // a virtual collision
            const double albedo = r->sigmaS / r->sigmaT;
            if (!(albedo > 0.0)) return;
            p.weight *= albedo;
            const UnfoldedProblem::Cone cone = u_.sourceCone(p.x);
            if (r->source <= 0.0)
                score += p.weight * uncollided(random, p.x, cone);  // among the sources: scored before
            score += p.weight * nextAmongSources(random, p.x, cone);
            if (p.weight < 0.05 / p.importance) {  // light below its place's share
                if (random() >= 0.25) return;
                p.weight *= 4.0;
            }
            p.w = random.direction();
        }
    }

    const UnfoldedProblem& u_;
    const LeastOpticalDepth depth_;
    Bounds3 domain_;
    double majorant_ = 0.0;
};

}  // namespace

CollidedEstimate collidedMonteCarlo(const TransportProblem& problem, const std::vector<Vec3>& points, long histories,
                                    int threads, uint64_t seed) {
    const UnfoldedProblem u(problem);
    const Reciprocal game(u);
    const long perBatch = std::max(1L, histories / kBatches);
    const size_t jobs = points.size() * kBatches;
    std::vector<double> batch(jobs, 0.0);  // each (point, batch)'s mean
    std::atomic<size_t> next{0};
    auto work = [&] {
        for (size_t job; (job = next++) < jobs;) {
            Random random{std::mt19937_64(seed * 1000003u + uint64_t(job))};  // per job: independent of threads
            double sum = 0.0;
            for (long i = 0; i < perBatch; ++i) sum += game.run(random, points[job / kBatches]);
            batch[job] = sum / double(perBatch);
        }
    };
    std::vector<std::thread> pool;
    for (int t = 1; t < threads; ++t) pool.emplace_back(work);
    work();
    for (std::thread& t : pool) t.join();

    CollidedEstimate e;
    e.histories = perBatch * kBatches;
    for (size_t i = 0; i < points.size(); ++i) {
        double sum = 0.0, squares = 0.0;
        for (int b = 0; b < kBatches; ++b) {
            const double mean = batch[i * kBatches + b];
            sum += mean;
            squares += mean * mean;
        }
        const double mean = sum / kBatches, variance = std::max(0.0, squares / kBatches - mean * mean);
        e.flux.push_back(mean);
        e.standardError.push_back(std::sqrt(variance / (kBatches - 1)));
    }
    return e;
}

}  // namespace lucent

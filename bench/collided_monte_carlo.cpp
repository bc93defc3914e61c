#include "bench/collided_monte_carlo.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <thread>

#include "bench/unfolded_problem.h"

namespace lucent {

namespace {

constexpr int kBatches = 32;  // independent batches, for the standard error

struct Random {
    std::mt19937_64 engine;
    double operator()() { return double(engine() >> 11) * 0x1.0p-53; }  // [0, 1)
    Vec3 direction() {
        const double z = 1.0 - 2.0 * (*this)(), phi = 2.0 * kPi * (*this)(), s = std::sqrt(std::max(0.0, 1.0 - z * z));
        return {s * std::cos(phi), s * std::sin(phi), z};
    }
};

class Histories {
public:
    Histories(const UnfoldedProblem& u, const std::vector<Vec3>& points, double r0)
        : u_(u), points_(points), r0_(r0), domain_(u.unfoldedDomain()) {
        const TransportProblem& p = u.problem();
        for (const TransportRegion& r : p.regions) {
            if (r.g != 0.0) throw std::invalid_argument("collidedMonteCarlo: anisotropic scattering (g other than 0)");
            majorant_ = std::max(majorant_, r.sigmaT);
            if (r.source <= 0.0) continue;
            const Vec3 e = r.box.max - r.box.min;
            strength_ += r.source * e.x * e.y * e.z;
            sources_.push_back(&r);
            cumulative_.push_back(strength_);
            sourceBox_.extend(glm::max(r.box.min, p.domain.min));
            sourceBox_.extend(glm::min(r.box.max, p.domain.max));
        }
    }
    // Total source strength: each history stands for this much emission.
    double strength() const { return strength_; }
    // One history's scores at the points, added to `score`.
    void run(Random& random, std::vector<double>& score) const {
        if (sources_.empty()) return;
        const double pick = random() * strength_;
        size_t s = 0;
        while (s + 1 < sources_.size() && cumulative_[s] <= pick) ++s;
        const TransportRegion& source = *sources_[s];
        Vec3 x;
        for (int a = 0; a < 3; ++a) x[a] = source.box.min[a] + random() * (source.box.max[a] - source.box.min[a]);
        if (u_.at(x) != &source) return;  // overridden by a later region: emits nothing, scores nothing
        std::vector<Particle> stack{{x, random.direction(), 1.0, importance(x)}};
        while (!stack.empty()) {
            Particle particle = stack.back();
            stack.pop_back();
            follow(random, particle, stack, score);
        }
    }

private:
    struct Particle {
        Vec3 x, w;
        double weight, importance;
        bool split = false;  // a copy that has yet to be tested for a collision where it was split off
    };
    // How much a particle at x matters to the points deep in the medium: e to
    // half the optical depth to the nearest source (splitting in proportion
    // keeps particles going where the light is faint).
    double importance(const Vec3& x) const {
        return std::exp(0.5 * u_.opticalDepth(x, glm::clamp(x, sourceBox_.min, sourceBox_.max)));
    }
    // A particle until it escapes or is absorbed; the copies it splits into go on the stack.
    void follow(Random& random, Particle& p, std::vector<Particle>& stack, std::vector<double>& score) const {
        while (majorant_ > 0.0) {
            if (!p.split) {  // a copy split off here has flown already
                const Vec3 y = p.x + p.w * (-std::log(1.0 - random()) / majorant_);
                if (!domain_.contains(y)) return;  // through a vacuum face
                p.x = u_.fold(y);
                for (int a = 0; a < 3; ++a)
                    if (p.x[a] != y[a]) p.w[a] = -p.w[a];  // reflected
                // At every step, virtual collisions too (a particle that crossed a
                // wall in one flight would reach the far side with the weight it
                // had): split where the importance rose, roulette where it fell.
                const double now = importance(p.x), ratio = now / p.importance;
                p.importance = now;
                if (ratio > 1.0) {
                    const int copies = std::min(int(ratio + random()), 64);
                    p.weight /= copies;
                    Particle copy = p;
                    copy.split = true;  // each copy is tested for a collision here too
                    for (int c = 1; c < copies; ++c) stack.push_back(copy);
                } else if (ratio < 1.0) {
                    if (random() >= ratio) return;
                    p.weight /= ratio;
                }
            }
            p.split = false;
            const double now = p.importance;
            const TransportRegion* r = u_.at(p.x);
            if (!r || random() * majorant_ >= r->sigmaT) continue;  // a virtual collision
            const double albedo = r->sigmaS / r->sigmaT;
            if (!(albedo > 0.0)) return;
            p.weight *= albedo;
            scoreCollision(p.x, p.weight, score);
            if (p.weight < 0.05 / now) {  // light below its place's share: roulette
                if (random() >= 0.25) return;
                p.weight *= 4.0;
            }
            p.w = random.direction();
        }
    }

    // The scattered light `emitted` at x, seen at every point from every image of x.
    void scoreCollision(const Vec3& x, double emitted, std::vector<double>& score) const {
        for (const Vec3& image : u_.images(x))
            for (size_t i = 0; i < points_.size(); ++i) {
                const double r = glm::length(points_[i] - image);
                const double kernel = r > r0_ ? 1.0 / (4.0 * kPi * r * r) : 3.0 / (4.0 * kPi * r0_ * r0_);
                score[i] += emitted * std::exp(-u_.opticalDepth(image, points_[i])) * kernel;
            }
    }

    const UnfoldedProblem& u_;
    const std::vector<Vec3>& points_;
    double r0_;
    Bounds3 domain_, sourceBox_;
    double majorant_ = 0.0, strength_ = 0.0;
    std::vector<const TransportRegion*> sources_;
    std::vector<double> cumulative_;
};

}  // namespace

CollidedEstimate collidedMonteCarlo(const TransportProblem& problem, const std::vector<Vec3>& points, long histories,
                                    int threads, uint64_t seed, double r0) {
    const UnfoldedProblem u(problem);
    const Histories h(u, points, r0);
    const long perBatch = std::max(1L, histories / kBatches);
    std::vector<std::vector<double>> batch(kBatches, std::vector<double>(points.size(), 0.0));
    auto work = [&](int thread) {
        for (int b = thread; b < kBatches; b += threads) {
            Random random{std::mt19937_64(seed * 1000003u + uint64_t(b))};  // per batch: independent of threads
            for (long i = 0; i < perBatch; ++i) h.run(random, batch[b]);
        }
    };
    std::vector<std::thread> pool;
    for (int t = 1; t < threads; ++t) pool.emplace_back(work, t);
    work(0);
    for (std::thread& t : pool) t.join();

    CollidedEstimate e;
    e.histories = perBatch * kBatches;
    for (size_t i = 0; i < points.size(); ++i) {
        double sum = 0.0, squares = 0.0;
        for (const std::vector<double>& b : batch) {
            const double mean = b[i] / double(perBatch) * h.strength();
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

#include "bench/uncollided_quadrature.h"

#include <cmath>

#include "bench/unfolded_problem.h"

namespace lucent {

double uncollidedQuadrature(const TransportProblem& problem, const Vec3& x, int polar) {
    const UnfoldedProblem u(problem);
    const UnfoldedProblem::Cone cone = u.sourceCone(x);
    const int azimuths = 2 * polar;
    double sum = 0.0;
    for (int i = 0; i < polar; ++i) {
        const double mu = cone.lowest + (i + 0.5) * (1.0 - cone.lowest) / polar;
        for (int j = 0; j < azimuths; ++j) sum += u.emission(x, cone.direction(mu, (j + 0.5) * 2.0 * kPi / azimuths));
    }
    return sum * ((1.0 - cone.lowest) / polar) * (2.0 * kPi / azimuths) / (4.0 * kPi);
}

}  // namespace lucent

#include "core/spherical_harmonics.h"

#include <array>
#include <cassert>
#include <cmath>

namespace lucent {
namespace {

// K_lm = sqrt((2l+1)/(4 pi) * (l-m)!/(l+m)!), tabulated once.
struct Normalisation {
    std::array<std::array<double, kMaxShOrder>, kMaxShOrder> k{};
    Normalisation() {
        for (int l = 0; l < kMaxShOrder; ++l)
            for (int m = 0; m <= l; ++m) {
                double ratio = 1.0;  // (l-m)!/(l+m)!
                for (int j = l - m + 1; j <= l + m; ++j) ratio /= double(j);
                k[l][m] = std::sqrt((2.0 * l + 1.0) / (4.0 * kPi) * ratio);
            }
    }
};
const Normalisation kNorm;

}  // namespace

void evaluateSh(int order, const Vec3& dir, std::span<double> out) {
    assert(order >= 1 && order <= kMaxShOrder);
    assert(int(out.size()) >= order * order);
    const double x = dir.x, y = dir.y, z = dir.z;
    // Work with Q_l^m(z) = P_l^m(z) / sin^m(theta), a polynomial obeying the same
    // three-term recurrence as P_l^m, and carry sin^m(theta) e^{i m phi} as (x + i y)^m.
    // This avoids atan2 and acos and stays exact at the poles.
    double cm = 1.0, sm = 0.0;  // Re, Im of (x + i y)^m
    double qmm = 1.0;           // Q_m^m = (-1)^m (2m-1)!!
    for (int m = 0; m < order; ++m) {
        double qPrev2 = 0.0, qPrev1 = qmm;
        for (int l = m; l < order; ++l) {
            double q;
            if (l == m)
                q = qmm;
            else if (l == m + 1)
                q = z * (2.0 * m + 1.0) * qmm;
            else
                q = ((2.0 * l - 1.0) * z * qPrev1 - (l + m - 1.0) * qPrev2) / double(l - m);
            if (l > m) {
                qPrev2 = qPrev1;
                qPrev1 = q;
            }
            const double k = kNorm.k[l][m];
            if (m == 0) {
                out[shIndex(l, 0)] = k * q;
            } else {
                out[shIndex(l, m)] = std::sqrt(2.0) * k * q * cm;
                out[shIndex(l, -m)] = std::sqrt(2.0) * k * q * sm;
            }
        }
        // Advance to m + 1.
        const double c = cm * x - sm * y, s = cm * y + sm * x;
        cm = c;
        sm = s;
        qmm *= -(2.0 * m + 1.0);
    }
}

double reconstructSh(int order, std::span<const double> coefficients, const Vec3& dir) {
    std::array<double, kMaxShOrder * kMaxShOrder> basis;
    evaluateSh(order, dir, basis);
    double sum = 0.0;
    for (int i = 0; i < order * order; ++i) sum += coefficients[i] * basis[i];
    return sum;
}

}  // namespace lucent

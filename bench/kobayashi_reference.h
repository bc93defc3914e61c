#pragma once
// Kobayashi's 3-D radiation transport benchmark, problem 1: the total scalar
// flux at its detectors (OECD/NEA NSC-DOC(2000)4; Kobayashi, Sugimura and
// Nagaya, Progress in Nuclear Energy 39(2) 119-144, 2001). The absorber's are
// the exact uncollided values; with 50% scattering, the report's Monte Carlo
// (GMVP) values and their relative standard error. The geometry is
// models/transport/kobayashi-1-*.json (docs/transport.md).
#include "core/math.h"

namespace lucent {

struct KobayashiDetector {
    char set;             // A along (5, y, 5), B along (x, x, x), C along (x, 55, 5)
    Vec3 at;              // cm
    double absorber;      // n cm^-2 s^-1, exact
    double scatter;       // n cm^-2 s^-1, Monte Carlo
    double scatterError;  // relative standard error of `scatter`
};

inline constexpr KobayashiDetector kKobayashiProblem1[] = {
    {'A', {5, 5, 5}, 5.95659e+00, 8.29260e+00, 0.0002},    {'A', {5, 15, 5}, 1.37185e+00, 1.87028e+00, 0.0001},
    {'A', {5, 25, 5}, 5.00871e-01, 7.13986e-01, 0.0000},   {'A', {5, 35, 5}, 2.52429e-01, 3.84685e-01, 0.0000},
    {'A', {5, 45, 5}, 1.50260e-01, 2.53984e-01, 0.0001},   {'A', {5, 55, 5}, 5.95286e-02, 1.37220e-01, 0.0007},
    {'A', {5, 65, 5}, 1.53283e-02, 4.65913e-02, 0.0012},   {'A', {5, 75, 5}, 4.17689e-03, 1.58766e-02, 0.0020},
    {'A', {5, 85, 5}, 1.18533e-03, 5.47036e-03, 0.0034},   {'A', {5, 95, 5}, 3.46846e-04, 1.85082e-03, 0.0062},
    {'B', {5, 5, 5}, 5.95659e+00, 8.29260e+00, 0.0002},    {'B', {15, 15, 15}, 4.70754e-01, 6.63233e-01, 0.0000},
    {'B', {25, 25, 25}, 1.69968e-01, 2.68828e-01, 0.0000}, {'B', {35, 35, 35}, 8.68334e-02, 1.56683e-01, 0.0001},
    {'B', {45, 45, 45}, 5.25132e-02, 1.04405e-01, 0.0001}, {'B', {55, 55, 55}, 1.33378e-02, 3.02145e-02, 0.0006},
    {'B', {65, 65, 65}, 1.45867e-03, 4.06555e-03, 0.0007}, {'B', {75, 75, 75}, 1.75364e-04, 5.86124e-04, 0.0012},
    {'B', {85, 85, 85}, 2.24607e-05, 8.66059e-05, 0.0020}, {'B', {95, 95, 95}, 3.01032e-06, 1.12892e-05, 0.0038},
    {'C', {5, 55, 5}, 5.95286e-02, 1.37220e-01, 0.0007},   {'C', {15, 55, 5}, 5.50247e-02, 1.27890e-01, 0.0008},
    {'C', {25, 55, 5}, 4.80754e-02, 1.13582e-01, 0.0008},  {'C', {35, 55, 5}, 3.96765e-02, 9.59578e-02, 0.0009},
    {'C', {45, 55, 5}, 3.16366e-02, 7.82701e-02, 0.0009},  {'C', {55, 55, 5}, 2.35303e-02, 5.67030e-02, 0.0011},
    {'C', {65, 55, 5}, 5.83721e-03, 1.88631e-02, 0.0019},  {'C', {75, 55, 5}, 1.56731e-03, 6.46624e-03, 0.0031},
    {'C', {85, 55, 5}, 4.53113e-04, 2.28099e-03, 0.0053},  {'C', {95, 55, 5}, 1.37079e-04, 7.93924e-04, 0.0089},
};

}  // namespace lucent

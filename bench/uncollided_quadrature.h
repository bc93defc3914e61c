#pragma once
// The uncollided scalar flux of a `lucent transport` problem at a point,
// computed without the solver's cells: an independent truth for pure
// absorbers (Kobayashi's problems 2 and 3 have no published one). Along each
// direction from the point the medium is piecewise constant between the
// regions' planes, so the emission integral int q e^{-tau} dt is exact piece
// by piece; the directions are a product midpoint rule over the cone that
// holds every source and its mirror images. Reflective faces are unfolded:
// beyond a mirror the medium and the sources are the mirror image of the
// domain's (one reflective face per axis at most).
#include "core/transport_problem.h"

namespace lucent {

// phi(x) = 1 / (4 pi) int_{4 pi} int_0^inf q(x + t w) e^{-tau(t)} dt dw, with
// `polar` cosines and 2 `polar` azimuths in the cone (or the whole sphere
// when x lies among the sources). Throws std::invalid_argument where both
// faces of an axis are reflective.
double uncollidedQuadrature(const TransportProblem& problem, const Vec3& x, int polar = 256);

}  // namespace lucent

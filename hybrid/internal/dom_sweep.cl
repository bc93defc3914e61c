// The discrete ordinates solver of thesis 5.3 on the device. Built with
//   DOM_K: directions per octant (N / 8), DOM_BANDS: spherical-harmonic bands
//   stored, DOM_M = DOM_BANDS^2 moments.
// Radiance sources and fluxes are kept as real spherical-harmonic moments per
// voxel, rgb in a float4 ([voxel][moment]): the source towards direction n is
// sum_m source_m Y_m(omega_n), and the flux moments are
// phi_m = sum_n w_n L_n Y_m(omega_n).

// (1 - e^-x) / x and (x - 1 + e^-x) / x^2, finite from x = 0 (limits 1 and 1/2)
// to x = infinity (1/x and 1/x): the radiance a characteristic gathers from a
// source S over a length s is S s phi1(sigma s), whatever sigma. Per channel.
inline float4 phi1(float4 x, float4 t) {
    const float4 series = 1.0f - x * (0.5f - x * (1.0f / 6.0f - x * (1.0f / 24.0f - x * (1.0f / 120.0f))));
    return select((1.0f - t) / x, series, x < 0.1f);
}
inline float4 psi(float4 x, float4 t) {
    const float4 series = 0.5f - x * (1.0f / 6.0f - x * (1.0f / 24.0f - x * (1.0f / 120.0f - x * (1.0f / 720.0f))));
    return select(select((x - 1.0f + t) / (x * x), 1.0f / x, x > 1e15f), series, x < 0.1f);
}

// Where face f's cells start in the boundary buffer (x-, x+, y-, y+, z-, z+;
// N directions of float4 radiance per cell).
inline int faceOffset(int f, int4 d) {
    const int cells[3] = {d.y * d.z, d.x * d.z, d.x * d.y};
    int off = 0;
    for (int g = 0; g < f; ++g) off += cells[g / 2];
    return off * 8 * DOM_K;
}

// One launch of an octant's sweep: the lines of voxels along x at (j, k) with
// j + k = diagonal (indices counted in the direction of the sweep), each
// marched voxel by voxel. A voxel's y and z inputs were written by the lines
// of the previous diagonal, its x input by the voxel before it in the line, so
// every work item runs independently (the wavefront w = i + j + k of thesis
// 5.3.3, one dimension folded into each work item). Radiance is float4: rgb.
//
// Per voxel and direction (thesis 5.3.1): with the voxel's extinction sigma
// and the source S towards the direction, the radiance leaving face Out is
//   L_Out = sum_In share[In][Out] (L_In e^{-sigma s} + S s phi1(sigma s)),   s = s_avg(In, Out),
// and the voxel's average radiance follows from the tubes (In, Out) that fill
// the voxel, so that absorption + out-flow = in-flow + emission exactly:
//   L_V = sum tube[In][Out] s (phi1(sigma s) L_In + s psi(sigma s) S),
// or, where the voxel is optically thicker than 0.1, from the balance itself:
//   sigma L_V = S + sum_In tube_In L_In - sum_Out tube_Out L_Out.
//
// The object's own boundary, where it refracts (index n != 1), reflects inside
// with Fresnel's share (and all of it past the critical angle): on a face
// between a voxel with medium and one of air (innerFace >= 0), the radiance
// leaving the medium along direction n keeps 1 - R going out, R at the angle
// between omega_n and the boundary's own normal there (the host's table), and
// R is stored (mirrorOut); the next iteration's sweep of the mirrored
// direction (one octant bit flipped, as at the box's reflecting faces) takes
// it back in on that face (mirrorIn). The staircase of faces reflects in its
// axes: the share is the boundary's, the direction the staircase's.
//
// The grid swept may be one block of a larger one (block_pool.h) or one rank's
// column of cells (sweep_halo.h): the faces in `halo` take in what the block
// or rank upstream left that face with (haloIn, this octant's slots).
kernel void dom_sweep(global const float4* extinction,  // sigma_t* per voxel; w: 0 where no flux is wanted
                      global const float4* source,      // [voxel][DOM_M]
                      global float4* flux,              // [voxel][DOM_M], accumulated
                      global float4* yFace,             // [k][i][DOM_K]
                      global float4* zFace,             // [j][i][DOM_K]
                      global const float4* boundaryIn,  // the previous iteration's out-going boundary radiance
                      global float4* boundaryOut,
                      constant float* ylm,              // [N][DOM_M]
                      constant float* weights,          // [N]
                      constant float* crossing,         // [DOM_K][27]: share[9], tube[9], length[9] (In * 3 + Out)
                      int4 dims, float maxEdge, int octant, int reflective, int diagonal, int kFirst,
                      global const int* innerFace,      // [voxel][6]: the faces to -x, +x, -y, +y, -z, +z: index, or -1
                      global const float4* mirrorIn,    // [face][N]: reflected inside, the previous iteration
                      global float4* mirrorOut,         // [face][N]
                      global const float* fresnel,      // [face][N]: R of each direction leaving by the face
                      int mirrors,                      // any inner faces at all
                      global const float4* haloIn,      // laid out as boundaryIn: what the neighbour ranks sent
                      int halo) {                       // faces whose radiance comes from a neighbour rank
    const int N = 8 * DOM_K;
    const int k = kFirst + (int)get_global_id(0), j = diagonal - k;
    const int nx = dims.x, ny = dims.y, nz = dims.z;
    const int sx = octant & 1, sy = (octant >> 1) & 1, sz = (octant >> 2) & 1;
    const int jr = sy ? ny - 1 - j : j, kr = sz ? nz - 1 - k : k;
    // The faces this octant enters by and leaves through, per axis.
    const int inX = sx, inY = 2 + sy, inZ = 4 + sz;
    const int outX = inX ^ 1, outY = inY ^ 1, outZ = inZ ^ 1;
    const int base = octant * DOM_K;
    // A reflecting face returns the direction mirrored in its axis: one octant bit flipped.
    float4 lx[DOM_K];
    for (int d = 0; d < DOM_K; ++d) {
        const int xCell = faceOffset(inX, dims) + (jr + ny * kr) * 8 * DOM_K;
        lx[d] = (halo >> inX) & 1         ? haloIn[xCell + base + d]
                : (reflective >> inX) & 1 ? boundaryIn[xCell + (octant ^ 1) * DOM_K + d]
                                          : (float4)(0.0f);
    }
    for (int i = 0; i < nx; ++i) {
        const int ir = sx ? nx - 1 - i : i;
        const size_t v = (size_t)ir + (size_t)nx * ((size_t)jr + (size_t)ny * kr);
        const float4 sigma = extinction[v];
        const float4 invSigma = 1.0f / sigma;
        // Below an optical depth of 0.1 across the voxel the balance would subtract near-equal numbers.
        const bool thin = fmin(fmin(sigma.x, sigma.y), sigma.z) * maxEdge < 0.1f;
        const bool vacuum = sigma.x == 0.0f && sigma.y == 0.0f && sigma.z == 0.0f;
        // Voxels whose flux nobody reads (nothing scatters there, the host says
        // so in w) neither read a source nor write moments: half the memory
        // traffic in a mesh's box is air.
        const bool active = sigma.w != 0.0f;
        // The inner faces this voxel enters by and leaves through, per axis (-1: none).
        int faceIn[3] = {-1, -1, -1}, faceOut[3] = {-1, -1, -1};
        if (mirrors && active) {
            const int flip[3] = {sx, sy, sz};
            for (int a = 0; a < 3; ++a) {
                const int down = innerFace[v * 6 + 2 * a], up = innerFace[v * 6 + 2 * a + 1];
                faceIn[a] = flip[a] ? up : down;
                faceOut[a] = flip[a] ? down : up;
            }
        }
        float4 src[DOM_M], acc[DOM_M];
        for (int m = 0; m < DOM_M; ++m) src[m] = active ? source[v * DOM_M + m] : (float4)(0.0f), acc[m] = (float4)(0.0f);
        global float4* yf = yFace + ((size_t)k * nx + i) * DOM_K;
        global float4* zf = zFace + ((size_t)j * nx + i) * DOM_K;
        const int yCell = faceOffset(inY, dims) + (ir + nx * kr) * 8 * DOM_K;
        const int zCell = faceOffset(inZ, dims) + (ir + nx * jr) * 8 * DOM_K;
        for (int d = 0; d < DOM_K; ++d) {
            const int n = base + d;
            constant float* cr = crossing + d * 27;
            float4 s = (float4)(0.0f);
            for (int m = 0; m < DOM_M; ++m) s += src[m] * ylm[n * DOM_M + m];
            float4 in[3];
            in[0] = lx[d];
            in[1] = j > 0                     ? yf[d]
                    : (halo >> inY) & 1       ? haloIn[yCell + n]
                    : (reflective >> inY) & 1 ? boundaryIn[yCell + (octant ^ 2) * DOM_K + d]
                                              : (float4)(0.0f);
            in[2] = k > 0                     ? zf[d]
                    : (halo >> inZ) & 1       ? haloIn[zCell + n]
                    : (reflective >> inZ) & 1 ? boundaryIn[zCell + (octant ^ 4) * DOM_K + d]
                                              : (float4)(0.0f);
            for (int a = 0; a < 3; ++a)
                if (faceIn[a] >= 0) in[a] += mirrorIn[(size_t)faceIn[a] * N + (octant ^ (1 << a)) * DOM_K + d];
            float4 out[3] = {(float4)(0.0f), (float4)(0.0f), (float4)(0.0f)}, average = (float4)(0.0f);
            if (vacuum) {
                // Nothing dims or scatters: phi1 = 1, psi = 1/2.
                for (int a = 0; a < 3; ++a)
                    for (int b = 0; b < 3; ++b) {
                        const float len = cr[18 + a * 3 + b];
                        out[b] += cr[a * 3 + b] * (in[a] + s * len);
                        average += cr[9 + a * 3 + b] * len * (in[a] + 0.5f * len * s);
                    }
            } else if (thin) {
                for (int a = 0; a < 3; ++a)
                    for (int b = 0; b < 3; ++b) {
                        const float len = cr[18 + a * 3 + b];
                        const float4 x = sigma * len, t = exp(-x), p1 = phi1(x, t);
                        out[b] += cr[a * 3 + b] * (in[a] * t + s * len * p1);
                        average += cr[9 + a * 3 + b] * len * (p1 * in[a] + len * psi(x, t) * s);
                    }
            } else {
                float4 flow = (float4)(0.0f);
                for (int a = 0; a < 3; ++a)
                    for (int b = 0; b < 3; ++b) {
                        const float4 t = exp(-sigma * cr[18 + a * 3 + b]);
                        const float4 carried = in[a] * t + s * (1.0f - t) * invSigma;
                        out[b] += cr[a * 3 + b] * carried;
                        flow += cr[9 + a * 3 + b] * (in[a] - carried);
                    }
                average = (s + flow) * invSigma;
            }
            for (int b = 0; b < 3; ++b)
                if (faceOut[b] >= 0) {
                    const float4 kept = fresnel[(size_t)faceOut[b] * N + n] * out[b];
                    mirrorOut[(size_t)faceOut[b] * N + n] = kept;
                    out[b] -= kept;
                }
            lx[d] = out[0];
            yf[d] = out[1];
            zf[d] = out[2];
            if (active) {
                const float4 wl = weights[n] * average;
                for (int m = 0; m < DOM_M; ++m) acc[m] += wl * ylm[n * DOM_M + m];
            }
            if (j == ny - 1) boundaryOut[faceOffset(outY, dims) + (ir + nx * kr) * 8 * DOM_K + n] = out[1];
            if (k == nz - 1) boundaryOut[faceOffset(outZ, dims) + (ir + nx * jr) * 8 * DOM_K + n] = out[2];
            if (i == nx - 1) boundaryOut[faceOffset(outX, dims) + (jr + ny * kr) * 8 * DOM_K + n] = out[0];
        }
        if (active)
            for (int m = 0; m < DOM_M; ++m) flux[v * DOM_M + m] += acc[m];
    }
}

// After an iteration's eight sweeps: the flux of this generation joins the
// total and scatters into the next generation's source,
//   source_lm = sigma_s* g*_l phi_lm          (thesis 5.3.2, the delta-M phase function diagonal in l)
// (the host then clears a fresh flux buffer for the next sweeps and keeps this one).
kernel void dom_scatter(global const float4* flux, global float4* total, global float4* source,
                        global const float4* scattering,  // sigma_s* per voxel
                        global const float4* phase) {     // x: Henyey-Greenstein g per voxel
    const size_t v = get_global_id(0);
    const float4 sigma = scattering[v];
    // The delta-M moments g*_l = (g^l - f) / (1 - f), f = g^DOM_BANDS (0 for g <= 0).
    const float g = phase[v].x, f = g > 0.0f ? pown(g, DOM_BANDS) : 0.0f;
    float gl = 1.0f, moment = 1.0f;
    for (int l = 0, m = 0; l < DOM_BANDS; ++l, gl *= g) {
        moment = l == 0 ? 1.0f : (gl - f) / (1.0f - f);
        for (int k = 0; k < 2 * l + 1; ++k, ++m) {
            const size_t at = v * DOM_M + m;
            const float4 phi = flux[at];
            total[at] += phi;
            source[at] = sigma * moment * phi;
        }
    }
}

// total += factor * flux, per channel: the generations still to come.
kernel void dom_add_scaled(global float4* total, global const float4* flux, float4 factor) {
    const size_t v = get_global_id(0);
    for (int m = 0; m < DOM_M; ++m) total[v * DOM_M + m] += factor * flux[v * DOM_M + m];
}

// The first-collided source (dom_solver.h, setUncollidedFlux): the zero
// moments of the scattering source in the source voxels, for the host to sum,
// and the part shaped like the sources, c times their zero moments, taken out.
kernel void dom_gather_zero(global const float4* source, global const int* voxels, global float4* out) {
    const size_t i = get_global_id(0);
    out[i] = source[(size_t)voxels[i] * DOM_M];
}

kernel void dom_take_shape(global float4* source, global const int* voxels, global const float4* shape, float4 c) {
    const size_t i = get_global_id(0);
    source[(size_t)voxels[i] * DOM_M] -= c * shape[i];
}

// Partial sums of the zero moments (the convergence measure), one per work
// item over a strided share of the voxels.
kernel void dom_power(global const float4* flux, global float4* partial, int voxels) {
    const int id = get_global_id(0), stride = get_global_size(0);
    float4 sum = (float4)(0.0f);
    for (int v = id; v < voxels; v += stride) sum += flux[(size_t)v * DOM_M];
    partial[id] = sum;
}

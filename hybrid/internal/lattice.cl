// Lattice-Boltzmann lighting (thesis 4.5, eq. 4.4-4.5; Geist et al. 2004) on 6
// directions. f[6 * voxel + d] is the power arriving at a voxel moving along
// direction d (+x -x +y -y +z -z). One lattice step is a collision, then
// streaming to the neighbour along d. With kappa_t = 1 - exp(-sigma_t lambda) the
// chance that a packet interacts within one voxel of path (lambda: voxel edge)
// and a the albedo, the collision is
//   out_d = (1 - kappa_t) f_d + (a kappa_t / 6) sum_j f_j + source / 6,
// thesis eq. 4.5 with its rest particle used only to inject the power that the
// photon marching deposits (isotropically). Thesis eq. 4.5 also turns the
// absorbed share kappa_a f into a rest particle that is re-emitted at the next
// step: mass is conserved but nothing is ever absorbed, so albedo would only
// delay light (Geist's D depends on kappa_a only through a time factor). Here
// the absorbed share (1 - a) kappa_t sum_j f_j leaves the lattice and is
// tallied, so the collision conserves power exactly: out + absorbed = in + source.
//
// Every packet arriving at a voxel has travelled kappa_t / sigma_t on average
// there (the mean path within one step), so the steady fluence is the track-
// length sum phi = (kappa_t / sigma_t) / V * sum_steps sum_d f_d, and the light
// scattered per unit length and solid angle is sigma_s phi / (4 pi)
// = a kappa_t / (4 pi V) * sum_steps sum_d f_d (kernel finish). The same path
// makes the tallies consistent: sigma_a phi V = (1 - a) kappa_t sum f is what
// the collisions absorb.
//
// Voxels: material.a = occupancy (0: empty, light that arrives there has left
// the object) or kOpaque (a blocker: light that arrives there is absorbed).
//
// A boundary that refracts (ior n != 1) keeps a share r of the light that
// reaches it from inside: a packet streaming from a medium voxel into an empty
// one comes back into its voxel reversed with r of its power, and 1 - r leaves.
// A lattice direction stands for the flux through a voxel's face, and the light
// near a boundary of a scattering medium is close to diffuse, so r is Fresnel's
// reflectance averaged over a diffuse hemisphere (diffuseFresnelReflectance,
// core/refraction.h): 0.47 at n = 1.33, 0.60 at n = 1.5. This is the partial-
// current boundary condition of diffusion theory, J- = r J+ (Groenhuis et al.
// 1983; Jensen et al. 2001, eq. 6-7), on the lattice's staircase boundary.

float3 interaction(float4 m, float lambda) { return -expm1(-m.xyz * lambda); }

constant int3 kStep[6] = {(int3)(1, 0, 0), (int3)(-1, 0, 0), (int3)(0, 1, 0),
                          (int3)(0, -1, 0), (int3)(0, 0, 1), (int3)(0, 0, -1)};

// One collision at a voxel of interaction chance kt: out[d] from in[d] (+ source), tallies updated.
void collide(const float4* in, float4 source, float4 kt, float4 albedo, float4* out, float4* fluence,
             float4* absorbed) {
    float4 sum = in[0] + in[1] + in[2] + in[3] + in[4] + in[5];
    *fluence += sum;
    *absorbed += (1.0f - albedo) * kt * sum;
    float4 isotropic = (albedo * kt * sum + source) * (1.0f / 6.0f);
    for (int d = 0; d < kDirections; ++d) out[d] = (1.0f - kt) * in[d] + isotropic;
}

// Where a packet that arrives at a voxel goes: into f (medium), escaped (empty:
// but the share r the boundary reflects, which its own voxel took back), absorbed (opaque).
void arrive(float4 m, float4 packet, float r, float4* f, float4* escaped, float4* absorbed) {
    if (m.w > 0.0f) *f = packet;
    else if (m.w < 0.0f) { *absorbed += packet; *f = (float4)(0.0f); }
    else { *escaped += (1.0f - r) * packet; *f = (float4)(0.0f); }
}

// Whether a packet moving along d into medium voxel c comes back off the boundary:
// the voxel it would come from, c - kStep[d], is empty (not a blocker, and in the grid).
bool mirrored(global const float4* material, int4 dims, int3 c, float4 m, int d, float r) {
    if (r <= 0.0f || m.w <= 0.0f) return false;
    int3 from = c - kStep[d];
    if (any(from < 0) || any(from >= dims.xyz)) return false;
    return material[from.x + dims.x * (from.y + dims.y * (size_t)from.z)].w == 0.0f;
}

// ---- The global lattice: one work-item per voxel, one step per pair of launches.
// The reference the blocked lattice is tested against (and its fallback).

kernel void lattice_collide(global const float4* f, global float4* source, global const float4* material,
                            global float4* out, global float4* fluence, global float4* absorbed, float4 albedo,
                            float lambda) {
    size_t at = get_global_id(0);
    float4 in[6], o[6];
    for (int d = 0; d < kDirections; ++d) in[d] = f[6 * at + d];
    float4 phi = fluence[at], abs = absorbed[at];
    collide(in, source[at], (float4)(interaction(material[at], lambda), 0.0f), albedo, o, &phi, &abs);
    source[at] = (float4)(0.0f);
    fluence[at] = phi;
    absorbed[at] = abs;
    for (int d = 0; d < kDirections; ++d) out[6 * at + d] = o[d];
}

kernel void lattice_stream(global const float4* out, global const float4* material, global float4* f,
                           global float4* escaped, global float4* absorbed, int4 dims, float r) {
    int3 c = (int3)(get_global_id(0), get_global_id(1), get_global_id(2));
    size_t at = c.x + dims.x * (c.y + dims.y * (size_t)c.z);
    float4 m = material[at], esc = escaped[at], abs = absorbed[at];
    for (int d = 0; d < kDirections; ++d) {
        if (mirrored(material, dims, c, m, d, r)) {  // its own packet along the reverse of d, reflected
            f[6 * at + d] = r * out[6 * at + (d ^ 1)];
            continue;
        }
        int3 from = c - kStep[d];
        float4 packet = (float4)(0.0f);
        if (all(from >= 0) && all(from < dims.xyz)) packet = out[6 * (from.x + dims.x * (from.y + dims.y * (size_t)from.z)) + d];
        float4 fd;
        arrive(m, packet, r, &fd, &esc, &abs);
        f[6 * at + d] = fd;
    }
    escaped[at] = esc;
    absorbed[at] = abs;
}

// ---- The blocked lattice (thesis 4.5): a work-group of kBlockVoxels work-items
// per active block runs `subSteps` lattice steps in local memory. Packets that
// leave the block go to its outgoing interface (6 faces x 4 x 4 per block),
// summed over the sub-steps, and enter the neighbour at the start of its next
// launch: a delay, not a loss, so once converged the time-summed fluence is the
// global lattice's (tests/hybrid: BlockedMatchesGlobalLattice). Interfaces are
// double-buffered (in: the previous launch's, out: this one's), which removes
// the read/write conflict that thesis fig. 4.5 solves by alternating faces.
// Blocks that hold no medium are not launched; what flows into them has escaped.

int faceSlot(int3 l, int axis) {
    return axis == 0 ? l.y + kBlockEdge * l.z : axis == 1 ? l.x + kBlockEdge * l.z : l.x + kBlockEdge * l.y;
}

kernel void lattice_blocks(global float4* f, global float4* source, global const float4* material,
                           global float4* fluence, global float4* absorbed, global float4* escaped,
                           global const float4* interfaceIn, global float4* interfaceOut,
                           global const int* activeBlocks, global const int* blockActive, int4 dims,
                           float4 albedo, float lambda, int subSteps, float r) {
    local float4 lf[kBlockVoxels * kDirections], lout[kBlockVoxels * kDirections];
    int3 blocks = dims.xyz / kBlockEdge;
    int b = activeBlocks[get_group_id(0)];
    int3 bc = (int3)(b % blocks.x, (b / blocks.x) % blocks.y, b / (blocks.x * blocks.y));
    int l = get_local_id(0);
    int3 lc = (int3)(l % kBlockEdge, (l / kBlockEdge) % kBlockEdge, l / (kBlockEdge * kBlockEdge));
    int3 c = bc * kBlockEdge + lc;
    size_t at = c.x + dims.x * (c.y + dims.y * (size_t)c.z);
    float4 m = material[at];
    float4 phi = fluence[at], abs = absorbed[at], esc = escaped[at];
    float4 src = source[at];
    source[at] = (float4)(0.0f);
    float4 leaving[6];
    for (int d = 0; d < kDirections; ++d) {
        leaving[d] = (float4)(0.0f);
        float4 fd = f[6 * at + d];
        // Packets moving along d enter through the face opposite to it.
        int axis = d >> 1;
        int3 nb = bc - kStep[d];
        bool entryFace = lc[axis] == ((d & 1) ? kBlockEdge - 1 : 0);
        if (entryFace && all(nb >= 0) && all(nb < blocks)) {
            int nbi = nb.x + blocks.x * (nb.y + blocks.y * nb.z);
            if (blockActive[nbi]) {
                float4 packet = interfaceIn[(nbi * kDirections + d) * kBlockEdge * kBlockEdge + faceSlot(lc, axis)];
                arrive(m, fd + packet, r, &fd, &esc, &abs);
            }
        }
        lf[6 * l + d] = fd;
    }
    bool mirror[6];
    for (int d = 0; d < kDirections; ++d) mirror[d] = mirrored(material, dims, c, m, d, r);
    barrier(CLK_LOCAL_MEM_FENCE);
    const float4 kt = (float4)(interaction(m, lambda), 0.0f);
    for (int s = 0; s < subSteps; ++s) {
        float4 in[6], o[6];
        for (int d = 0; d < kDirections; ++d) in[d] = lf[6 * l + d];
        collide(in, s == 0 ? src : (float4)(0.0f), kt, albedo, o, &phi, &abs);
        for (int d = 0; d < kDirections; ++d) lout[6 * l + d] = o[d];
        barrier(CLK_LOCAL_MEM_FENCE);
        for (int d = 0; d < kDirections; ++d) {
            int axis = d >> 1;
            int3 from = lc - kStep[d];
            float4 packet = (float4)(0.0f);
            if (all(from >= 0) && all(from < kBlockEdge))
                packet = lout[6 * (from.x + kBlockEdge * (from.y + kBlockEdge * from.z)) + d];
            float4 fd;
            if (mirror[d]) fd = r * lout[6 * l + (d ^ 1)];  // its own packet, reflected (any block's boundary)
            else arrive(m, packet, r, &fd, &esc, &abs);
            lf[6 * l + d] = fd;
            if (lc[axis] == ((d & 1) ? 0 : kBlockEdge - 1)) leaving[d] += lout[6 * l + d];
        }
        barrier(CLK_LOCAL_MEM_FENCE);
    }
    for (int d = 0; d < kDirections; ++d) {
        f[6 * at + d] = lf[6 * l + d];
        int axis = d >> 1;
        if (lc[axis] != ((d & 1) ? 0 : kBlockEdge - 1)) continue;
        int3 nb = bc + kStep[d];
        bool flows = all(nb >= 0) && all(nb < blocks) && blockActive[nb.x + blocks.x * (nb.y + blocks.y * nb.z)];
        if (flows) interfaceOut[(b * kDirections + d) * kBlockEdge * kBlockEdge + faceSlot(lc, axis)] = leaving[d];
        else esc += (mirrored(material, dims, c, m, d ^ 1, r) ? 1.0f - r : 1.0f) * leaving[d];  // r came back
    }
    fluence[at] = phi;
    absorbed[at] = abs;
    escaped[at] = esc;
}

// Sums the fluence tally at the probe voxels (the convergence test of thesis 4.6.1).
kernel void gather_probes(global const float4* fluence, global const int* probes, global float4* out) {
    out[get_global_id(0)] = fluence[probes[get_global_id(0)]];
}

// The radiance grid the view pass reads: sigma_s phi / (4 pi), see the top of this
// file. The lattice may run on reduced coefficients (similarity, Lattice's
// constructor): then the mean path per step is kappa'_t / sigma'_t, while the
// light scattered towards the eye takes the true sigma_s = albedo sigma_t.
kernel void finish(global const float4* fluence, global const float4* material, global const float4* latticeMaterial,
                   global float4* radiance, float4 albedo, float lambda, float invFourPiVolume) {
    size_t at = get_global_id(0);
    float4 m = material[at], reduced = latticeMaterial[at];
    float3 path = reduced.xyz * lambda > 1e-4f ? interaction(reduced, lambda) / reduced.xyz : (float3)(lambda);
    radiance[at] = m.w > 0.0f ? (float4)(albedo.xyz * m.xyz * path, 0.0f) * fluence[at] * invFourPiVolume
                              : (float4)(0.0f);
}

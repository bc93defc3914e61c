// Photon marching (thesis 4.4.2): each work-item carries one light ray through
// the material volume for `steps` fixed steps of length `step` (world units),
// depositing in the voxel where each step begins the power scattered along it:
//   scattered = albedo * P (1 - exp(-sigma_t step)),   P <- P exp(-sigma_t step),
// the exact form of thesis eq. 4.3 (its linearisation kappa_s P step loses
// energy balance when sigma_t step is not small). Deposits are added with 64-bit
// integer atomics on fixed point (kFixedBits), since OpenCL 1.2 has no float atomics.
//
// The path bends along the eikonal equation. With s the arc length and
// v = n dx/ds, the ray equation d/ds (n dx/ds) = grad n becomes
//   dx/ds = v / n,   dv/ds = grad n,
// which is thesis eq. 4.1-4.2 with step = ds. The code listing of thesis fig. 4.4
// also divides the velocity update by n; that breaks the invariant of the
// continuous ray, |v|^2 - n^2 = const (d|v|^2/ds = 2 v.grad n = 2 n dn/ds), and
// with it Snell's law across an interface (tests/hybrid: SnellAcrossSmoothedInterface).
//
// The smoothed index bends the ray but reflects nothing: where the ray first
// crosses the middle of the index's ramp, it keeps Fresnel's transmission
// 1 - R of its power, and the rest is tallied as escaped (reflected off the
// object). The angle of incidence is the one outside: across a boundary the
// component of v along it is conserved (|v| = n, Snell's n sin t = sin i), so
// sin i = |v x nu| at any point of the ramp, nu the unit gradient of n.
#pragma OPENCL EXTENSION cl_khr_int64_base_atomics : enable

float4 refractionAt(global const float4* refraction, int4 dims, float3 g) {
    // Trilinear between voxel centres, clamped at the grid's edge.
    float3 c = g - 0.5f;
    float3 f = c - floor(c);
    int3 lo = clamp(convert_int3(floor(c)), (int3)(0), dims.xyz - 1);
    int3 hi = min(lo + 1, dims.xyz - 1);
    float4 r = (float4)(0.0f);
    for (int k = 0; k < 8; ++k) {
        int3 q = (int3)((k & 1) ? hi.x : lo.x, (k & 2) ? hi.y : lo.y, (k & 4) ? hi.z : lo.z);
        float w = ((k & 1) ? f.x : 1.0f - f.x) * ((k & 2) ? f.y : 1.0f - f.y) * ((k & 4) ? f.z : 1.0f - f.z);
        r += w * refraction[q.x + dims.x * (q.y + dims.y * q.z)];
    }
    return r;
}

// Fresnel reflectance for light from air (unpolarised), cosine cosI, relative index n (core/refraction.cpp).
float fresnelFromAir(float cosI, float n) {
    float eta = 1.0f / n;
    float sin2T = eta * eta * (1.0f - cosI * cosI);
    float cosT = sqrt(max(0.0f, 1.0f - sin2T));
    float rs = (eta * cosI - cosT) / (eta * cosI + cosT), rp = (cosI - eta * cosT) / (cosI + eta * cosT);
    return 0.5f * (rs * rs + rp * rp);
}

void addFixed(global ulong* at, float3 value, float3 unitsPerWatt) {
    if (value.x > 0.0f) atom_add(at + 0, convert_ulong_rte(value.x * unitsPerWatt.x));
    if (value.y > 0.0f) atom_add(at + 1, convert_ulong_rte(value.y * unitsPerWatt.y));
    if (value.z > 0.0f) atom_add(at + 2, convert_ulong_rte(value.z * unitsPerWatt.z));
}

// tallies: [0..2] absorbed, [3..5] escaped, fixed point like deposit; [6] rays still marching.
kernel void march(global PhotonRay* rays, global const float4* material, global const float4* refraction,
                  global ulong* deposit, global ulong* tallies, int4 dims, float4 origin, float voxel,
                  float step, int steps, float4 albedo, float4 unitsPerWatt, int refracting, float ior) {
    PhotonRay ray = rays[get_global_id(0)];
    if (ray.position.w == 0.0f) return;
    float3 x = ray.position.xyz, v = ray.velocity.xyz, power = ray.power.xyz;
    bool entered = ray.velocity.w != 0.0f;
    float3 absorbed = (float3)(0.0f), reflected = (float3)(0.0f);
    bool alive = true;
    for (int s = 0; s < steps && alive; ++s) {
        float3 g = (x - origin.xyz) / voxel;
        int3 c = convert_int3(floor(g));
        if (any(c < 0) || any(c >= dims.xyz)) {
            addFixed(tallies + 3, power, unitsPerWatt.xyz);
            alive = false;
            break;
        }
        int at = c.x + dims.x * (c.y + dims.y * c.z);
        float4 m = material[at];
        if (m.w < 0.0f) {  // an opaque blocker
            absorbed += power;
            power = (float3)(0.0f);
            alive = false;
            break;
        }
        float3 interacted = power * -expm1(-m.xyz * step);
        float3 scattered = albedo.xyz * interacted;
        absorbed += interacted - scattered;
        power -= interacted;
        addFixed(deposit + 3 * at, scattered, unitsPerWatt.xyz);
        if (refracting) {
            // The midpoint rule on eq. 4.1-4.2 (second order; the thesis' forward
            // Euler step bends 1.3% short of Snell's law at 50 degrees here).
            float4 r = refractionAt(refraction, dims, g);
            if (!entered && r.x >= 0.5f * (1.0f + ior) && dot(r.yzw, r.yzw) > 0.0f) {
                entered = true;
                float sinI = length(cross(v, normalize(r.yzw)));
                float3 kept = power * (1.0f - fresnelFromAir(sqrt(max(0.0f, 1.0f - sinI * sinI)), ior));
                reflected += power - kept;
                power = kept;
            }
            float3 xm = x + 0.5f * step * v / r.x, vm = v + 0.5f * step * r.yzw;
            float4 rm = refractionAt(refraction, dims, (xm - origin.xyz) / voxel);
            x += step * vm / rm.x;
            v += step * rm.yzw;
        } else {
            x += step * v;
        }
    }
    addFixed(tallies + 0, absorbed, unitsPerWatt.xyz);
    addFixed(tallies + 3, reflected, unitsPerWatt.xyz);
    if (alive) atom_inc(tallies + 6);
    ray.position = (float4)(x, alive ? 1.0f : 0.0f);
    ray.velocity = (float4)(v, entered ? 1.0f : 0.0f);
    ray.power = (float4)(power, 0.0f);
    rays[get_global_id(0)] = ray;
}

// Moves the fixed-point deposits into the lattice's source (the transfer T of
// thesis fig. 4.1), as watts, and clears them for the next marching step.
kernel void transfer(global ulong* deposit, global float4* source, float4 wattsPerUnit) {
    size_t at = get_global_id(0);
    ulong r = deposit[3 * at], g = deposit[3 * at + 1], b = deposit[3 * at + 2];
    if ((r | g | b) == 0) return;
    source[at] += (float4)(convert_float(r) * wattsPerUnit.x, convert_float(g) * wattsPerUnit.y,
                           convert_float(b) * wattsPerUnit.z, 0.0f);
    deposit[3 * at] = deposit[3 * at + 1] = deposit[3 * at + 2] = 0;
}

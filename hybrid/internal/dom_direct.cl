// The direct component of the modified discrete ordinates method (thesis 5.2),
// gathered instead of scattered: each voxel marches to the light, so no two
// work items write one voxel and nothing needs sorting or atomics.

// Transmittance from p along the unit direction w over reach (clipped to the
// box), through the scaled and the true extinction; 0 where an opaque voxel stops it.
void march(global const float4* scaledExtinction, global const float4* trueExtinction, global const int* opaque,
           float3 p, float3 w, float reach, float4 origin, float voxel, int4 dims, float4* scaled, float4* unscaled) {
    const float3 lo = origin.xyz, hi = origin.xyz + voxel * (float3)(dims.x, dims.y, dims.z);
    float exitT = INFINITY;
    for (int a = 0; a < 3; ++a) {
        const float d = a == 0 ? w.x : a == 1 ? w.y : w.z;
        const float q = a == 0 ? p.x : a == 1 ? p.y : p.z;
        const float l = a == 0 ? lo.x : a == 1 ? lo.y : lo.z, h = a == 0 ? hi.x : a == 1 ? hi.y : hi.z;
        if (d > 0.0f) exitT = fmin(exitT, (h - q) / d);
        if (d < 0.0f) exitT = fmin(exitT, (l - q) / d);
    }
    reach = fmin(reach, exitT);
    const int steps = max(1, (int)ceil(reach / (0.5f * voxel)));
    const float dt = reach / steps;
    float4 tauScaled = (float4)(0.0f), tauTrue = (float4)(0.0f);
    *scaled = *unscaled = (float4)(0.0f);
    for (int s = 0; s < steps; ++s) {
        const float3 q = (p + ((float)s + 0.5f) * dt * w - origin.xyz) / voxel;
        const int qi = clamp((int)floor(q.x), 0, dims.x - 1), qj = clamp((int)floor(q.y), 0, dims.y - 1),
                  qk = clamp((int)floor(q.z), 0, dims.z - 1);
        const int at = qi + dims.x * (qj + dims.y * qk);
        if (opaque[at]) return;
        tauScaled += scaledExtinction[at] * dt;
        tauTrue += trueExtinction[at] * dt;
    }
    *scaled = exp(-tauScaled);
    *unscaled = exp(-tauTrue);
}

// A sphere light's cone on this many directions (uniform in solid angle, core/sphere_light.h).
#define SPHERE_DIRECTIONS 8

// The radiance a voxel receives straight from a light, through the scaled
// extinction sigma_t* (what the solver's first source scatters) and through the
// true extinction (what single scattering, drawn by the runtime, already
// shows): per voxel with medium, marched to the light in half-voxel steps. A
// sphere light (power.w its radius) is marched to along directions over its
// cone, the transmittances averaged: its soft shadows.
kernel void dom_uncollided(global const float4* scaledExtinction, global const float4* trueExtinction,
                           global const int* opaque, global float4* scaledOut, global float4* trueOut,
                           float4 light,   // xyz: position (w = 1) or travel direction (w = 0)
                           float4 power,   // W/sr (point) or W/m^2 (directional); w: a sphere light's radius
                           float4 spot,    // a spot's cone (core/scene.h, spotCoefficients); else (0, 0, 0, 1)
                           float4 origin, float voxel, int4 dims) {
    const int v = get_global_id(0);
    const int i = v % dims.x, j = (v / dims.x) % dims.y, k = v / (dims.x * dims.y);
    const float4 here = trueExtinction[v];
    scaledOut[v] = trueOut[v] = (float4)(0.0f);
    if (here.x <= 0.0f && here.y <= 0.0f && here.z <= 0.0f) return;
    const float3 p = origin.xyz + voxel * (float3)(i + 0.5f, j + 0.5f, k + 0.5f);
    float3 toLight = light.w > 0.5f ? light.xyz - p : -light.xyz;
    float distance = length(toLight);
    if (!(distance > 0.0f)) return;
    toLight /= distance;
    const float4 intensity = (float4)(power.xyz, 0.0f);
    const float radius = light.w > 0.5f ? power.w : 0.0f;
    float4 scaled, unscaled;
    if (radius > 0.0f) {
        const float s2 = radius * radius / (distance * distance);
        if (s2 >= 1.0f) return;  // inside the light: it sends nothing there
        const float root = sqrt(1.0f - s2), oneMinusCos = s2 / (1.0f + root);
        const float3 a = normalize(fabs(toLight.x) > 0.5f ? cross(toLight, (float3)(0.0f, 1.0f, 0.0f))
                                                          : cross(toLight, (float3)(1.0f, 0.0f, 0.0f)));
        const float3 b = cross(toLight, a);
        float4 sumScaled = (float4)(0.0f), sumTrue = (float4)(0.0f);
        for (int n = 0; n < SPHERE_DIRECTIONS; ++n) {
            const float cosT = 1.0f - ((float)n + 0.5f) / SPHERE_DIRECTIONS * oneMinusCos;
            const float sinT = sqrt(fmax(0.0f, 1.0f - cosT * cosT)), phi = 2.39996323f * (float)n;  // golden angle
            const float3 w = cosT * toLight + sinT * (cos(phi) * a + sin(phi) * b);
            // Up to the sphere's near side.
            const float along = dot(distance * toLight, w);
            const float miss2 = fmax(0.0f, distance * distance - along * along);
            const float reach = along - sqrt(fmax(0.0f, radius * radius - miss2));
            march(scaledExtinction, trueExtinction, opaque, p, w, reach, origin, voxel, dims, &scaled, &unscaled);
            sumScaled += scaled;
            sumTrue += unscaled;
        }
        const float factor = 2.0f / (distance * distance * (1.0f + root)) / SPHERE_DIRECTIONS;
        scaledOut[v] = intensity * factor * sumScaled;
        trueOut[v] = intensity * factor * sumTrue;
        return;
    }
    march(scaledExtinction, trueExtinction, opaque, p, toLight, light.w > 0.5f ? distance : INFINITY, origin, voxel,
          dims, &scaled, &unscaled);
    const float ramp = clamp(dot(spot.xyz, -toLight) + spot.w, 0.0f, 1.0f);
    const float falloff = light.w > 0.5f ? ramp * ramp / (distance * distance) : 1.0f;
    scaledOut[v] = intensity * falloff * scaled;
    trueOut[v] = intensity * falloff * unscaled;
}

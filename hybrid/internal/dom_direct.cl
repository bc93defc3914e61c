// The direct component of the modified discrete ordinates method (thesis 5.2),
// gathered instead of scattered: each voxel marches to the light, so no two
// work items write one voxel and nothing needs sorting or atomics.

// The radiance a voxel receives straight from a light, through the scaled
// extinction sigma_t* (what the solver's first source scatters) and through the
// true extinction (what single scattering, drawn by the runtime, already
// shows): per voxel with medium, marched to the light in half-voxel steps.
kernel void dom_uncollided(global const float4* scaledExtinction, global const float4* trueExtinction,
                           global const int* opaque, global float4* scaledOut, global float4* trueOut,
                           float4 light,   // xyz: position (w = 1) or travel direction (w = 0)
                           float4 power,   // W/sr (point) or W/m^2 (directional)
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
    // Up to the box's exit or the light, whichever is nearer.
    const float3 lo = origin.xyz, hi = origin.xyz + voxel * (float3)(dims.x, dims.y, dims.z);
    float exitT = INFINITY;
    for (int a = 0; a < 3; ++a) {
        const float d = a == 0 ? toLight.x : a == 1 ? toLight.y : toLight.z;
        const float q = a == 0 ? p.x : a == 1 ? p.y : p.z;
        const float l = a == 0 ? lo.x : a == 1 ? lo.y : lo.z, h = a == 0 ? hi.x : a == 1 ? hi.y : hi.z;
        if (d > 0.0f) exitT = fmin(exitT, (h - q) / d);
        if (d < 0.0f) exitT = fmin(exitT, (l - q) / d);
    }
    const float reach = light.w > 0.5f ? fmin(distance, exitT) : exitT;
    const int steps = max(1, (int)ceil(reach / (0.5f * voxel)));
    const float dt = reach / steps;
    float4 tauScaled = (float4)(0.0f), tauTrue = (float4)(0.0f);
    for (int s = 0; s < steps; ++s) {
        const float3 q = (p + ((float)s + 0.5f) * dt * toLight - origin.xyz) / voxel;
        const int qi = clamp((int)floor(q.x), 0, dims.x - 1), qj = clamp((int)floor(q.y), 0, dims.y - 1),
                  qk = clamp((int)floor(q.z), 0, dims.z - 1);
        const int at = qi + dims.x * (qj + dims.y * qk);
        if (opaque[at]) return;
        tauScaled += scaledExtinction[at] * dt;
        tauTrue += trueExtinction[at] * dt;
    }
    const float ramp = clamp(dot(spot.xyz, -toLight) + spot.w, 0.0f, 1.0f);
    const float falloff = light.w > 0.5f ? ramp * ramp / (distance * distance) : 1.0f;
    scaledOut[v] = power * falloff * exp(-tauScaled);
    trueOut[v] = power * falloff * exp(-tauTrue);
}

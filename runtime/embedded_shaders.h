#pragma once
// GLSL sources from shaders/, embedded at build time (cmake/EmbedShaders.cmake).
namespace lucent::shaders {
extern const char* const mesh_vert;
extern const char* const surface_frag;
extern const char* const depth_only_frag;
extern const char* const scatter_vert;
extern const char* const scatter_geom;
extern const char* const scatter_frag;
extern const char* const fullscreen_vert;
extern const char* const copy_depth_frag;
extern const char* const tonemap_frag;
extern const char* const segment_frag;
extern const char* const sample_light_glsl;
extern const char* const received_comp;
extern const char* const blocker_distance_frag;
extern const char* const skin_frag;
}  // namespace lucent::shaders

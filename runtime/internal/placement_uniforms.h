#pragma once
// Where an object stands (core/similarity.h), as its programs read it. The GPU
// keeps each object's mesh and samples in the object's own space and places them
// per draw, so a host may move an object every frame without uploading anything.
// - Mesh programs (mesh.vert): `model` (mat4) and `modelRotation` (mat3, for normals).
// - Sample programs (sample_light.glsl): `modelRotation`, `modelTranslation` and
//   `modelScale`, and `preprocessedScale`, the scale the samples were made at
//   (SampleParameters::placementScale); scatter.frag also takes the camera in object space
//   (`objectCamera`) and the view-to-object map of directions (`viewToObject`),
//   for the density slabs, which are the object's.
#include "core/similarity.h"
#include "runtime/internal/gl_program.h"

namespace lucent {

void setMeshPlacement(const GlProgram& program, const Similarity& placement);
void setSamplePlacement(const GlProgram& program, const Similarity& placement, float preprocessedScale);

}  // namespace lucent

#pragma once
// A triangle mesh on the GPU (positions and shading normals, core/triangle_mesh.h) that the passes draw:
// an object's boundary or one of its blockers.
#include "core/triangle_mesh.h"
#include "runtime/internal/gl.h"

namespace lucent {

class GpuMesh {
public:
    explicit GpuMesh(const TriangleMesh& mesh);
    ~GpuMesh();
    GpuMesh(const GpuMesh&) = delete;
    GpuMesh& operator=(const GpuMesh&) = delete;
    void draw() const;

private:
    GLuint vao_ = 0, buffers_[2] = {0, 0};
    GLsizei indexCount_ = 0;
};

}  // namespace lucent

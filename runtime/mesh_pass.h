#pragma once
// A translucent object's boundary on the GPU (positions and smooth normals) and
// the passes that draw it: front depth, farthest back depth, Phong surface.
#include "core/triangle_mesh.h"
#include "runtime/gl.h"

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

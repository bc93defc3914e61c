#include "runtime/internal/gpu_mesh.h"

#include <vector>

namespace lucent {

GpuMesh::GpuMesh(const TriangleMesh& mesh) {
    // Three vertices per face, each with its corner's shading normal
    // (core/triangle_mesh.h: smooth within the crease angle, sharp across it).
    const std::vector<std::array<Vec3, 3>> normals = cornerNormals(mesh);
    std::vector<glm::vec3> vertices;
    vertices.reserve(mesh.triangles.size() * 6);
    for (size_t f = 0; f < mesh.triangles.size(); ++f)
        for (int c = 0; c < 3; ++c) {
            vertices.emplace_back(mesh.positions[mesh.triangles[f][c]]);
            vertices.emplace_back(normals[f][c]);
        }
    glCreateVertexArrays(1, &vao_);
    glCreateBuffers(1, &buffer_);
    glNamedBufferStorage(buffer_, GLsizeiptr(vertices.size() * sizeof(glm::vec3)), vertices.data(), 0);
    glVertexArrayVertexBuffer(vao_, 0, buffer_, 0, 2 * sizeof(glm::vec3));
    for (GLuint attribute : {0u, 1u}) {
        glEnableVertexArrayAttrib(vao_, attribute);
        glVertexArrayAttribFormat(vao_, attribute, 3, GL_FLOAT, GL_FALSE, attribute * sizeof(glm::vec3));
        glVertexArrayAttribBinding(vao_, attribute, 0);
    }
    vertexCount_ = GLsizei(mesh.triangles.size() * 3);
}

GpuMesh::~GpuMesh() {
    glDeleteBuffers(1, &buffer_);
    glDeleteVertexArrays(1, &vao_);
}

void GpuMesh::draw() const {
    glBindVertexArray(vao_);
    glDrawArrays(GL_TRIANGLES, 0, vertexCount_);
}

}  // namespace lucent

#include "runtime/internal/gpu_mesh.h"

#include <vector>

namespace lucent {

GpuMesh::GpuMesh(const TriangleMesh& mesh) {
    // Smooth normals: area-weighted average of the faces around each vertex.
    std::vector<glm::vec3> vertices(mesh.positions.size() * 2, glm::vec3(0.0f));
    for (size_t f = 0; f < mesh.triangles.size(); ++f) {
        const glm::vec3 n(mesh.faceNormal(f));
        for (uint32_t v : mesh.triangles[f]) vertices[2 * v + 1] += n;
    }
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
        vertices[2 * v] = glm::vec3(mesh.positions[v]);
        const float length = glm::length(vertices[2 * v + 1]);
        vertices[2 * v + 1] = length > 0.0f ? vertices[2 * v + 1] / length : glm::vec3(0, 0, 1);
    }
    glCreateVertexArrays(1, &vao_);
    glCreateBuffers(2, buffers_);
    glNamedBufferStorage(buffers_[0], GLsizeiptr(vertices.size() * sizeof(glm::vec3)), vertices.data(), 0);
    glNamedBufferStorage(buffers_[1], GLsizeiptr(mesh.triangles.size() * sizeof(mesh.triangles[0])), mesh.triangles.data(), 0);
    glVertexArrayVertexBuffer(vao_, 0, buffers_[0], 0, 2 * sizeof(glm::vec3));
    glVertexArrayElementBuffer(vao_, buffers_[1]);
    for (GLuint attribute : {0u, 1u}) {
        glEnableVertexArrayAttrib(vao_, attribute);
        glVertexArrayAttribFormat(vao_, attribute, 3, GL_FLOAT, GL_FALSE, attribute * sizeof(glm::vec3));
        glVertexArrayAttribBinding(vao_, attribute, 0);
    }
    indexCount_ = GLsizei(mesh.triangles.size() * 3);
}

GpuMesh::~GpuMesh() {
    glDeleteBuffers(2, buffers_);
    glDeleteVertexArrays(1, &vao_);
}

void GpuMesh::draw() const {
    glBindVertexArray(vao_);
    glDrawElements(GL_TRIANGLES, indexCount_, GL_UNSIGNED_INT, nullptr);
}

}  // namespace lucent

#include "runtime/internal/gpu_mesh.h"

#include <vector>

namespace lucent {

GpuMesh::GpuMesh(const TriangleMesh& mesh) {
    // Each corner's shading normal (core/triangle_mesh.h: smooth within the
    // crease angle, sharp across it). A vertex is split only where its corners'
    // normals differ, so smooth meshes keep one vertex each and the vertex
    // cache its reuse.
    const std::vector<std::array<Vec3, 3>> normals = cornerNormals(mesh);
    std::vector<glm::vec3> vertices;  // position, normal
    std::vector<std::vector<std::pair<glm::vec3, uint32_t>>> copies(mesh.positions.size());
    std::vector<uint32_t> indices;
    indices.reserve(mesh.triangles.size() * 3);
    for (size_t f = 0; f < mesh.triangles.size(); ++f)
        for (int c = 0; c < 3; ++c) {
            const uint32_t v = mesh.triangles[f][c];
            const glm::vec3 n(normals[f][c]);
            uint32_t index = ~0u;
            for (const auto& [normal, i] : copies[v])
                if (normal == n) index = i;
            if (index == ~0u) {
                index = uint32_t(vertices.size() / 2);
                vertices.emplace_back(mesh.positions[v]);
                vertices.push_back(n);
                copies[v].emplace_back(n, index);
            }
            indices.push_back(index);
        }
    glCreateVertexArrays(1, &vao_);
    glCreateBuffers(2, buffers_);
    glNamedBufferStorage(buffers_[0], GLsizeiptr(vertices.size() * sizeof(glm::vec3)), vertices.data(), 0);
    glNamedBufferStorage(buffers_[1], GLsizeiptr(indices.size() * sizeof(uint32_t)), indices.data(), 0);
    glVertexArrayVertexBuffer(vao_, 0, buffers_[0], 0, 2 * sizeof(glm::vec3));
    glVertexArrayElementBuffer(vao_, buffers_[1]);
    for (GLuint attribute : {0u, 1u}) {
        glEnableVertexArrayAttrib(vao_, attribute);
        glVertexArrayAttribFormat(vao_, attribute, 3, GL_FLOAT, GL_FALSE, attribute * sizeof(glm::vec3));
        glVertexArrayAttribBinding(vao_, attribute, 0);
    }
    indexCount_ = GLsizei(indices.size());
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

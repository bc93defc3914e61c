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
    vertices.reserve(2 * mesh.positions.size());
    // The copies of each mesh vertex as a list through the vertices made: its
    // latest copy, and each copy's previous one (no allocation per vertex).
    constexpr uint32_t kNone = ~0u;
    std::vector<uint32_t> latest(mesh.positions.size(), kNone), previous;
    previous.reserve(mesh.positions.size());
    std::vector<uint32_t> indices;
    indices.reserve(mesh.triangles.size() * 3);
    for (size_t f = 0; f < mesh.triangles.size(); ++f)
        for (int c = 0; c < 3; ++c) {
            const uint32_t v = mesh.triangles[f][c];
            const glm::vec3 n(normals[f][c]);
            uint32_t index = latest[v];
            while (index != kNone && vertices[2 * size_t(index) + 1] != n) index = previous[index];
            if (index == kNone) {
                index = uint32_t(previous.size());
                vertices.emplace_back(mesh.positions[v]);
                vertices.push_back(n);
                previous.push_back(latest[v]);
                latest[v] = index;
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

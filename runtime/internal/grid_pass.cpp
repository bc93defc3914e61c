#include "runtime/internal/grid_pass.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>

#include "core/error.h"
#include "runtime/internal/frame_targets.h"
#include "runtime/internal/gpu_layout.h"

namespace lucent {

namespace {

GLuint texture3d(const ScatteringGrid& grid, const std::vector<float>& values, bool rgba = false) {
    GLuint t = 0;
    glCreateTextures(GL_TEXTURE_3D, 1, &t);
    glTextureStorage3D(t, 1, rgba ? GL_RGBA32F : GL_RGB32F, grid.dims[0], grid.dims[1], grid.dims[2]);
    glTextureSubImage3D(t, 0, 0, 0, 0, grid.dims[0], grid.dims[1], grid.dims[2], rgba ? GL_RGBA : GL_RGB, GL_FLOAT,
                        values.data());
    glTextureParameteri(t, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(t, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
        glTextureParameteri(t, wrap, GL_CLAMP_TO_EDGE);
    return t;
}

}  // namespace

GridPass::~GridPass() { clear(); }

void GridPass::clear() {
    for (GpuGrid& g : grids_) {
        glDeleteTextures(1, &g.source);
        glDeleteTextures(1, &g.extinction);
        if (g.refraction) glDeleteTextures(1, &g.refraction);
    }
    grids_.clear();
}

void GridPass::add(const ScatteringGrid& grid) {
    const size_t n = grid.voxelCount();
    if (n == 0 || grid.source.size() != 3 * n || grid.extinction.size() != 3 * n ||
        (!grid.refraction.empty() && grid.refraction.size() != 4 * n))
        throw Error("scattering grid: " + std::to_string(grid.source.size()) + " source, " +
                    std::to_string(grid.extinction.size()) + " extinction and " +
                    std::to_string(grid.refraction.size()) + " refraction values for " + std::to_string(n) + " voxels");
    GLint largest = 0;
    glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &largest);
    if (*std::max_element(grid.dims.begin(), grid.dims.end()) > largest)
        throw Error("scattering grid of " + std::to_string(grid.dims[0]) + "x" + std::to_string(grid.dims[1]) + "x" +
                    std::to_string(grid.dims[2]) + " voxels exceeds OpenGL's 3D texture limit of " +
                    std::to_string(largest));
    GpuGrid g;
    g.source = texture3d(grid, grid.source);
    g.extinction = texture3d(grid, grid.extinction);
    if (!grid.refraction.empty()) g.refraction = texture3d(grid, grid.refraction, true);
    g.ior = float(grid.ior);
    g.bounds = grid.bounds;
    g.voxel = float(grid.bounds.extent().x / grid.dims[0]);
    grids_.push_back(g);
}

void GridPass::draw(FrameContext& frame) {
    if (!frame.options.scattering || grids_.empty()) return;
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glDepthMask(GL_FALSE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    const GlProgram& program = program_.get();
    glUseProgram(program.id());
    const glm::mat4 inverseViewProjection = glm::inverse(frame.viewProjection);
    glUniformMatrix4fv(program.uniform("inverseViewProjection"), 1, GL_FALSE, glm::value_ptr(inverseViewProjection));
    glUniform3fv(program.uniform("cameraPosition"), 1, glm::value_ptr(frame.view.cameraPosition));
    glUniform2f(program.uniform("viewportSize"), float(frame.view.width), float(frame.view.height));
    glUniform1i(program.uniform("raySegments"), GLint(gpu::kUnitRaySegments));
    glUniform1i(program.uniform("source"), GLint(gpu::kUnitGridSource));
    glUniform1i(program.uniform("extinction"), GLint(gpu::kUnitGridExtinction));
    glUniform1i(program.uniform("refraction"), GLint(gpu::kUnitGridRefraction));
    glBindTextureUnit(gpu::kUnitRaySegments, frame.targets.raySegments());
    glBindVertexArray(frame.targets.emptyVertexArray());
    for (const GpuGrid& g : grids_) {
        glBindTextureUnit(gpu::kUnitGridSource, g.source);
        glBindTextureUnit(gpu::kUnitGridExtinction, g.extinction);
        glBindTextureUnit(gpu::kUnitGridRefraction, g.refraction);
        glUniform1i(program.uniform("refracting"), g.refraction != 0);
        glUniform1f(program.uniform("ior"), g.ior);
        glUniform3fv(program.uniform("boundsMin"), 1, glm::value_ptr(glm::vec3(g.bounds.min)));
        glUniform3fv(program.uniform("boundsMax"), 1, glm::value_ptr(glm::vec3(g.bounds.max)));
        glUniform1f(program.uniform("voxel"), g.voxel);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
}

}  // namespace lucent

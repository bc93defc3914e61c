#pragma once
// The targets every pass of a frame reads (thesis 3.4.1): the host's depth with
// the opaque blockers drawn in, the nearest front face and the farthest back face
// of the translucent meshes with the next entries and exits peeled behind them,
// each pixel's ray segment [t0, t1] inside them and its first two intervals inside.
#include <memory>

#include "runtime/internal/gl.h"
#include "runtime/internal/gl_program.h"
#include "runtime/internal/gpu_layout.h"
#include "runtime/internal/render_pass.h"

namespace lucent {

// A framebuffer with one texture the passes sample: a depth texture
// (GL_DEPTH_COMPONENT32F) or a colour one (the RG32F ray segments, the RGBA32F
// intervals inside the objects).
class TextureTarget {
public:
    explicit TextureTarget(GLenum textureFormat) : format_(textureFormat) {}
    ~TextureTarget() { release(); }
    TextureTarget(const TextureTarget&) = delete;
    TextureTarget& operator=(const TextureTarget&) = delete;
    void resize(int width, int height);
    void clearDepth(float depth) const { glClearNamedFramebufferfv(framebuffer_, GL_DEPTH, 0, &depth); }
    GLuint framebuffer() const { return framebuffer_; }
    GLuint texture() const { return texture_; }

private:
    bool isDepth() const { return format_ == GL_DEPTH_COMPONENT32F; }
    void release();
    GLenum format_;
    GLuint framebuffer_ = 0, texture_ = 0;
    int width_ = 0, height_ = 0;
};

class FrameTargets {
public:
    FrameTargets();
    ~FrameTargets();
    FrameTargets(const FrameTargets&) = delete;
    FrameTargets& operator=(const FrameTargets&) = delete;

    // Which depth layers a frame's targets hold, and how they are drawn.
    enum class Layers {
        // The scattering is drawn elsewhere, and only the surface (frontDepth)
        // and the upsampling's likeness (the first interval of insideSegments)
        // read these targets: the later intervals, raySegments and reachDepth
        // are left out, and so are their mesh passes.
        FirstInterval,
        // Every layer as a depth texture, peeled (peel.frag): a mesh pass each.
        Peeled,
        // Every layer in one mesh pass (depth_layers.frag): frontDepth is not drawn.
        OnePass,
    };
    // Draws the targets for this frame as seen through view (frame.view, or the
    // reduced one the scattering runs at: the host's depth is then read at each
    // pixel's centre); leaves depth testing on with GL_LESS, back faces culled
    // and the last target bound.
    void draw(const FrameContext& frame, const ViewSetup& view, Layers layers);
    // Draws every object's boundary mesh with program (mesh.vert), each where it stands.
    static void drawMeshes(const FrameContext& frame, const GlProgram& program);

    GLuint frontDepth() const { return frontLayers_[0].texture(); }  // not with Layers::OnePass
    GLuint raySegments() const { return segments_.texture(); }
    // RGBA32F: the first two intervals each pixel's ray spends inside the objects (segment.frag).
    GLuint insideSegments() const { return inside_.texture(); }
    // DEPTH_COMPONENT32F: the window depth of the farthest point the intervals
    // inside reach, 0 where the ray has none (segment.frag).
    GLuint reachDepth() const { return reach_.texture(); }
    GLuint emptyVertexArray() const { return emptyVao_; }
    // Whether the camera of the last draw stands inside an object (then it sees back faces).
    bool cameraInside() const { return cameraInside_; }

private:
    GlProgram depthProgram_{{GL_VERTEX_SHADER, "mesh.vert"}, {GL_FRAGMENT_SHADER, "depth_only.frag"}};
    // Linked on first use (GlProgramVariants): only with a host's depth texture;
    // only for Layers::Peeled; only for Layers::OnePass. A frame's full and
    // reduced targets each use one of the last two.
    GlProgramVariants copyDepthProgram_{
        {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "copy_depth.frag"}}};
    GlProgramVariants peelProgram_{{{GL_VERTEX_SHADER, "mesh.vert"}, {GL_FRAGMENT_SHADER, "peel.frag"}}};
    GlProgramVariants layersProgram_{{{GL_VERTEX_SHADER, "mesh.vert"}, {GL_FRAGMENT_SHADER, "depth_layers.frag"}}};
    // segment.frag, and its FIRST_INTERVAL_ONLY and ONE_PASS_LAYERS variants.
    GlProgramVariants segmentPrograms_{{{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "segment.frag"}}};
    void drawPeeled(const FrameContext& frame, bool firstIntervalOnly);
    void drawInOnePass(const FrameContext& frame, const ViewSetup& view);
    // The entries (front faces) and exits (back faces) nearest first, peeled.
    TextureTarget frontLayers_[gpu::kMaxRaySegments] = {TextureTarget(GL_DEPTH_COMPONENT32F),
                                                        TextureTarget(GL_DEPTH_COMPONENT32F)};
    TextureTarget backLayers_[gpu::kMaxRaySegments] = {TextureTarget(GL_DEPTH_COMPONENT32F),
                                                       TextureTarget(GL_DEPTH_COMPONENT32F)};
    TextureTarget back_{GL_DEPTH_COMPONENT32F}, host_{GL_DEPTH_COMPONENT32F};
    TextureTarget segments_{GL_RG32F};
    TextureTarget inside_{GL_RGBA32F};
    TextureTarget reach_{GL_DEPTH_COMPONENT32F};
    // Layers::OnePass: the R32UI array depth_layers.frag keeps its layers in, and
    // a framebuffer without attachments of its size to rasterize the meshes into.
    GLuint layerArray_ = 0, layerFramebuffer_ = 0;
    int layerWidth_ = 0, layerHeight_ = 0;
    GLuint emptyVao_ = 0;
    bool cameraInside_ = false;
};

}  // namespace lucent

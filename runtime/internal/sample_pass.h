#pragma once
// Pass 2 of thesis 3.4.2: every sample's Gaussian, expanded in a geometry shader
// and integrated exactly along each pixel's ray segment (scatter.vert, .geom,
// .frag), summed. Isotropic media reuse the light each sample receives while the
// lights and the medium scale stay put (received.comp); every medium reuses the
// environment's light projected onto SH (environment_sh.comp). The sum goes to the
// pass's own target first, whose depth is each pixel's reach inside the objects
// (proxies beyond it are rejected before shading), and is then added to the
// host's framebuffer (add_light.frag), or upsampled along the objects' depth
// when the scattering is reduced (upsample.frag).
#include <future>
#include <memory>
#include <utility>
#include <vector>

#include "runtime/internal/frame_targets.h"
#include "runtime/internal/gl_program.h"
#include "runtime/internal/render_pass.h"

namespace lucent {

class SamplePass final : public RenderPass {
public:
    // cutoff: a Gaussian is drawn where it exceeds this fraction of its peak.
    explicit SamplePass(double cutoff);
    void prepare(FrameContext& frame) override;  // the blocker shadow maps, when the lights changed
    void draw(FrameContext& frame) override;

private:
    void setFrameUniforms(const GlProgram& program, const FrameContext& frame) const;
    static void setSampleUnits(const GlProgram& program);  // SH normalisation and texture units
    // Whether object o's samples take their light traced this frame (DrawOptions::tracedLight).
    static bool traced(const GpuObject& o, const FrameContext& frame);
    // Whether object o is drawn through its refracting boundary this frame: its
    // medium's ior is not 1, its light is traced (through the boundary,
    // REFRACTED_LIGHT) and its fragments attenuate from the front face, here
    // where the refracted ray enters (REFRACTED_VIEW). Otherwise the boundary
    // is drawn as index-matched (SsMethod::limitations says so).
    static bool refracted(const GpuObject& o, const FrameContext& frame);
    void updateReceived(GpuObject& object, const FrameContext& frame) const;
    // Whether object o's samples read the environment's SH this frame, and their projection (environment_sh.comp).
    static bool environmentSh(const GpuObject& o, const FrameContext& frame);
    void updateEnvironment(GpuObject& object, const FrameContext& frame) const;
    // Traces the light of the objects whose light is traced and no longer current,
    // and the view through refracting boundaries, on other threads.
    void startTraces(FrameContext& frame);
    void upsample(const FrameContext& frame) const;
    void addLight(const FrameContext& frame) const;
    // Every object's proxies into the bound target (points: POINT_PROXIES);
    // countUseful: the variant that discards fragments below DrawOptions::discardBelow.
    void drawProxies(FrameContext& frame, bool points, bool countUseful);
    void countFragments(FrameContext& frame, bool points);  // DrawOptions::fragments
    double cutoffSigmas_;
    // A Gaussian seen on screen is a 2D Gaussian; the square around its cut-off
    // circle (radius r = cutoffSigmas s) keeps erf(r / (s sqrt 2))^2 of its mass
    // (1 - cutoff in the circle, and the corners): the kept part is scaled to the whole.
    double keptMassInverse_;
    float largestPoint_ = 0.0f;  // GL_POINT_SIZE_RANGE's upper end, asked on the first draw
    // The traced depths prepare() started, set on their samples when draw() begins.
    std::vector<std::pair<GpuSamples*, std::future<std::vector<glm::vec4>>>> pendingTraces_;
    // The refracted view rays prepare() started, uploaded when draw() begins.
    struct PendingView {
        GpuObject* object;
        std::future<std::vector<RefractedStretch>> rays;
    };
    std::vector<PendingView> pendingViews_;
    // The scattering program's variants: the defines that shape scatter.vert,
    // scatter.geom, scatter.frag and sample_light.glsl (GlProgramVariants).
    struct ScatterVariant {
        bool slabs = false;           // constant-density slabs (DENSITY_SLABS)
        bool regions = false;         // samples clipped to their regions (SAMPLE_REGIONS)
        bool viewFromFront = false;   // attenuated from each pixel's front face (VIEW_FROM_FRONT)
        bool countUseful = false;     // the render benchmark's diagnostic (COUNT_USEFUL_FRAGMENTS)
        bool receivedCached = false;  // isotropic: the received light from received.comp (RECEIVED_CACHED)
        bool oneChannel = false;      // grey sigma_t: one integral for three channels (ONE_CHANNEL)
        bool tracedLight = false;     // traced(): the light from the traced depths, not the SH (TRACED_LIGHT)
        bool pointProxies = false;    // pointProxiesCover(): a point sprite per proxy (POINT_PROXIES)
        bool refracted = false;       // refracted(): REFRACTED_LIGHT and REFRACTED_VIEW
        bool environmentSh = false;   // environmentSh(): the environment's SH (ENVIRONMENT_SH)
    };
    // Whether kPointProxyTiles^2 points of the largest size cover a target of
    // this size (scatter.geom, POINT_PROXIES); otherwise squares of two triangles.
    bool pointProxiesCover(int width, int height) const;
    const GlProgram& scatterProgram(const ScatterVariant& variant) const;
    GlProgramVariants scatterPrograms_{{{GL_VERTEX_SHADER, "scatter.vert"},
                                        {GL_GEOMETRY_SHADER, "scatter.geom"},
                                        {GL_FRAGMENT_SHADER, "scatter.frag"}},
                                       setSampleUnits};
    // The received light for isotropic media, traced or from the SH (TRACED_LIGHT),
    // through a refracting boundary (REFRACTED_LIGHT), with the environment's SH (ENVIRONMENT_SH).
    const GlProgram& receivedProgram(bool tracedLight, bool refracted, bool environment) const;
    GlProgramVariants receivedPrograms_{{{GL_COMPUTE_SHADER, "received.comp"}}, setSampleUnits};
    GlProgramVariants environmentPrograms_{{{GL_COMPUTE_SHADER, "environment_sh.comp"}}, setSampleUnits};
    GlProgram upsampleProgram_{{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "upsample.frag"}};
    GlProgram addProgram_{{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "add_light.frag"}};
    // The scattered light at the scattering's resolution, before upsampling or adding.
    TextureTarget light_{GL_RGBA32F};
};

}  // namespace lucent

#include "runtime/internal/refracted_view.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <utility>

#include "core/error.h"
#include "core/refraction.h"

namespace lucent {
namespace {

bool sameView(const ViewSetup& a, const ViewSetup& b) {
    return a.view == b.view && a.projection == b.projection && a.cameraPosition == b.cameraPosition &&
           a.width == b.width && a.height == b.height;
}

// The stretches of the camera ray from origin along dir, in the volume's own
// world (lengths in its units): refracted where it enters, then reflected back
// inside where it leaves, by Fresnel's share.
struct OwnStretch {
    Vec3 origin, direction;
    double weight = 0.0, length = 0.0;
};

std::array<OwnStretch, gpu::kRefractedStretches> stretchesOf(const VolumeObject& o, const Vec3& origin,
                                                             const Vec3& dir) {
    std::array<OwnStretch, gpu::kRefractedStretches> out{};
    const std::optional<BoundaryHit> hit = nextBoundaryHit(o, origin, dir);
    if (!hit || !hit->entering) return out;  // misses it, or the camera stands inside
    const double n = o.desc().medium.ior;
    const double cosine = -glm::dot(dir, hit->normal);
    OwnStretch s{hit->point, dir, 1.0, 0.0};
    // A shading normal turned away from the ray lets it through unbent (as the reference).
    if (cosine > 0.0) {
        s.direction = *refractedDirection(dir, hit->normal, 1.0 / n);  // entering never reflects totally
        s.weight = (1.0 - fresnelReflectance(cosine, 1.0 / n)) / (n * n);
    }
    for (OwnStretch& stretch : out) {
        const std::optional<BoundaryHit> exit = nextBoundaryHit(o, s.origin, s.direction);
        const double blocker = o.firstBlockerHit(s.origin, s.direction);
        s.length = std::min(exit ? exit->t : 0.0, blocker);
        if (!(s.length > 0.0) || !(s.weight > 0.0)) break;
        stretch = s;
        if (!exit || blocker < exit->t || exit->entering) break;  // a blocker ends the ray; a stray crossing too
        // Fresnel's share reflected back inside about the shading normal (all of it past the critical angle).
        const double inside = glm::dot(s.direction, exit->normal);
        const double reflected = inside > 0.0 ? fresnelReflectance(inside, n) : 0.0;
        s = OwnStretch{exit->point, reflectedDirection(s.direction, exit->normal), s.weight * reflected, 0.0};
    }
    return out;
}

}  // namespace

std::vector<RefractedStretch> refractedViewRays(const VolumeObject& volume, const Similarity& placement,
                                                const ViewSetup& view) {
    constexpr size_t K = gpu::kRefractedStretches;
    std::vector<RefractedStretch> rays(size_t(view.width) * size_t(view.height) * K, RefractedStretch{});
    const glm::dmat4 viewMatrix(view.view);
    const glm::dmat3 worldToView(viewMatrix);
    const glm::dmat3 viewToWorld = glm::transpose(worldToView);
    const glm::dmat4 P(view.projection);
    // View-space direction through pixel centre (x, y) at z = -1 (SamplePass's pixelToView).
    const glm::dvec4 pixelToView(2.0 / (view.width * P[0][0]), 2.0 / (view.height * P[1][1]), (P[2][0] - 1.0) / P[0][0],
                                 (P[2][1] - 1.0) / P[1][1]);
    const Similarity& own = volume.placement();
    const double toOwn = own.scale / placement.scale;  // the volume's lengths per world length
    const Vec3 origin = own.point(placement.inversePoint(Vec3(view.cameraPosition)));
    volume.boundary();  // built once here, not raced for by the rays
    tbb::parallel_for(tbb::blocked_range<int>(0, view.height, 8), [&](const tbb::blocked_range<int>& r) {
        for (int y = r.begin(); y != r.end(); ++y)
            for (int x = 0; x < view.width; ++x) {
                const Vec3 inView = glm::normalize(
                    Vec3((x + 0.5) * pixelToView.x + pixelToView.z, (y + 0.5) * pixelToView.y + pixelToView.w, -1.0));
                const Vec3 dir = own.direction(placement.inverseDirection(viewToWorld * inView));
                const auto stretches = stretchesOf(volume, origin, dir);
                for (size_t k = 0; k < K; ++k) {
                    const OwnStretch& s = stretches[k];
                    if (!(s.weight > 0.0)) break;
                    const Vec3 start = placement.point(own.inversePoint(s.origin));
                    const Vec3 direction = worldToView * placement.direction(own.inverseDirection(s.direction));
                    RefractedStretch& out = rays[(size_t(y) * size_t(view.width) + size_t(x)) * K + k];
                    out.origin = glm::vec4(glm::vec3(viewMatrix * glm::dvec4(start, 1.0)), float(s.weight));
                    out.direction = glm::vec4(glm::vec3(glm::normalize(direction)), float(s.length / toOwn));
                }
            }
    });
    return rays;
}

RefractedView::~RefractedView() {
    if (texture_) glDeleteTextures(1, &texture_);
}

RefractedView::RefractedView(RefractedView&& other) noexcept
    : stretches_(other.stretches_), traced_(other.traced_), placement_(other.placement_), volume_(other.volume_) {
    std::swap(texture_, other.texture_);
}

RefractedView& RefractedView::operator=(RefractedView&& other) noexcept {
    std::swap(texture_, other.texture_);
    std::swap(stretches_, other.stretches_);
    std::swap(traced_, other.traced_);
    std::swap(placement_, other.placement_);
    std::swap(volume_, other.volume_);
    return *this;
}

bool RefractedView::current(const VolumeObject& volume, const Similarity& placement, const ViewSetup& view) const {
    return texture_ && volume_ == &volume && placement_ == placement && sameView(traced_, view);
}

void RefractedView::upload(const std::vector<RefractedStretch>& rays, const VolumeObject& volume,
                           const Similarity& placement, const ViewSetup& view) {
    constexpr size_t K = gpu::kRefractedStretches;
    const size_t pixels = size_t(view.width) * size_t(view.height);
    if (rays.size() != pixels * K) throw Error("RefractedView: rays for another view");
    if (!texture_ || traced_.width != view.width || traced_.height != view.height) {
        if (texture_) glDeleteTextures(1, &texture_);
        glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &texture_);
        glTextureStorage3D(texture_, 1, GL_RGBA32F, view.width, view.height, GLsizei(2 * K));
        glTextureParameteri(texture_, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTextureParameteri(texture_, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    std::vector<glm::vec4> layer(pixels);
    stretches_ = 0;
    for (size_t k = 0; k < K; ++k)
        for (int half = 0; half < 2; ++half) {
            bool any = false;
            for (size_t i = 0; i < pixels; ++i) {
                const RefractedStretch& s = rays[i * K + k];
                layer[i] = half == 0 ? s.origin : s.direction;
                any = any || s.origin.w > 0.0f;
            }
            if (any) stretches_ = std::max(stretches_, int(k) + 1);
            glTextureSubImage3D(texture_, 0, 0, 0, GLint(2 * k) + half, view.width, view.height, 1, GL_RGBA, GL_FLOAT,
                                layer.data());
        }
    volume_ = &volume;
    placement_ = placement;
    traced_ = view;
}

void RefractedView::bind(GLuint unit) const { glBindTextureUnit(unit, texture_); }

}  // namespace lucent

#include "bump/height_map.h"

#include <cmath>

#include "bump/bump.h"
#include "core/instance.h"

namespace rb {

HeightImage::HeightImage(const TextureImage& image) : width_(image.width), height_(image.height) {
    heights_.reserve(static_cast<size_t>(width_) * static_cast<size_t>(height_));
    for (int y = 0; y < height_; ++y)
        for (int x = 0; x < width_; ++x) {
            const Colour t = image.texel(x, y);
            heights_.push_back(static_cast<float>(
                (linearToSrgb(t.r) + linearToSrgb(t.g) + linearToSrgb(t.b)) / 3.0));
        }
}

double HeightImage::texel(long long x, long long y) const {
    // Repeat: wrap into [0, width) and [0, height), also for negative indices.
    x %= width_;
    y %= height_;
    if (x < 0) x += width_;
    if (y < 0) y += height_;
    return heights_[static_cast<size_t>(y) * static_cast<size_t>(width_) + static_cast<size_t>(x)];
}

double HeightImage::at(const Vec2& st) const {
    // Texel (x, y) holds the value at its centre ((x + ½)/w, 1 − (y + ½)/h).
    const double fx = st.x * width_ - 0.5;
    const double fy = (1.0 - st.y) * height_ - 0.5;
    if (!std::isfinite(fx) || !std::isfinite(fy) || std::abs(fx) > 1e15 || std::abs(fy) > 1e15)
        return 0.0;  // no texel: a coordinate too large to index
    const double x0 = std::floor(fx), y0 = std::floor(fy);
    const double tx = fx - x0, ty = fy - y0;
    const auto ix = static_cast<long long>(x0), iy = static_cast<long long>(y0);
    const double top = (1 - tx) * texel(ix, iy) + tx * texel(ix + 1, iy);
    const double bottom = (1 - tx) * texel(ix, iy + 1) + tx * texel(ix + 1, iy + 1);
    return (1 - ty) * top + ty * bottom;
}

// [height-map-gradient]
Vec3 heightMapGradient(double h_u, double h_v, const Vec3& dpdu, const Vec3& dpdv, const Vec3& n) {
    const double D = glm::dot(n, glm::cross(dpdu, dpdv));
    if (!(std::abs(D) > 0.0) || !std::isfinite(D)) return Vec3(0.0);
    // The dual basis of (dp/du, dp/dv) in the tangent plane.
    const Vec3 gradU = glm::cross(dpdv, n) / D;
    const Vec3 gradV = glm::cross(n, dpdu) / D;
    return h_u * gradU + h_v * gradV;
}
// [height-map-gradient]

HeightMapBump::HeightMapBump(std::shared_ptr<const HeightImage> image, double strength,
                             double stepTexels, UVMapping mapping, const Vec2& scale)
    : image_(std::move(image)),
      strength_(strength),
      step_(stepTexels),
      mapping_(mapping),
      scale_(scale) {}

// [height-map-perturb]
void HeightMapBump::perturb(const Ray& ray, Hit& hit) const {
    if (strength_ == 0.0 || !hit.instance) return;  // a zero bump is no bump
    const Instance& instance = *hit.instance;
    // The texture coordinates st = scale · uv, and the surface's derivatives along them
    // (dp/ds = dp/du / scale.x), in object space.
    const SurfaceUV s = surfaceUV(hit, mapping_);
    const Mat3 toObject(instance.worldToObject);
    const Vec3 dpdu = toObject * s.dpdu / scale_.x, dpdv = toObject * s.dpdv / scale_.y;
    const Vec2 st = s.uv * scale_;
    const Vec3 n = glm::transpose(Mat3(instance.objectToWorld)) * hit.ns;
    const double length = glm::length(n);
    if (!(length > 0.0) || !std::isfinite(length)) return;
    // Central differences in texture space, `step` texels each way.
    const double du = step_ / image_->width(), dv = step_ / image_->height();
    const double h_u =
        (image_->at(st + Vec2(du, 0.0)) - image_->at(st - Vec2(du, 0.0))) / (2.0 * du);
    const double h_v =
        (image_->at(st + Vec2(0.0, dv)) - image_->at(st - Vec2(0.0, dv))) / (2.0 * dv);
    // The surface gradient, the bumped normal, and back to world space on the viewer's side.
    const Vec3 g = heightMapGradient(h_u, h_v, dpdu, dpdv, n / length);
    const Vec3 bumped = bumpedNormal(n / length, g, strength_);
    const Vec3 nWorld = glm::normalize(instance.normalToWorld * bumped);
    if (!isFinite(nWorld)) return;
    hit.ns = keepViewerSide(nWorld, hit.ns, -glm::normalize(ray.d));
}
// [height-map-perturb]

}  // namespace rb

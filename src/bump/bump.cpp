#include "bump/bump.h"

#include <cmath>

#include "core/instance.h"
#include "core/material.h"
#include "core/render_context.h"

namespace rb {

namespace {

/// v / |v|, or `fallback` when v is zero or not finite. Scaling by the largest component
/// first keeps |v|² from overflowing for huge v.
Vec3 unitOr(const Vec3& v, const Vec3& fallback) {
    const double m = maxAbsComponent(v);
    if (!(m > 0.0) || !std::isfinite(m)) return fallback;
    return glm::normalize(v / m);
}

}  // namespace

void tangentFrame(const Vec3& n, Vec3& t, Vec3& b) {
    const double sign = std::copysign(1.0, n.z);
    const double a = -1.0 / (sign + n.z);
    const double c = n.x * n.y * a;
    t = Vec3(1.0 + sign * n.x * n.x * a, sign * c, -sign * n.x);
    b = Vec3(c, sign + n.y * n.y * a, -n.y);
}

// [surface-gradient]
Vec3 surfaceGradient(const HeightField& field, const Vec3& x, const Vec3& n, double step) {
    Vec3 t, b;
    tangentFrame(n, t, b);
    // [exercise-surface-gradient]
    // Exercise 11.2, the numerical surface gradient: read ch11-gradient.
    // Blank: return Vec3(0.0);
    // Central differences along each tangent: the error falls as step², until rounding in
    // the two heights' difference takes over.
    const double dh_dt = (field.height(x + step * t) - field.height(x - step * t)) / (2.0 * step);
    const double dh_db = (field.height(x + step * b) - field.height(x - step * b)) / (2.0 * step);
    return dh_dt * t + dh_db * b;
    // [exercise-surface-gradient]
}
// [surface-gradient]

// [bumped-normal]
Vec3 bumpedNormal(const Vec3& n, const Vec3& g, double strength) {
    if (!isFinite(g)) return n;
    // [exercise-bumped-normal]
    // Exercise 11.1, the bumped normal: read ch11-equations.
    // Blank: return n;
    // n − strength · g, divided through by max(1, |strength|) so a huge strength cannot
    // overflow: the direction is the same, and tends to −g as the strength grows.
    const double scale = std::max(1.0, std::abs(strength));
    return unitOr(n / scale - (strength / scale) * g, n);
    // [exercise-bumped-normal]
}
// [bumped-normal]

// [keep-viewer-side]
Vec3 keepViewerSide(const Vec3& bumped, const Vec3& original, const Vec3& v) {
    // Orient both so that the unbumped normal faces the viewer.
    const double side = glm::dot(original, v) < 0.0 ? -1.0 : 1.0;
    Vec3 n = side * bumped;
    // [exercise-keep-viewer-side]
    // Exercise 11.3, keeping the bumped normal on the viewer's side: read ch11-facing.
    // Blank: return bumped;
    const double cosView = glm::dot(n, v);
    // A normal tipped past (or nearly onto) the tangent plane would light the surface from
    // behind. Turn it towards the viewer, in the plane of n and v, until cos = kMinCosView.
    if (!(cosView >= kMinCosView)) {
        Vec3 t, b;
        tangentFrame(v, t, b);  // any direction across v, for n = −v exactly
        const Vec3 across = unitOr(n - cosView * v, t);
        n = kMinCosView * v + std::sqrt(1.0 - kMinCosView * kMinCosView) * across;
    }
    return side * n;
    // [exercise-keep-viewer-side]
}
// [keep-viewer-side]

Bump::Bump(std::shared_ptr<const HeightField> field, double strength, double step)
    : field_(std::move(field)), strength_(strength), step_(step) {
    if (!(step_ > 0.0)) step_ = kDefaultStepFraction * field_->featureSize();
}

// [bump-perturb]
void Bump::perturb(const Ray& ray, Hit& hit) const {
    if (strength_ == 0.0 || !hit.instance) return;  // a zero bump is no bump
    const Instance& instance = *hit.instance;
    // Into object space, where the height field lives: the point, and the shading normal by
    // the inverse of normalToWorld, which is the transpose of objectToWorld's linear part.
    const Vec3 x = transformPoint(instance.worldToObject, hit.p);
    const Vec3 n = unitOr(glm::transpose(Mat3(instance.objectToWorld)) * hit.ns, hit.ns);
    // Tilt it by the height's surface gradient.
    const Vec3 g = surfaceGradient(*field_, x, n, step_);
    const Vec3 bumped = bumpedNormal(n, g, strength_);
    // Back to world space, on the viewer's side.
    const Vec3 nWorld = unitOr(instance.normalToWorld * bumped, hit.ns);
    hit.ns = keepViewerSide(nWorld, hit.ns, -glm::normalize(ray.d));
}
// [bump-perturb]

// [bump-normals]
void BumpNormals::apply(const Ray& ray, Hit& hit) const {
    if (hit.material && hit.material->bump) hit.material->bump->perturb(ray, hit);
}
// [bump-normals]

// [install-bump]
void installBump(Pipeline& pipeline, Scene&, const RenderContext& context) {
    // Only a scene with a bumped material pays for the lookup on every hit. Features install
    // in chapter order, so this stage runs after chapter 9's and tilts the smooth normal.
    for (const Instance& i : context.instances)
        if (i.material && i.material->bump) {
            pipeline.normals.push_back(std::make_shared<BumpNormals>());
            return;
        }
}
// [install-bump]

Feature bumpFeature() {
    return {
        "bump", 11,       "bump mapping: ripples, noise and height maps tilt the shading normal",
        true,   bindBump, installBump};
}

}  // namespace rb

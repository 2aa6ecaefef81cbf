#include "dof/thin_lens.h"

#include <cmath>

namespace rb {

// [focal-plane-point]
Vec3 focalPlanePoint(const PinholeCamera& camera, const Vec2& film, double focusDistance) {
    // The film direction has length 1 along the view, so scaling it by the focus distance
    // reaches the focal plane.
    return camera.eye() + focusDistance * camera.filmDirection(film.x, film.y);
}
// [focal-plane-point]

double blurCircleDiameter(double aperture, double focusDistance, double depth) {
    return aperture * std::abs(1.0 / focusDistance - 1.0 / depth);
}

Ray ThinLens::generate(const PinholeCamera& camera, const Vec2& film, const RaySlot& slot,
                       Sampler& sampler) const {
    return rayThrough(camera, film, stratifiedLensSample(slot, sampler));
}

// [thin-lens-ray]
Ray ThinLens::rayThrough(const PinholeCamera& camera, const Vec2& film, const Vec2& u) const {
    // [exercise-thin-lens-ray]
    // Exercise 13.1, the thin-lens ray: read ch13-thin-lens.
    // Blank: return camera.generateRay(film.x, film.y);
    // The lens point: the aperture shape scaled to its radius, in the camera's right/up plane.
    const Vec2 lens = 0.5 * settings_.aperture * aperturePoint(settings_.shape, u);
    const Vec3 offset = lens.x * camera.right() + lens.y * camera.upVector();
    // Aim at the point in focus, eye + f·d: the direction f·d − offset, divided by f so that
    // a zero offset leaves d (and the pinhole's ray) exactly as it was.
    const Vec3 d = camera.filmDirection(film.x, film.y);
    return Ray{camera.eye() + offset, glm::normalize(d - offset / settings_.focusDistance)};
    // [exercise-thin-lens-ray]
}
// [thin-lens-ray]

}  // namespace rb

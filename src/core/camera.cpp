#include "core/camera.h"

#include <glm/gtc/constants.hpp>

#include "core/error.h"

namespace rb {

// [camera-basis]
PinholeCamera::PinholeCamera(const CameraSpec& spec, int width, int height)
    : eye_(spec.eye), width_(width), height_(height) {
    if (!(glm::length(spec.view) > 0.0)) throw InputError("gr.render: view direction is zero");
    if (!(spec.fovyDegrees > 0.0 && spec.fovyDegrees < 180.0))
        throw InputError("gr.render: fovy must be between 0 and 180 degrees");
    // Build an orthonormal frame: w along the view, u to the right, v up (Gram–Schmidt on up).
    w_ = glm::normalize(spec.view);
    const Vec3 right = glm::cross(w_, spec.up);
    if (!(glm::length(right) > 1e-12 * glm::length(spec.up)))
        throw InputError("gr.render: up vector is zero or parallel to the view direction");
    u_ = glm::normalize(right);
    v_ = glm::cross(u_, w_);
    // The image plane sits at distance 1; fovy spans its height.
    halfHeight_ = std::tan(0.5 * glm::radians(spec.fovyDegrees));
    halfWidth_ = halfHeight_ * static_cast<double>(width) / static_cast<double>(height);
}
// [camera-basis]

// [camera-ray]
Ray PinholeCamera::generateRay(double x, double y) const {
    // [exercise-camera-ray]
    // Exercise 1.2, the camera ray through a pixel: read ch01-equations.
    // Blank: return Ray{eye_, w_};
    // Map pixel coordinates to [-1, 1] on the image plane, with +y up.
    const double sx = 2.0 * x / width_ - 1.0;
    const double sy = 1.0 - 2.0 * y / height_;
    const Vec3 d = w_ + sx * halfWidth_ * u_ + sy * halfHeight_ * v_;
    return Ray{eye_, glm::normalize(d)};
    // [exercise-camera-ray]
}
// [camera-ray]

Vec3 PinholeCamera::filmDirection(double x, double y) const {
    const double sx = 2.0 * x / width_ - 1.0;
    const double sy = 1.0 - 2.0 * y / height_;
    return w_ + sx * halfWidth_ * u_ + sy * halfHeight_ * v_;
}

bool PinholeCamera::mayShow(const AABB& box) const {
    if (box.empty()) return false;
    for (int k = 0; k < 3; ++k)
        if (!std::isfinite(box.lo[k]) || !std::isfinite(box.hi[k])) return true;
    // Count the corners outside each of the view pyramid's five planes, in camera coordinates
    // (x right, y up, z forward): behind the eye, beyond the left, right, bottom, top edges.
    int outside[5] = {0, 0, 0, 0, 0};
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3 c(corner & 1 ? box.hi.x : box.lo.x, corner & 2 ? box.hi.y : box.lo.y,
                     corner & 4 ? box.hi.z : box.lo.z);
        const Vec3 d = c - eye_;
        const double x = glm::dot(d, u_), y = glm::dot(d, v_), z = glm::dot(d, w_);
        outside[0] += z <= 0.0;
        outside[1] += x < -halfWidth_ * z;
        outside[2] += x > halfWidth_ * z;
        outside[3] += y < -halfHeight_ * z;
        outside[4] += y > halfHeight_ * z;
    }
    // All eight corners beyond one plane: the whole box is.
    for (int count : outside)
        if (count == 8) return false;
    return true;
}

}  // namespace rb

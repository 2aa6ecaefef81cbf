/// \file
/// The pinhole camera with A4's conventions.
#pragma once

#include "core/aabb.h"
#include "core/ray.h"

namespace rb {

/// A4's camera parameters, as gr.render receives them.
struct CameraSpec {
    Vec3 eye{0.0};              ///< Centre of projection.
    Vec3 view{0.0, 0.0, -1.0};  ///< Viewing direction (not normalised).
    Vec3 up{0.0, 1.0, 0.0};     ///< Up hint (need not be orthogonal to view).
    double fovyDegrees = 50.0;  ///< Vertical field of view in degrees.
};

/// A pinhole camera: every ray starts at the eye and passes through a point on an image plane
/// at distance 1 along the view direction.
class PinholeCamera {
  public:
    /// Build the camera basis; throws InputError when view is zero, up is parallel to view, or
    /// fovy is outside (0°, 180°).
    PinholeCamera(const CameraSpec& spec, int width, int height);
    /// The ray through image position (x, y) in pixels: (0,0) is the top-left corner of the
    /// image and (width, height) the bottom-right; a pixel centre is (i + 0.5, j + 0.5).
    Ray generateRay(double x, double y) const;
    /// The point of the image plane (at distance 1 along the view) that image position (x, y)
    /// maps to, relative to the eye: the unnormalised direction of generateRay(x, y), computed
    /// by the same arithmetic, so normalising it gives that ray's direction bit for bit.
    Vec3 filmDirection(double x, double y) const;
    /// The centre of projection.
    Vec3 eye() const { return eye_; }
    /// The unit forward, right and up vectors of the camera frame.
    Vec3 forward() const { return w_; }
    Vec3 right() const { return u_; }
    Vec3 upVector() const { return v_; }
    /// False when the box lies wholly behind the eye or wholly beyond one edge of the image,
    /// so no camera ray can reach it; true otherwise (also for an unbounded box).
    bool mayShow(const AABB& box) const;

  private:
    Vec3 eye_, w_, u_, v_;
    double halfWidth_, halfHeight_;
    int width_, height_;
};

}  // namespace rb

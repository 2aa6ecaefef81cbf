/// \file
/// The thin lens: camera rays that start on an aperture and meet on the plane in focus.
#pragma once

#include "core/camera_rays.h"
#include "dof/lens_sampling.h"

namespace rb {

/// A thin lens, described as a student's camera is: how wide, where it focuses, how many rays.
struct ThinLensSettings {
    double aperture = 0.0;       ///< Diameter of the disk, or side of the square (scene units).
    double focusDistance = 1.0;  ///< Distance from the eye to the plane in focus, along the view.
    int samples = 16;            ///< Lens samples per pixel (the fewest rays per pixel).
    ApertureShape shape = ApertureShape::Disk;
};

/// The point of the plane in focus (distance `focusDistance` from the eye along the view) that
/// the pinhole ray through image position `film` meets.
Vec3 focalPlanePoint(const PinholeCamera& camera, const Vec2& film, double focusDistance);

/// The diameter, on the image plane at distance 1, of the blur circle of a point at distance
/// `depth` along the view, seen through a disk of diameter `aperture` focused at
/// `focusDistance`: aperture · |1/focusDistance − 1/depth|.
/// Source: the thin-lens circle of confusion c = A·v·|S₂ − S₁| / (S₁·S₂) on a sensor at image
/// distance v (S₁ in focus, S₂ the point's distance), scaled to an image plane at distance 1.
double blurCircleDiameter(double aperture, double focusDistance, double depth);

/// Chapter 13's camera-ray generator: each ray starts at a point of the aperture (centred on
/// the eye, in the camera's right/up plane) and passes through the point of the focal plane
/// that the pinhole ray through the same image position meets.
class ThinLens final : public CameraRayGenerator {
  public:
    /// A lens with the given (checked) settings.
    explicit ThinLens(const ThinLensSettings& settings) : settings_(settings) {}
    /// The lens samples per pixel.
    int raysPerPixel() const override { return settings_.samples; }
    /// The ray through image position `film` from the lens point of ray `slot` (a stratified
    /// lens sample: see stratifiedLensSample).
    Ray generate(const PinholeCamera& camera, const Vec2& film, const RaySlot& slot,
                 Sampler& sampler) const override;
    /// The ray through image position `film` from the lens point for unit-square sample u.
    Ray rayThrough(const PinholeCamera& camera, const Vec2& film, const Vec2& u) const;
    /// The settings in use.
    const ThinLensSettings& settings() const { return settings_; }

  private:
    ThinLensSettings settings_;
};

}  // namespace rb

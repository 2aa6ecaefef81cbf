/// \file
/// Height maps: seed 002's bump from a grey image. The heights are looked up at the hit's
/// texture coordinates (chapter 10's UV mapping), differentiated numerically in texture space,
/// and turned into a surface gradient through dp/du and dp/dv (Blinn 1978).
#pragma once

#include <memory>
#include <vector>

#include "core/normal_perturbation.h"
#include "texture/texture_image.h"
#include "texture/uv_mapping.h"

namespace rb {

/// The default strength of seed 002's set_bump_map(file), which names none: object units of
/// displacement per unit of height (a full black-to-white step over one texel of a 256-texel
/// map across one object unit then tilts the normal by atan(2.56) = 69°).
inline constexpr double kDefaultHeightMapStrength = 0.01;

/// A grey image as heights in [0, 1]: each texel's value as the file stores it (the mean of its
/// channels, sRGB-encoded again, so 8-bit grey level g is height g/255), bilinear between texel
/// centres and repeating at the edges, as chapter 10 samples colours.
class HeightImage {
  public:
    /// The heights of a loaded image (at least 1 × 1).
    explicit HeightImage(const TextureImage& image);
    /// The height at texture coordinate st (v up: v = 0 is the bottom row).
    double at(const Vec2& st) const;
    int width() const { return width_; }
    int height() const { return height_; }

  private:
    /// The height of texel (x, y), with x and y wrapped into the image.
    double texel(long long x, long long y) const;
    int width_, height_;
    std::vector<float> heights_;
};

/// The surface gradient of a height map from its texture-space derivatives h_u and h_v and
/// the surface derivatives dp/du, dp/dv, on a surface with unit normal n: h_u ∇u + h_v ∇v,
/// where ∇u = (dp/dv × n) / D and ∇v = (n × dp/du) / D, D = n · (dp/du × dp/dv), are the
/// tangent vectors with ∇u · dp/du = 1, ∇u · dp/dv = 0 (and the same for v). Zero where the
/// parameterisation is degenerate (D = 0, as at a sphere's poles).
Vec3 heightMapGradient(double h_u, double h_v, const Vec3& dpdu, const Vec3& dpdv, const Vec3& n);

/// Seed 002's height-map bump: heights from an image at the hit's (u, v), derivatives by
/// central differences of `step` texels.
class HeightMapBump final : public NormalPerturbation {
  public:
    /// A bump of `image` at strength (finite), with a finite-difference step in texels (> 0),
    /// (u, v) from `mapping`, and the image repeated scale.x times along u and scale.y along v
    /// (both non-zero).
    HeightMapBump(std::shared_ptr<const HeightImage> image, double strength, double stepTexels,
                  UVMapping mapping = UVMapping::Surface, const Vec2& scale = Vec2(1.0));
    /// Tilt hit.ns by the map's gradient, in the instance's object space; strength 0 leaves it.
    void perturb(const Ray& ray, Hit& hit) const override;
    /// The heights.
    const HeightImage& image() const { return *image_; }
    /// The strength.
    double strength() const { return strength_; }
    /// The finite-difference step in texels.
    double step() const { return step_; }

  private:
    std::shared_ptr<const HeightImage> image_;
    double strength_;
    double step_;
    UVMapping mapping_;
    Vec2 scale_;
};

}  // namespace rb

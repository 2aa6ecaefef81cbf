/// \file
/// Lights with an area (chapter 6): the rectangular panel of seed 001 and the ball of seed 002,
/// each a LightShape that the core's Phong shading samples as n × n points.
///
/// The emission model, in one place. A light's `colour` I is a radiant intensity: what a point
/// light of that colour would deliver, I / (c0 + c1·r + c2·r²) before the cosine at the
/// receiver. A shaped light spreads the same intensity over its surface, as a uniform
/// Lambertian emitter, so that with physical falloff {0, 0, 1} the shading is an unbiased
/// estimate of the irradiance the surface would really receive:
///
/// - the **rectangle** is a one-sided panel of area A facing `normal`, with radiance L = I / A;
///   seen along its normal it is exactly as bright as a point light of colour I, and off its
///   normal it dims with its cosine lobe (I·cosθ_light);
/// - the **ball** is a sphere of radius R with radiance L = I / (πR²) on its surface; seen from
///   anywhere outside it delivers exactly the point-light irradiance I·cosθ/d² while it is
///   wholly above the receiver's horizon.
///
/// Each sampler returns a point and its *emission weight* w: the factor by which that point,
/// treated as a point light of colour I at distance r, must be scaled so that the average over
/// the samples is the estimator above. Every sampler sits next to its pdf.
#pragma once

#include <memory>

#include "core/light.h"

namespace rb {

/// How the n × n points on a light are chosen.
enum class LightSampling {
    Stratified,   ///< One jittered point in each cell of an n × n grid (the default).
    Independent,  ///< n × n independent uniform points (for comparison).
};

// [stratum]
/// The k-th of n × n sample positions in the unit square: with stratified sampling, point k
/// lies in cell (k mod n, k div n), jittered within it by u; with independent sampling it is
/// u itself.
inline Vec2 unitSquareSample(int k, int n, const Vec2& u, LightSampling sampling) {
    if (sampling == LightSampling::Independent) return u;
    return {((k % n) + u.x) / n, ((k / n) + u.y) / n};
}
// [stratum]

/// What every chapter-6 light shape shares: its own sample count and the sampling strategy.
class AreaLightShape : public LightShape {
  public:
    /// The default number of samples per axis (4 × 4 = 16 shadow rays per shading point).
    static constexpr int kDefaultSamplesPerAxis = 4;

    /// This light's own samples per axis (gr.area_light's or gr.ball_light's `samples`).
    int samplesPerAxis() const override { return samplesPerAxis_; }
    /// The strategy samplePoint uses.
    LightSampling sampling() const { return sampling_; }
    /// A copy of this shape that samples with the given strategy.
    virtual std::shared_ptr<const AreaLightShape> withSampling(LightSampling s) const = 0;

  protected:
    AreaLightShape(int samplesPerAxis, LightSampling sampling)
        : samplesPerAxis_(samplesPerAxis), sampling_(sampling) {}
    int samplesPerAxis_;
    LightSampling sampling_;
};

/// Seed 001's rectangular area light: a one-sided Lambertian panel of size length × width,
/// centred on the light's position, facing `normal`. `length` runs along `left`, `width`
/// along normal × left.
class RectangleLight final : public AreaLightShape {
  public:
    /// A panel from unit, orthogonal `normal` and `left`; sizes ≥ 0 (zero gives a point
    /// light with a cosine lobe).
    RectangleLight(double length, double width, const Vec3& normal, const Vec3& left,
                   int samplesPerAxis = kDefaultSamplesPerAxis,
                   LightSampling sampling = LightSampling::Stratified);

    /// Point k of n × n, uniform over the panel's area (pdf: pdfArea()); weight
    /// max(0, cosθ_light), the panel's cosine towards p.
    Vec3 samplePoint(const Vec3& centre, const Vec3& p, int k, int n, const Vec2& u,
                     double& weight) const override;
    /// The density of samplePoint's points with respect to area: 1 / (length · width)
    /// (infinite for a panel of zero area, whose points all lie on its centre).
    double pdfArea() const { return 1.0 / (length_ * width_); }

    /// A copy that samples with strategy s.
    std::shared_ptr<const AreaLightShape> withSampling(LightSampling s) const override;

    double length() const { return length_; }       ///< Size along left().
    double width() const { return width_; }         ///< Size along normal × left.
    const Vec3& normal() const { return normal_; }  ///< Unit; the side that emits.
    const Vec3& left() const { return left_; }      ///< Unit, orthogonal to normal().

  private:
    double length_, width_;
    Vec3 normal_, left_, up_;  // up_ = normal × left
};

/// Seed 002's ball light: a uniform spherical emitter of radius R centred on the light's
/// position. Seen from outside it is sampled over the cap visible from the shading point,
/// uniformly in solid angle; from inside, uniformly over its whole surface.
class BallLight final : public AreaLightShape {
  public:
    /// A ball of radius ≥ 0 (zero gives exactly a point light).
    explicit BallLight(double radius, int samplesPerAxis = kDefaultSamplesPerAxis,
                       LightSampling sampling = LightSampling::Stratified);

    /// Point k of n × n on the part of the ball visible from p (pdf: pdfSolidAngle()), with
    /// weight 2(1 − cosθ_max)·r²/R², where r = |point − p|; from inside the ball, uniform over
    /// its area with weight 4|cosθ_light|. Radius 0: the centre with weight 1.
    Vec3 samplePoint(const Vec3& centre, const Vec3& p, int k, int n, const Vec2& u,
                     double& weight) const override;
    /// The density of samplePoint's directions (seen from p outside the ball) with respect to
    /// solid angle: 1 / (2π(1 − cosθ_max)), with sinθ_max = R / |centre − p|.
    double pdfSolidAngle(const Vec3& centre, const Vec3& p) const;

    /// A copy that samples with strategy s.
    std::shared_ptr<const AreaLightShape> withSampling(LightSampling s) const override;

    double radius() const { return radius_; }  ///< R.

  private:
    double radius_;
};

}  // namespace rb

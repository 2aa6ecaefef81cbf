/// \file
/// The integrator: trace a ray, find the surface, and add up the shading terms.
#pragma once

#include <memory>
#include <vector>

#include "core/aggregate.h"
#include "core/light.h"
#include "core/sampler.h"
#include "core/stats.h"

namespace rb {

/// The world a ray is traced in: instances, their aggregate, lights and render settings.
struct Scene {
    std::vector<Instance> instances;
    std::unique_ptr<Aggregate> aggregate;
    std::vector<PointLight> lights;
    Colour ambient{0.0};
    Colour background{0.0};
    int maxDepth = 5;  ///< Recursion limit for secondary rays (chapters 4–7).
};

class Integrator;

/// What a shading routine may use: the scene, the integrator (to trace more rays), this
/// sample's random stream, this thread's counters and the recursion depth.
struct ShadeContext {
    const Scene& scene;
    const Integrator& integrator;
    Sampler& sampler;
    RayCounters& counters;
    int depth = 0;
};

/// The local shading model: chapter 1 has a headlight; chapter 2 replaces it with Phong.
using SurfaceShader = Colour (*)(const ShadeContext& ctx, const Ray& ray, const Hit& hit);

/// A secondary-ray term added to the local shading (mirror, transmission, glossy lobe...).
/// This is the extension point chapters 4–7 plug into.
class ShadingTerm {
public:
    virtual ~ShadingTerm() = default;
    /// The term's contribution at hit, for a ray arriving along ray.d.
    virtual Colour shade(const ShadeContext& ctx, const Ray& ray, const Hit& hit) const = 0;
};

/// How a render is put together; each enabled feature adjusts it.
struct Pipeline {
    SurfaceShader surface = nullptr;           ///< Local shading (set by chapter 1, then 2).
    AggregateBuilder buildAggregate = nullptr; ///< Acceleration (set by chapter 1, then 3).
    std::vector<std::shared_ptr<const ShadingTerm>> terms;  ///< Secondary terms, in order.
};

/// Traces rays through a scene with a pipeline.
class Integrator {
public:
    Integrator(const Scene& scene, const Pipeline& pipeline) : scene_(scene), pipeline_(pipeline) {}
    /// Radiance arriving along a ray (reversed): the shaded colour of the first surface, or
    /// the background.
    Colour trace(const Ray& ray, Sampler& sampler, RayCounters& counters, int depth) const;
    /// True when the segment from p (t=0) to p + d (t=1) is blocked.
    bool occluded(const Ray& ray, double tMax, RayCounters& counters) const;

private:
    const Scene& scene_;
    const Pipeline& pipeline_;
};

/// Chapter 1's shading: the eye is a light (kd · |n·v|), so shapes read as solid.
Colour shadeHeadlight(const ShadeContext& ctx, const Ray& ray, const Hit& hit);

}  // namespace rb

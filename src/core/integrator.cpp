#include "core/integrator.h"

#include "core/material.h"

namespace rb {

// [trace]
Colour Integrator::trace(const Ray& ray, Sampler& sampler, RayCounters& counters, int depth,
                         const MediumStack& media, double weight, bool ambient) const {
    // A camera ray of a path-traced render (chapter 18): the estimator follows the whole path.
    if (pipeline_.radiance && depth == 0) return pipeline_.radiance->Li(*this, ray, sampler, counters);
    Hit hit;
    const bool found =
        scene_.aggregate->intersect(ray, std::numeric_limits<double>::infinity(), hit);
    const ShadeContext ctx{scene_, *this, sampler, counters, depth, media, weight, ambient};
    if (pipeline_.media) {
        // Media (chapter 17): the light they scatter in, plus what reaches us from the end.
        Colour throughput(1.0);
        const Colour scattered = pipeline_.media->segment(
            ctx, ray, found ? hit.t : std::numeric_limits<double>::infinity(), throughput);
        if (throughput == Colour(0.0)) return scattered;
        return scattered + throughput * (found ? shade(ctx, ray, hit) : scene_.background);
    }
    if (!found) return scene_.background;
    return shade(ctx, ray, hit);
}
// [trace]

// [shade]
Colour Integrator::shade(const ShadeContext& ctx, const Ray& ray, Hit& hit) const {
    // Smooth normals (chapter 9), then bumps (chapter 11), before anything shades.
    for (const auto& normal : pipeline_.normals) normal->apply(ray, hit);
    // Local shading, then each chapter's secondary term.
    Colour colour;
    if (pipeline_.textureLookup && hit.material && !hit.material->textures.empty()) {
        // A textured material (chapter 10): the surface shader sees its colours at this
        // point; the secondary terms still read the material's own parameters.
        const Material textured = pipeline_.textureLookup(hit);
        Hit shaded = hit;
        shaded.material = &textured;
        colour = pipeline_.surface(ctx, ray, shaded);
    } else {
        colour = pipeline_.surface(ctx, ray, hit);
    }
    for (const auto& term : pipeline_.terms) colour = term->apply(ctx, ray, hit, colour);
    return colour;
}
// [shade]

// [headlight]
Colour shadeHeadlight(const ShadeContext&, const Ray& ray, const Hit& hit) {
    const Colour kd = hit.material ? hit.material->kd : Colour(0.5);
    const double cosTheta = std::abs(glm::dot(hit.ng, glm::normalize(ray.d)));
    return kd * cosTheta;
}
// [headlight]

}  // namespace rb

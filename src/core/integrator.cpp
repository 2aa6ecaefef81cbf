#include "core/integrator.h"

#include "core/material.h"

namespace rb {

// [trace]
Colour Integrator::trace(const Ray& ray, Sampler& sampler, RayCounters& counters, int depth,
                         const MediumStack& media, double weight) const {
    Hit hit;
    if (!scene_.aggregate->intersect(ray, std::numeric_limits<double>::infinity(), hit))
        return scene_.background;
    // Smooth normals (chapter 9), then bumps (chapter 11), before anything shades.
    for (const auto& normal : pipeline_.normals) normal->apply(ray, hit);
    // Local shading, then each chapter's secondary term.
    const ShadeContext ctx{scene_, *this, sampler, counters, depth, media, weight};
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
// [trace]

// [headlight]
Colour shadeHeadlight(const ShadeContext&, const Ray& ray, const Hit& hit) {
    const Colour kd = hit.material ? hit.material->kd : Colour(0.5);
    const double cosTheta = std::abs(glm::dot(hit.ng, glm::normalize(ray.d)));
    return kd * cosTheta;
}
// [headlight]

}  // namespace rb

#include "reflection/reflection.h"

#include "phong/phong.h"
#include "core/render_context.h"

namespace rb {

void bindReflection(LuaBindings& lua);

Vec3 reflect(const Vec3& d, const Vec3& n) {
    // [exercise-reflect]
    // Exercise 4.1, the law of reflection: read ch04-equations.
    // Blank: return d;
    return d - 2.0 * glm::dot(d, n) * n;
    // [exercise-reflect]
}

// [trace-specular]
Colour traceSpecular(const ShadeContext& ctx, const Hit& hit, const Vec3& axis, const Vec3& side,
                     RayKind kind, const MediumStack& media, double weight) {
    // Adaptive depth control: light this faint could not move the pixel by one 8-bit level.
    const double pathWeight = ctx.weight * weight;
    if (pathWeight < ctx.scene.minWeight) return Colour(0.0);
    const Vec3 origin = offsetRayOrigin(hit.p, hit.ng, side);
    const LobeSampler* lobe = ctx.integrator.pipeline().lobe.get();
    int samples = lobe && hit.material ? lobe->sampleCount(*hit.material) : 0;
    // Spread into many rays only where the camera sees the glossy surface; a glossy bounce
    // deeper in the path takes one lobe sample. Otherwise rays multiply like N^depth.
    if (samples > 1 && ctx.depth > 0) samples = 1;
    if (samples == 0) {
        // One sharp ray.
        ctx.counters.add(kind);
        return ctx.integrator.trace(Ray{origin, axis}, ctx.sampler, ctx.counters, ctx.depth + 1,
                                    media, pathWeight, ctx.ambient);
    }
    // A glossy surface: average the lobe's directions; those that fall below the surface
    // carry nothing.
    Colour sum(0.0);
    for (int s = 0; s < samples; ++s) {
        Vec3 direction;
        if (!lobe->sample(*hit.material, axis, side, ctx.sampler, direction)) continue;
        ctx.counters.add(RayKind::Glossy);
        sum += ctx.integrator.trace(Ray{origin, direction}, ctx.sampler, ctx.counters,
                                    ctx.depth + 1, media, pathWeight, ctx.ambient);
    }
    return sum / static_cast<double>(samples);
}
// [trace-specular]

// [reflection-term]
Colour ReflectionTerm::apply(const ShadeContext& ctx, const Ray& ray, const Hit& hit,
                             const Colour& colour) const {
    const double r = hit.material ? hit.material->param("reflect") : 0.0;
    if (r <= 0.0 || ctx.depth >= ctx.scene.maxDepth) return colour;
    // [exercise-mirror]
    // Exercise 4.2, the mirror term: read ch04-equations.
    // Blank: return colour;
    // Reflect about the shading normal turned towards the viewer (no back-face culling).
    const Vec3 d = glm::normalize(ray.d);
    const Vec3 n = faceForward(hit.ns, -d);
    const Vec3 mirror = glm::normalize(reflect(d, n));
    return colour + r * traceSpecular(ctx, hit, mirror, faceForward(hit.ng, -d),
                                      RayKind::Reflection, ctx.media, r);
    // [exercise-mirror]
}
// [reflection-term]

namespace {
void installReflection(Pipeline& pipeline, Scene&, const RenderContext& context) {
    // A scene with no mirror pays nothing: the term is not even added.
    if (context.anyMaterialUses("reflect"))
        pipeline.terms.push_back(std::make_shared<ReflectionTerm>());
}
}  // namespace

Feature reflectionFeature() {
    return {"reflection", 4, "mirror reflection with a recursion limit", true, bindReflection,
            installReflection};
}

}  // namespace rb

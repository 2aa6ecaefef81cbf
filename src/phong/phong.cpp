#include "phong/phong.h"

#include "core/material.h"

namespace rb {

// [phong-term]
Colour phongBrdfTerm(const Material& m, const Vec3& n, const Vec3& l, const Vec3& v) {
    // [exercise-phong-term]
    // Exercise 2.1, the Phong term: read ch02-equations.
    // Blank: return Colour(0.0);
    const double nDotL = glm::dot(n, l);
    if (nDotL <= 0.0) return Colour(0.0);  // light is behind the surface
    const Colour diffuse = m.kd * nDotL;
    if (m.ks == Colour(0.0)) return diffuse;  // no highlight: skip the costly pow
    const Vec3 r = 2.0 * nDotL * n - l;       // l mirrored about n
    const double rDotV = std::max(0.0, glm::dot(r, v));
    if (rDotV == 0.0 && m.shininess > 0.0) return diffuse;  // 0^s = 0: skip the pow
    return diffuse + m.ks * std::pow(rDotV, m.shininess);
    // [exercise-phong-term]
}
// [phong-term]

namespace {

// [shadow-ray]
/// Light arriving from one point `from` of a light, through the shadow test, times the Phong
/// term. `emission` scales the light's intensity (1 for a point light).
Colour lightFromPoint(const ShadeContext& ctx, const Hit& hit, const Material& m, const Vec3& n,
                      const Vec3& ng, const Vec3& v, const PointLight& light, const Vec3& from,
                      double emission) {
    const Vec3 toLight = from - hit.p;
    const double r = glm::length(toLight);
    if (!(r > 0.0) || emission <= 0.0) return Colour(0.0);
    const Vec3 l = toLight / r;
    if (glm::dot(n, l) <= 0.0) return Colour(0.0);  // light behind the shading normal
    // [exercise-shadow-ray]
    // Exercise 2.3, the shadow ray: read ch02-equations.
    // Blank: 
    // Cast a shadow ray from the (offset) hit point to the light: t in (0, 1). (A smooth
    // mesh, chapter 9, may move where shadow rays start: hit.shadowOffset.)
    const Vec3 origin = offsetRayOrigin(hit.p + hit.shadowOffset, ng, l);
    if (ctx.integrator.occluded(Ray{origin, from - origin}, 1.0, ctx.counters)) return Colour(0.0);
    // [exercise-shadow-ray]
    const Colour lit = emission * light.intensityAt(r) * phongBrdfTerm(m, n, l, v);
    // Fog or smoke on the way (chapter 17) dims the light.
    if (!ctx.integrator.hasMedia() || lit == Colour(0.0)) return lit;
    return lit * ctx.integrator.transmittance(hit.p, from, ctx.sampler, ctx.counters);
}
// [shadow-ray]

}  // namespace

// [phong-shade]
Colour shadePhong(const ShadeContext& ctx, const Ray& ray, const Hit& hit) {
    static const Material kBlack{};
    const Material& m = hit.material ? *hit.material : kBlack;
    const Vec3 v = -glm::normalize(ray.d);
    const Vec3 n = faceForward(hit.ns, v);
    const Vec3 ng = faceForward(hit.ng, v);
    // A4's ambient term, unless the path counted it already (at a particle of smoke, chapter 17).
    Colour colour = ctx.ambient ? m.kd * ctx.scene.ambient : Colour(0.0);
    for (const PointLight& light : ctx.scene.lights) {
        if (!light.shape || !ctx.scene.sampleAreaLights) {
            colour += lightFromPoint(ctx, hit, m, n, ng, v, light, light.position, 1.0);
            continue;
        }
        // A light with an area (chapter 6): average n × n stratified points on it, each
        // shaded in full, so the highlight takes the light's shape.
        const int perAxis =
            ctx.scene.lightSamples > 0 ? ctx.scene.lightSamples : light.shape->samplesPerAxis();
        Colour sum(0.0);
        for (int k = 0; k < perAxis * perAxis; ++k) {
            double emission = 1.0;
            const Vec3 from = light.shape->samplePoint(light.position, hit.p, k, perAxis,
                                                       ctx.sampler.next2D(), emission);
            sum += lightFromPoint(ctx, hit, m, n, ng, v, light, from, emission);
        }
        colour += sum / static_cast<double>(perAxis * perAxis);
    }
    return colour;
}
// [phong-shade]

}  // namespace rb

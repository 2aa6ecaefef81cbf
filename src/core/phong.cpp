#include "core/phong.h"

#include "core/material.h"

namespace rb {

// [phong-term]
Colour phongBrdfTerm(const Material& m, const Vec3& n, const Vec3& l, const Vec3& v) {
    const double nDotL = glm::dot(n, l);
    if (nDotL <= 0.0) return Colour(0.0);  // light is behind the surface
    const Vec3 r = 2.0 * nDotL * n - l;    // l mirrored about n
    const double rDotV = std::max(0.0, glm::dot(r, v));
    return m.kd * nDotL + m.ks * std::pow(rDotV, m.shininess);
}
// [phong-term]

// [phong-shade]
Colour shadePhong(const ShadeContext& ctx, const Ray& ray, const Hit& hit) {
    static const Material kBlack{};
    const Material& m = hit.material ? *hit.material : kBlack;
    const Vec3 v = -glm::normalize(ray.d);
    const Vec3 n = faceForward(hit.ns, v);
    const Vec3 ng = faceForward(hit.ng, v);
    Colour colour = m.kd * ctx.scene.ambient;
    for (const PointLight& light : ctx.scene.lights) {
        // Cast a shadow ray from the (offset) hit point towards the light: t in (0, 1).
        const Vec3 toLight = light.position - hit.p;
        const double r = glm::length(toLight);
        if (!(r > 0.0)) continue;
        const Vec3 l = toLight / r;
        if (glm::dot(ng, l) <= 0.0 && glm::dot(n, l) <= 0.0) continue;  // light behind surface
        const Vec3 origin = offsetRayOrigin(hit.p, ng, l);
        if (ctx.integrator.occluded(Ray{origin, light.position - origin}, 1.0, ctx.counters))
            continue;
        colour += light.intensityAt(r) * phongBrdfTerm(m, n, l, v);
    }
    return colour;
}
// [phong-shade]

}  // namespace rb

#include "refraction/refraction.h"

#include <cstdio>

#include "core/error.h"
#include "phong/phong.h"
#include "core/render_context.h"
#include "reflection/reflection.h"

namespace rb {

void bindRefraction(LuaBindings& lua);

// [refract-direction]
bool refractDirection(const Vec3& d, const Vec3& n, double eta_i, double eta_t, Vec3& t) {
    const double cosTheta_i = std::clamp(-glm::dot(d, n), 0.0, 1.0);
    double cosTheta_t;
    if (!snellCosTheta_t(cosTheta_i, eta_i, eta_t, cosTheta_t)) return false;
    // Split d into a part along n and a part across it; the part across shrinks by η_i/η_t
    // (that is Snell's law) and the part along n is set so the result has unit length.
    // Source: B. de Greve, "Reflections and Refractions in Ray Tracing" (2006), eq. 22.
    const double eta = eta_i / eta_t;
    t = glm::normalize(eta * d + (eta * cosTheta_i - cosTheta_t) * n);
    return true;
}
// [refract-direction]

// [ior-stack]
MediaCrossing crossSurface(const MediumStack& media, const Instance* instance, double ior,
                           bool entering) {
    // [exercise-ior-stack]
    // Exercise 5.3, crossing a surface with the IOR stack: read ch05-equations.
    MediaCrossing c;
    c.entering = entering;
    if (entering) {
        // From the medium we are in into the object: push it.
        c.eta_i = media.currentIor();
        c.eta_t = ior;
        c.beyond = media.entered(instance, ior);
    } else if (media.contains(instance)) {
        // Out of the object: the stack knows what surrounds it (glass around water, or air).
        c.eta_i = media.currentIor();
        c.eta_t = media.iorBeyond(instance, ior);
        c.beyond = media.left(instance);
    } else {
        // Leaving an object the path never entered: it started inside (a camera under water).
        // Its own index is on this side, the current medium beyond.
        c.eta_i = ior;
        c.eta_t = media.currentIor();
        c.beyond = media;
    }
    return c;
    // [exercise-ior-stack]
}
// [ior-stack]

// [dielectric-split]
DielectricSplit splitAtDielectric(const Vec3& d, const Hit& hit, double ior,
                                  const MediumStack& media, FresnelFormula formula) {
    DielectricSplit s;
    // Closed shapes' geometric normals point outwards: a ray that meets the surface against
    // the normal is entering the object.
    const bool entering = glm::dot(d, hit.ng) < 0.0;
    s.media = crossSurface(media, hit.instance, ior, entering);
    // Work with the shading normal turned towards the side the ray comes from.
    const Vec3 n = faceForward(hit.ns, -d);
    s.cosTheta_i = std::clamp(-glm::dot(d, n), 0.0, 1.0);
    s.reflected = glm::normalize(reflect(d, n));
    const double eta_i = s.media.eta_i, eta_t = s.media.eta_t;
    Vec3 t;
    // A refracted ray that would leave on the incident side of the geometric surface can only
    // come from an interpolated shading normal (chapter 9); treat it like TIR.
    if (!refractDirection(d, n, eta_i, eta_t, t) || glm::dot(t, faceForward(hit.ng, -d)) >= 0.0) {
        s.totalInternalReflection = true;
        s.F = 1.0;
        return s;
    }
    s.transmitted = t;
    s.F = fresnelReflectance(formula, s.cosTheta_i, eta_i, eta_t);
    return s;
}
// [dielectric-split]

FresnelFormula RefractionTerm::formulaFor(const Material& m) const {
    switch (choice_) {
        case FresnelChoice::Exact:
            return FresnelFormula::Exact;
        case FresnelChoice::Schlick:
            return FresnelFormula::Schlick;
        case FresnelChoice::PerMaterial:
            break;
    }
    return m.param("schlick") != 0.0 ? FresnelFormula::Schlick : FresnelFormula::Exact;
}

// Shadows through glass. The core's shadow rays (chapter 2) stop at the first surface they
// meet, glass included, so a glass ball casts a full, hard shadow, as in Whitted's 1980 images.
// Seed 001 skipped refractive objects in its shadow tests instead (glass cast no shadow at all),
// and POV-Ray dims a shadow ray by each transparent surface it passes. Neither is right: the
// light under a real glass ball is a caustic, focused by refraction, which only chapter 16's
// photon map can draw.

// [refraction-term]
Colour RefractionTerm::apply(const ShadeContext& ctx, const Ray& ray, const Hit& hit,
                             const Colour& colour) const {
    const double transparency = hit.material ? hit.material->param("transparency") : 0.0;
    if (transparency <= 0.0 || ctx.depth >= ctx.scene.maxDepth) return colour;
    const Material& m = *hit.material;
    const Vec3 d = glm::normalize(ray.d);
    const DielectricSplit s =
        splitAtDielectric(d, hit, m.param("ior", 1.0), ctx.media, formulaFor(m));
    // The mirror ray leaves on the incident side and keeps the media it came through; the
    // refracted ray leaves on the far side and carries the stack with this object entered or
    // left. Both go through traceSpecular, so chapter 7 can spread them into lobes.
    const Vec3 incidentSide = faceForward(hit.ng, -d);
    // Each ray's weight in this surface's colour, for adaptive depth control.
    auto reflected = [&](double weight) {
        return traceSpecular(ctx, hit, s.reflected, incidentSide, RayKind::Reflection, ctx.media,
                             weight);
    };
    auto transmitted = [&](double weight) {
        return traceSpecular(ctx, hit, s.transmitted, -incidentSide, RayKind::Refraction,
                             s.media.beyond, weight);
    };
    Colour split(0.0);
    if (ctx.depth < kFullSplitDepth) {
        // Whitted: follow both rays, weighted by Fresnel.
        if (s.F > 0.0) split += s.F * reflected(transparency * s.F);
        if (s.F < 1.0) split += (1.0 - s.F) * transmitted(transparency * (1.0 - s.F));
    } else {
        // Deep in the tree: follow one ray, the mirror one with probability F. Its expected
        // value is F·L_r + (1 − F)·L_t, as above, at the cost of one ray instead of two.
        const bool mirror = s.F >= 1.0 || (s.F > 0.0 && ctx.sampler.next1D() < s.F);
        split = mirror ? reflected(transparency) : transmitted(transparency);
    }
    // Seed 001: only the transparent fraction is split; the rest is the opaque surface.
    return (1.0 - transparency) * colour + transparency * split;
}
// [refraction-term]

namespace {

std::string number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return text;
}

// [refraction-install]
void installRefraction(Pipeline& pipeline, Scene&, const RenderContext& context) {
    // --fresnel=exact|schlick overrides every material's choice.
    const std::string fresnel = context.cliOption("fresnel");
    FresnelChoice choice = FresnelChoice::PerMaterial;
    if (fresnel == "exact")
        choice = FresnelChoice::Exact;
    else if (fresnel == "schlick")
        choice = FresnelChoice::Schlick;
    else if (!fresnel.empty())
        throw InputError("--fresnel: expected 'exact' or 'schlick', got '" + fresnel + "'");
    // A scene without transparent materials pays nothing: the term is not even added.
    if (!context.anyMaterialUses("transparency")) return;
    // Check the parameters once here rather than on every ray.
    std::vector<const Material*> materials;
    for (const Instance& i : context.instances) {
        // The instance's material and those its shape carries (CSG operands, chapter 14).
        materials.assign(1, i.material);
        i.shape->materials(materials);
        for (const Material* m : materials) {
            if (!m) continue;
            const double transparency = m->param("transparency");
            const double ior = m->param("ior", 1.0);
            if (transparency < 0.0 || transparency > 1.0)
                throw InputError("material of '" + i.name +
                                 "': transparency must be in [0, 1], got " + number(transparency));
            if (transparency != 0.0 && !(ior > 0.0))
                throw InputError("material of '" + i.name + "': ior must be positive, got " +
                                 number(ior));
        }
    }
    pipeline.terms.push_back(std::make_shared<RefractionTerm>(choice));
}
// [refraction-install]

}  // namespace

Feature refractionFeature() {
    return {"refraction",
            5,
            "glass and water: Snell, Fresnel (exact or Schlick), TIR, nested media",
            true,
            bindRefraction,
            installRefraction,
            {{"fresnel", "exact|schlick", "Fresnel formula for every transparent material",
              "each material's own, else exact"}}};
}

}  // namespace rb

#include "photon_map/photon_tracer.h"

#include <omp.h>

#include <algorithm>

#include "core/material.h"
#include "phong/phong.h"
#include "photon_map/emission.h"
#include "reflection/reflection.h"
#include "refraction/refraction.h"
#include "soft_shadows/area_light.h"

namespace rb {

PhotonScattering PhotonScattering::of(const Pipeline& pipeline) {
    PhotonScattering s;
    s.pipeline = &pipeline;
    s.lobe = pipeline.lobe.get();
    for (const auto& term : pipeline.terms) {
        if (dynamic_cast<const ReflectionTerm*>(term.get())) s.mirrors = true;
        if (const auto* r = dynamic_cast<const RefractionTerm*>(term.get())) s.refraction = r;
    }
    return s;
}

bool PhotonScattering::specular(const Material& m) const {
    return (mirrors && m.param("reflect") > 0.0) || (refraction && m.param("transparency") > 0.0);
}

namespace {

/// The random streams of photons start here, far from any pixel index.
constexpr std::uint64_t kPhotonStream = 0x50484f544f4e0000ULL;
/// Photons per unit of parallel work.
constexpr std::uint64_t kChunk = 1024;

/// The mean of a colour's channels.
double mean(const Colour& c) {
    return (c.r + c.g + c.b) / 3.0;
}

// [emitters]
/// One light as photon emission sees it.
struct Emitter {
    const PointLight* light = nullptr;
    const RectangleLight* rectangle = nullptr;  ///< Seed 001's panel, when chapter 6 is on.
    const BallLight* ball = nullptr;            ///< Seed 002's ball, when chapter 6 is on.
    double power = 0.0;                         ///< Mean flux over the channels.
};

/// Every light with its power: 4πI for a point light and a ball (a uniform sphere of
/// intensity I), πI for a one-sided Lambertian panel whose intensity along its normal is I.
std::vector<Emitter> emittersOf(const Scene& scene) {
    std::vector<Emitter> emitters;
    for (const PointLight& light : scene.lights) {
        Emitter e;
        e.light = &light;
        if (light.shape && scene.sampleAreaLights) {
            e.rectangle = dynamic_cast<const RectangleLight*>(light.shape.get());
            e.ball = dynamic_cast<const BallLight*>(light.shape.get());
        }
        e.power = mean(light.colour) * (e.rectangle ? M_PI : 4.0 * M_PI);
        if (e.power > 0.0) emitters.push_back(e);
    }
    return emitters;
}
// [emitters]

/// A sphere around a specular object, for aiming caustic photons (Jensen's projection map).
struct Target {
    Vec3 centre{0.0};
    double radius = 0.0;
};

/// Bounding spheres of the instances that send photons on specularly.
std::vector<Target> specularTargets(const Scene& scene, const PhotonScattering& scattering) {
    std::vector<Target> targets;
    std::vector<const Material*> parts;
    for (const Instance& i : scene.instances) {
        parts.assign(1, i.material);
        i.shape->materials(parts);
        const bool specular = std::any_of(parts.begin(), parts.end(), [&](const Material* m) {
            return m && scattering.specular(*m);
        });
        if (!specular) continue;
        const Vec3 lo = i.worldBounds.lo, hi = i.worldBounds.hi;
        targets.push_back({0.5 * (lo + hi), 0.5 * glm::length(hi - lo)});
    }
    return targets;
}

/// A photon leaving a light: where, which way, and its flux (before the falloff).
struct EmittedPhoton {
    Vec3 origin{0.0}, direction{0.0};
    Colour flux{0.0};
    const PointLight* light = nullptr;
};

/// The emitters and targets shared by every photon of a pass.
struct EmissionPlan {
    std::vector<Emitter> emitters;
    std::vector<double> cdf;  ///< Running sums of power, normalised to end at 1.
    std::vector<Target> targets;
};

// [emit]
/// Photon number `index` of `count`: a light chosen in proportion to its power, a point on it
/// and a direction, with flux f(ω) / (p_light · pdf(ω) · count), where f is what the light
/// sends along ω per unit of the point's density. Caustic photons are aimed at the specular
/// objects' bounding spheres (the mixture of their cones); the others leave uniformly (point
/// lights) or with a cosine lobe (panels and balls). Returns false when it carries nothing.
bool emitPhoton(const EmissionPlan& plan, PhotonPaths paths, std::uint64_t index,
                std::uint64_t count, bool stratify, Sampler& sampler, EmittedPhoton& out) {
    // Step 1: choose a light in proportion to its power.
    const double u = sampler.next1D();
    const std::size_t which = std::min<std::size_t>(
        std::upper_bound(plan.cdf.begin(), plan.cdf.end(), u) - plan.cdf.begin(),
        plan.emitters.size() - 1);
    const Emitter& e = plan.emitters[which];
    const double pLight = plan.cdf[which] - (which ? plan.cdf[which - 1] : 0.0);
    // Step 2: a point on the light, and its normal (panels and balls).
    const Vec2 uPoint = sampler.next2D();
    Vec3 origin = e.light->position, normal(0.0);
    if (e.rectangle) {
        const RectangleLight& r = *e.rectangle;
        const Vec3 up = glm::cross(r.normal(), r.left());
        origin += (uPoint.x - 0.5) * r.length() * r.left() + (uPoint.y - 0.5) * r.width() * up;
        normal = r.normal();
    } else if (e.ball) {
        normal = sampleUniformSphere(uPoint.x, uPoint.y);
        origin += e.ball->radius() * normal;
    }
    // Step 3: a direction, stratified over the photon index when asked.
    Vec2 uDir = sampler.next2D();
    const std::uint64_t n = static_cast<std::uint64_t>(std::sqrt(static_cast<double>(count)));
    if (stratify && index < n * n)
        uDir = {((index % n) + uDir.x) / static_cast<double>(n),
                ((index / n) + uDir.y) / static_cast<double>(n)};
    Vec3 direction;
    double pdf = 0.0;
    if (paths == PhotonPaths::Caustic) {
        // Jensen's projection map: towards the specular objects only, a cone to each.
        std::vector<double> cosMax(plan.targets.size());
        double total = 0.0;
        for (std::size_t t = 0; t < plan.targets.size(); ++t) {
            const double d = glm::length(plan.targets[t].centre - origin);
            const double sinMax = d > plan.targets[t].radius ? plan.targets[t].radius / d : 1.0;
            cosMax[t] = d > plan.targets[t].radius ? std::sqrt(1.0 - sinMax * sinMax) : -1.0;
            total += coneSolidAngle(cosMax[t]);
        }
        double pick = sampler.next1D() * total;
        std::size_t t = 0;
        while (t + 1 < plan.targets.size() && pick >= coneSolidAngle(cosMax[t]))
            pick -= coneSolidAngle(cosMax[t++]);
        const Vec3 towards = plan.targets[t].centre - origin;
        const Vec3 axis =
            glm::dot(towards, towards) > 0.0 ? glm::normalize(towards) : Vec3(0.0, 0.0, 1.0);
        direction = sampleUniformCone(axis, cosMax[t], uDir.x, uDir.y);
        // The mixture's density: every cone that holds the direction contributes.
        int holding = 0;
        for (std::size_t k = 0; k < plan.targets.size(); ++k) {
            const Vec3 to = plan.targets[k].centre - origin;
            const double len = glm::length(to);
            if (cosMax[k] <= -1.0 || (len > 0.0 && glm::dot(direction, to) / len >= cosMax[k]))
                ++holding;
        }
        pdf = std::max(1, holding) / total;
    } else if (e.rectangle || e.ball) {
        direction = sampleCosineHemisphere(normal, uDir.x, uDir.y);
        pdf = cosineHemispherePdf(glm::dot(direction, normal));
    } else {
        direction = sampleUniformSphere(uDir.x, uDir.y);
        pdf = uniformSpherePdf();
    }
    // Step 4: what the light sends along the direction: I for a point light; I·cosθ from a
    // panel point (radiance I/A over area A); 4I·cosθ from a ball point (radiance I/(πR²)
    // over area 4πR²).
    Colour f = e.light->colour;
    if (e.rectangle) f *= std::max(0.0, glm::dot(direction, normal));
    if (e.ball) f *= 4.0 * std::max(0.0, glm::dot(direction, normal));
    if (!(pdf > 0.0) || f == Colour(0.0)) return false;
    out = {origin, direction, f / (pLight * pdf * static_cast<double>(count)), e.light};
    return true;
}
// [emit]

/// True when a photon that arrives along a path with `specular` and `diffuse` bounces so far
/// belongs in a map of `paths`.
bool keeps(PhotonPaths paths, bool specular, int diffuse) {
    switch (paths) {
        case PhotonPaths::Caustic:
            return specular && diffuse == 0;
        case PhotonPaths::Indirect:
            return diffuse > 0;
        case PhotonPaths::Direct:
            return !specular && diffuse == 0;
    }
    return false;
}

/// Spread a specular direction into chapter 7's lobe, when the material is glossy there.
/// Returns false when the lobe's sample falls below the surface: the photon is absorbed.
bool spread(const PhotonScattering& s, const Material& m, const Vec3& side, Sampler& sampler,
            Vec3& direction) {
    if (!s.lobe || s.lobe->sampleCount(m) == 0) return true;
    return s.lobe->sample(m, direction, side, sampler, direction);
}

// [trace-photon]
/// Follow one photon from its light, storing it where the map keeps it.
void tracePhoton(const Scene& scene, const PhotonScattering& s, PhotonPaths paths,
                 EmittedPhoton photon, Sampler& sampler, RayCounters& counters,
                 std::vector<Photon>& out) {
    Ray ray{photon.origin, photon.direction};
    Colour flux = photon.flux;
    MediumStack media;
    bool specular = false;
    int diffuse = 0, stored = 0;
    for (int bounce = 0; bounce < kMaxPhotonBounces; ++bounce) {
        Hit hit;
        counters.add(RayKind::Photon);
        if (!scene.aggregate->intersect(ray, std::numeric_limits<double>::infinity(), hit)) return;
        // The light's falloff acts on the way from the light, as it does on shadow rays:
        // a photon carries I·r²/(c0 + c1·r + c2·r²) in place of I.
        if (bounce == 0) {
            const double r = hit.t * glm::length(ray.d);
            const double attenuation = photon.light->falloff.x + photon.light->falloff.y * r +
                                       photon.light->falloff.z * r * r;
            flux *= r * r / attenuation;
        }
        if (!hit.material) return;
        for (const auto& normal : s.pipeline->normals) normal->apply(ray, hit);
        const Material& m = *hit.material;
        const Vec3 d = glm::normalize(ray.d);
        const double transparency = s.refraction ? m.param("transparency") : 0.0;
        // Step 1: store the photon where the surface is diffuse, if this map keeps it.
        if (transparency < 1.0 && std::max(m.kd.r, std::max(m.kd.g, m.kd.b)) > 0.0 &&
            keeps(paths, specular, diffuse)) {
            Photon p;
            for (int a = 0; a < 3; ++a) p.position[a] = static_cast<float>(hit.p[a]);
            packRgbe(flux, p.power, sampler.next1D());
            packDirection(d, p.theta, p.phi);
            p.reserved = 0;
            out.push_back(p);
            if (paths == PhotonPaths::Direct || ++stored == kMaxStoredPerPhoton) return;
        }
        // Step 2: Russian roulette picks what happens next, in the shares the shading uses:
        // the transparent part τ is glass (chapter 5); the opaque part reflects `reflect`
        // (chapter 4) and scatters kd diffusely (chapter 2).
        const Vec3 incident = faceForward(hit.ng, -d);
        Vec3 direction;
        Vec3 side = incident;
        if (sampler.next1D() < transparency) {
            const DielectricSplit split =
                splitAtDielectric(d, hit, m.param("ior", 1.0), media, s.refraction->formulaFor(m));
            if (split.F >= 1.0 || sampler.next1D() < split.F) {
                direction = split.reflected;
            } else {
                direction = split.transmitted;
                side = -incident;
                media = split.media.beyond;
            }
            if (!spread(s, m, side, sampler, direction)) return;
            specular = true;
        } else {
            const double mirror = s.mirrors ? m.param("reflect") : 0.0;
            const double scatter = std::clamp(mean(m.kd), 0.0, 1.0);
            // Shares that add up past 1 (a bright mirror that is also white) are scaled down
            // together; the flux is scaled up to match.
            const double scale = std::max(1.0, mirror + scatter);
            const double u = sampler.next1D() * scale;
            if (u < mirror) {
                direction = glm::normalize(reflect(d, faceForward(hit.ns, -d)));
                if (!spread(s, m, side, sampler, direction)) return;
                flux *= scale;
                specular = true;
            } else if (u < mirror + scatter && paths != PhotonPaths::Caustic) {
                direction = sampleCosineHemisphere(faceForward(hit.ns, -d), sampler.next1D(),
                                                   sampler.next1D());
                if (glm::dot(direction, incident) <= 0.0) return;  // below the true surface
                flux *= m.kd * (scale / scatter);
                ++diffuse;
            } else {
                return;  // absorbed (or a caustic photon's path turned diffuse: its map is done)
            }
        }
        ray = Ray{offsetRayOrigin(hit.p, hit.ng, side), direction};
    }
}
// [trace-photon]

}  // namespace

std::vector<Photon> tracePhotons(const Scene& scene, const PhotonScattering& scattering,
                                 const PhotonTraceSettings& settings, RayCounters& counters) {
    EmissionPlan plan;
    plan.emitters = emittersOf(scene);
    if (settings.paths == PhotonPaths::Caustic) plan.targets = specularTargets(scene, scattering);
    if (plan.emitters.empty() || settings.photons == 0 ||
        (settings.paths == PhotonPaths::Caustic && plan.targets.empty()))
        return {};
    double total = 0.0;
    for (const Emitter& e : plan.emitters) plan.cdf.push_back(total += e.power);
    for (double& c : plan.cdf) c /= total;

    // Chunks of photons in parallel; each chunk's photons in photon order, and the chunks
    // joined in order, so the map is the same for any thread count.
    const std::uint64_t chunks = (settings.photons + kChunk - 1) / kChunk;
    std::vector<std::vector<Photon>> found(chunks);
    std::vector<RayCounters> perThread(omp_get_max_threads());
    const std::uint64_t stream = kPhotonStream + static_cast<std::uint64_t>(settings.pass) * 3 +
                                 static_cast<std::uint64_t>(settings.paths);
#pragma omp parallel for schedule(dynamic, 1)
    for (std::int64_t c = 0; c < static_cast<std::int64_t>(chunks); ++c) {
        RayCounters& rays = perThread[omp_get_thread_num()];
        const std::uint64_t end = std::min(settings.photons, (c + 1) * kChunk);
        for (std::uint64_t k = c * kChunk; k < end; ++k) {
            Sampler sampler(settings.seed, stream, k);
            EmittedPhoton photon;
            if (emitPhoton(plan, settings.paths, k, settings.photons, settings.stratify, sampler,
                           photon))
                tracePhoton(scene, scattering, settings.paths, photon, sampler, rays, found[c]);
        }
    }
    for (const RayCounters& r : perThread) counters.merge(r);
    std::size_t size = 0;
    for (const auto& f : found) size += f.size();
    std::vector<Photon> photons;
    photons.reserve(size);
    for (const auto& f : found) photons.insert(photons.end(), f.begin(), f.end());
    return photons;
}

}  // namespace rb

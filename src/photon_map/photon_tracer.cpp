#include "photon_map/photon_tracer.h"

#include <omp.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <optional>
#include <span>

#include "core/cluster.h"
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
    return specularShare(m) > 0.0;
}

double PhotonScattering::causticShare(const Material& m) const {
    return m.param("caustics", 1.0) != 0.0 ? specularShare(m) : 0.0;
}

bool PhotonScattering::spread(const Material& m, const Vec3& side, Sampler& sampler,
                              Vec3& direction) const {
    if (!lobe || lobe->sampleCount(m) == 0) return true;
    return lobe->sample(m, direction, side, sampler, direction);
}

double PhotonScattering::specularShare(const Material& m) const {
    // The shares tracePhoton's Russian roulette uses: glass takes τ; of the opaque rest, a
    // mirror takes reflect / max(1, reflect + mean(kd)).
    const double transparency = refraction ? std::clamp(m.param("transparency"), 0.0, 1.0) : 0.0;
    const double mirror = mirrors ? std::max(0.0, m.param("reflect")) : 0.0;
    const double scatter = std::clamp((m.kd.r + m.kd.g + m.kd.b) / 3.0, 0.0, 1.0);
    return transparency + (1.0 - transparency) * mirror / std::max(1.0, mirror + scatter);
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

/// A sphere around specular objects, for aiming caustic photons (Jensen's projection map),
/// and the share of the photons that reach them that go on specularly.
struct Target {
    Vec3 centre{0.0};
    double radius = 0.0;
    double share = 0.0;
};

/// Specular instances: their world bounds and the largest specular share of their materials.
struct SpecularPart {
    AABB bounds;
    double share = 0.0;
};

/// The bounding sphere of parts [first, last).
Target boundingTarget(const std::vector<SpecularPart>& parts, std::size_t first, std::size_t last) {
    AABB box;
    for (std::size_t p = first; p < last; ++p) box.extend(parts[p].bounds);
    return {0.5 * (box.lo + box.hi), 0.5 * glm::length(box.hi - box.lo), parts[first].share};
}

/// At most this many targets for the parts of one specular share: a floor of 600 polished
/// tiles is aimed at as 8 patches, not 600 cones (each photon tests every cone).
constexpr std::size_t kTargetsPerShare = 8;

/// Split parts [first, last), all of one share, at the median of their centres along the
/// widest axis, until `leaves` groups remain; each group becomes one target.
void clusterTargets(std::vector<SpecularPart>& parts, std::size_t first, std::size_t last,
                    std::size_t leaves, std::vector<Target>& out) {
    if (leaves <= 1 || last - first <= 1) {
        out.push_back(boundingTarget(parts, first, last));
        return;
    }
    AABB centres;
    for (std::size_t p = first; p < last; ++p) centres.extend(parts[p].bounds.centre());
    const Vec3 extent = centres.hi - centres.lo;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0
                     : extent.y >= extent.z                       ? 1
                                                                  : 2;
    const std::size_t middle = first + (last - first) / 2;
    std::nth_element(parts.begin() + first, parts.begin() + middle, parts.begin() + last,
                     [axis](const SpecularPart& a, const SpecularPart& b) {
                         return a.bounds.centre()[axis] < b.bounds.centre()[axis];
                     });
    clusterTargets(parts, first, middle, leaves / 2, out);
    clusterTargets(parts, middle, last, leaves - leaves / 2, out);
}

/// The targets of caustic photons: the specular instances, grouped by specular share, each
/// share's instances in at most kTargetsPerShare bounding spheres.
std::vector<Target> specularTargets(const Scene& scene, const PhotonScattering& scattering) {
    std::vector<SpecularPart> parts;
    std::vector<const Material*> materials;
    for (const Instance& i : scene.instances) {
        materials.assign(1, i.material);
        i.shape->materials(materials);
        double share = 0.0;
        for (const Material* m : materials)
            if (m) share = std::max(share, scattering.causticShare(*m));
        if (share > 0.0) parts.push_back({i.worldBounds, share});
    }
    // In scene order within a share, so the targets are the same on every run.
    std::stable_sort(parts.begin(), parts.end(), [](const SpecularPart& a, const SpecularPart& b) {
        return a.share > b.share;
    });
    std::vector<Target> targets;
    for (std::size_t first = 0; first < parts.size();) {
        std::size_t last = first;
        while (last < parts.size() && parts[last].share == parts[first].share) ++last;
        clusterTargets(parts, first, last, kTargetsPerShare, targets);
        first = last;
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
        // Jensen's projection map: towards the specular objects only, a cone to each, chosen
        // in proportion to its solid angle Ω times its specular share s (the photons that
        // reach a faint mirror mostly end there; they get fewer of the budget).
        std::vector<double> cosMax(plan.targets.size()), weight(plan.targets.size());
        double total = 0.0;
        for (std::size_t t = 0; t < plan.targets.size(); ++t) {
            const double d = glm::length(plan.targets[t].centre - origin);
            const double sinMax = d > plan.targets[t].radius ? plan.targets[t].radius / d : 1.0;
            cosMax[t] = d > plan.targets[t].radius ? std::sqrt(1.0 - sinMax * sinMax) : -1.0;
            weight[t] = coneSolidAngle(cosMax[t]) * plan.targets[t].share;
            total += weight[t];
        }
        double pick = sampler.next1D() * total;
        std::size_t t = 0;
        while (t + 1 < plan.targets.size() && pick >= weight[t]) pick -= weight[t++];
        const Vec3 towards = plan.targets[t].centre - origin;
        const Vec3 axis =
            glm::dot(towards, towards) > 0.0 ? glm::normalize(towards) : Vec3(0.0, 0.0, 1.0);
        direction = sampleUniformCone(axis, cosMax[t], uDir.x, uDir.y);
        // The mixture's density: Σ over the cones that hold the direction of (w_k / W)(1/Ω_k)
        // = Σ s_k / W.
        double holding = 0.0;
        for (std::size_t k = 0; k < plan.targets.size(); ++k) {
            const Vec3 to = plan.targets[k].centre - origin;
            const double len = glm::length(to);
            if (k == t || cosMax[k] <= -1.0 ||
                (len > 0.0 && glm::dot(direction, to) / len >= cosMax[k]))
                holding += plan.targets[k].share;
        }
        pdf = holding / total;
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
        // Step 2: what happens next, in the shares the shading uses: the transparent part τ
        // is glass (chapter 5); the opaque part reflects `reflect` (chapter 4) and scatters
        // kd diffusely (chapter 2). Shares that add up past 1 (a bright mirror that is also
        // white) are scaled down together.
        const Vec3 incident = faceForward(hit.ng, -d);
        const double mirror = s.mirrors ? m.param("reflect") : 0.0;
        const double scatter = std::clamp(mean(m.kd), 0.0, 1.0);
        const double scale = std::max(1.0, mirror + scatter);
        double u = sampler.next1D();
        if (paths == PhotonPaths::Caustic) {
            // A caustic path ends at its first diffuse bounce, so it always goes on
            // specularly, its flux scaled by the specular share s (not Russian roulette, which
            // would end it with probability 1 − s): with emission in proportion to s too,
            // every stored caustic photon carries the same flux.
            const double share = s.causticShare(m);
            if (!(share > 0.0)) return;
            flux *= share;
            u *= share;
        }
        Vec3 direction;
        Vec3 side = incident;
        if (u < transparency) {
            const DielectricSplit split =
                splitAtDielectric(d, hit, m.param("ior", 1.0), media, s.refraction->formulaFor(m));
            if (split.F >= 1.0 || sampler.next1D() < split.F) {
                direction = split.reflected;
            } else {
                direction = split.transmitted;
                side = -incident;
                media = split.media.beyond;
            }
            if (!s.spread(m, side, sampler, direction)) return;
            specular = true;
        } else {
            // The opaque part: u, rescaled to [0, scale), picks mirror, diffuse or absorbed.
            const double v = (u - transparency) / (1.0 - transparency) * scale;
            if (v < mirror) {
                direction = glm::normalize(reflect(d, faceForward(hit.ns, -d)));
                if (!s.spread(m, side, sampler, direction)) return;
                flux *= scale;
                specular = true;
            } else if (v < mirror + scatter) {
                direction = sampleCosineHemisphere(faceForward(hit.ns, -d), sampler.next1D(),
                                                   sampler.next1D());
                if (glm::dot(direction, incident) <= 0.0) return;  // below the true surface
                flux *= m.kd * (scale / scatter);
                ++diffuse;
            } else {
                return;  // absorbed
            }
        }
        ray = Ray{offsetRayOrigin(hit.p, hit.ng, side), direction};
    }
}
// [trace-photon]

}  // namespace

namespace {

/// The emission plan of a map's paths: every emitter, and for caustics the specular targets.
/// Empty emitters mean the map receives no photons.
EmissionPlan planFor(const Scene& scene, const PhotonScattering& scattering, PhotonPaths paths) {
    EmissionPlan plan;
    plan.emitters = emittersOf(scene);
    if (paths == PhotonPaths::Caustic) plan.targets = specularTargets(scene, scattering);
    if (paths == PhotonPaths::Caustic && plan.targets.empty()) plan.emitters.clear();
    double total = 0.0;
    for (const Emitter& e : plan.emitters) plan.cdf.push_back(total += e.power);
    for (double& c : plan.cdf) c /= total;
    return plan;
}

}  // namespace

std::vector<Photon> tracePhotons(const Scene& scene, const PhotonScattering& scattering,
                                 const PhotonTraceSettings& settings, RayCounters& counters) {
    return std::move(tracePhotonPasses(scene, scattering, {settings}, counters).front());
}

// [trace-passes]
std::vector<std::vector<Photon>> tracePhotonPasses(const Scene& scene,
                                                   const PhotonScattering& scattering,
                                                   const std::vector<PhotonTraceSettings>& passes,
                                                   RayCounters& counters) {
    // Step 1: one emission plan per kind of map, shared by its passes.
    std::array<std::optional<EmissionPlan>, 3> plans;
    auto plan = [&](PhotonPaths paths) -> const EmissionPlan& {
        auto& p = plans[static_cast<int>(paths)];
        if (!p) p = planFor(scene, scattering, paths);
        return *p;
    };
    // Step 2: each pass's chunks of kChunk photons. Many processes: this one traces a
    // contiguous share of each pass's chunks (the others theirs). The chunks of every pass are
    // numbered one after another, from offset[pass], for a single parallel loop over them all.
    std::vector<std::uint64_t> firstChunk(passes.size()), offset(passes.size() + 1, 0);
    for (std::size_t j = 0; j < passes.size(); ++j) {
        const PhotonTraceSettings& s = passes[j];
        const std::uint64_t chunks =
            plan(s.paths).emitters.empty() ? 0 : (s.photons + kChunk - 1) / kChunk;
        std::uint64_t first = 0, last = chunks;
        if (s.cluster && s.cluster->size() > 1) {
            const auto rank = static_cast<std::uint64_t>(s.cluster->rank());
            const auto ranks = static_cast<std::uint64_t>(s.cluster->size());
            first = chunks * rank / ranks;
            last = chunks * (rank + 1) / ranks;
        }
        firstChunk[j] = first;
        offset[j + 1] = offset[j] + (last - first);
    }
    // Step 3: every chunk in parallel; each chunk's photons in photon order, into a vector of
    // its own (neighbouring vectors' headers share cache lines, so they are written once).
    std::vector<std::vector<Photon>> found(offset.back());
    std::vector<RayCounters> perThread(omp_get_max_threads());
#pragma omp parallel for schedule(dynamic, 1)
    for (std::int64_t w = 0; w < static_cast<std::int64_t>(offset.back()); ++w) {
        const std::size_t j =
            std::upper_bound(offset.begin(), offset.end(), static_cast<std::uint64_t>(w)) -
            offset.begin() - 1;
        const PhotonTraceSettings& s = passes[j];
        const EmissionPlan& emission = *plans[static_cast<int>(s.paths)];
        const std::uint64_t stream = kPhotonStream + static_cast<std::uint64_t>(s.pass) * 3 +
                                     static_cast<std::uint64_t>(s.paths);
        const std::uint64_t c = firstChunk[j] + (static_cast<std::uint64_t>(w) - offset[j]);
        RayCounters& rays = perThread[omp_get_thread_num()];
        std::vector<Photon> chunk;
        const std::uint64_t end = std::min(s.photons, (c + 1) * kChunk);
        for (std::uint64_t k = c * kChunk; k < end; ++k) {
            Sampler sampler(s.seed, stream, k);
            EmittedPhoton photon;
            if (emitPhoton(emission, s.paths, k, s.photons, s.stratify, sampler, photon))
                tracePhoton(scene, scattering, s.paths, photon, sampler, rays, chunk);
        }
        found[w] = std::move(chunk);
    }
    for (const RayCounters& r : perThread) counters.merge(r);
    // Step 4: each pass's chunks joined in order, so its map is the same for any thread count;
    // the passes side by side.
    std::vector<std::vector<Photon>> traced(passes.size());
#pragma omp parallel for schedule(dynamic, 1)
    for (std::int64_t j = 0; j < static_cast<std::int64_t>(passes.size()); ++j) {
        std::size_t size = 0;
        for (std::uint64_t w = offset[j]; w < offset[j + 1]; ++w) size += found[w].size();
        traced[j].reserve(size);
        for (std::uint64_t w = offset[j]; w < offset[j + 1]; ++w) {
            traced[j].insert(traced[j].end(), found[w].begin(), found[w].end());
            std::vector<Photon>().swap(found[w]);  // free the chunk: one copy at a time
        }
    }
    // Step 5: many processes: each pass's shares joined in process order are its chunks in
    // order, the map one process traces (outside any parallel region: it talks to the others).
    for (std::size_t j = 0; j < passes.size(); ++j) {
        Cluster* cluster = passes[j].cluster;
        if (!cluster || cluster->size() <= 1) continue;
        const std::vector<std::byte> joined =
            cluster->joinInOrder(std::as_bytes(std::span<const Photon>(traced[j])));
        traced[j].resize(joined.size() / sizeof(Photon));
        std::memcpy(traced[j].data(), joined.data(), joined.size());
    }
    return traced;
}
// [trace-passes]

}  // namespace rb

/// \file
/// Chapter 16's final gather (Jensen 1996): the indirect light at a visible diffuse point, not
/// read from the indirect map right there, but gathered over the hemisphere from what the
/// points it sees send back: their direct light (shadow rays), their caustic and their indirect
/// map. The maps' blotches are then seen only through an average over many rays, which blurs
/// them away, and the direct light at the gathered points, the largest part, is exact.
#include <algorithm>
#include <cmath>

#include "core/material.h"
#include "phong/phong.h"
#include "photon_map/emission.h"
#include "photon_map/photon_map.h"
#include "reflection/reflection.h"
#include "refraction/refraction.h"

namespace rb {

namespace {

/// The most specular bounces one gather ray follows (mirror to mirror, or through glass)
/// before it gives up: a ray that survives 8 bounces carries at most 0.9^8 = 43% of its light
/// in the chapter's scene, and is rare (each bounce continues only with the specular share's
/// probability).
constexpr int kMaxSpecularBounces = 8;

/// The gather rays that read the indirect map: one in kMapEvery, each counting kMapEvery
/// times. The direct light, which every ray measures, is most of what comes back; the map's
/// density estimates cost the most (three quarters of the time when every ray read it).
constexpr int kMapEvery = 4;

/// A gather ray shorter than this many of the indirect map's radii does not read the map where
/// it lands but goes on one more diffuse bounce: near an edge or in a corner the gather disc
/// hangs over empty space and reads low (ch16-limits), and the rays from a point near a corner
/// land near that corner.
constexpr double kShortGather = 2.0;

/// Diffuse bounces a short gather ray may add.
constexpr int kShortBounces = 2;

/// A material with kd = 1 and no highlight: Phong's shading of it is the irradiance of the
/// direct light (Σ visible · I(r) · cos θ), in A4's units.
Material unitDiffuse() {
    Material m;
    m.kd = Colour(1.0);
    return m;
}

}  // namespace

// [final-gather]
Colour PhotonMapping::gatherIrradiance(const ShadeContext& ctx, const Hit& hit, const Vec3& n,
                                       int rays) const {
    // Step 1: the rays' directions, stratified: a grid of columns × rows cells over the square
    // that sampleCosineHemisphere warps, one ray in each, columns the largest divisor of N
    // up to √N (4 × 8 for 32 rays). A prime N above 3 takes ⌊√N⌋² cells, the rest anywhere.
    int columns = static_cast<int>(std::sqrt(static_cast<double>(rays)));
    while (rays % columns != 0) --columns;
    int rows = rays / columns;
    if (columns == 1 && rays > 3)
        rows = columns = static_cast<int>(std::sqrt(static_cast<double>(rays)));
    const int cells = columns * rows;
    // Step 2: which pass each ray reads: a random first pass, then one after another, so that
    // every pass is read equally often and the mean over the rays estimates the mean over the
    // passes, as the direct read does. And which rays read the maps at all: the cells on every
    // kMapEvery-th diagonal from a random first one, so that each cell does with probability
    // 1/kMapEvery and the readers spread over both of the square's axes.
    const std::size_t passes = indirect_.grids.size();
    const std::size_t firstPass =
        std::min(passes - 1, static_cast<std::size_t>(ctx.sampler.next1D() * passes));
    const int firstReader =
        std::min(kMapEvery - 1, static_cast<int>(ctx.sampler.next1D() * kMapEvery));
    const Vec3 ng = faceForward(hit.ng, n);
    Colour sum(0.0);
    for (int j = 0; j < rays; ++j) {
        const Vec2 u = ctx.sampler.next2D();
        const int column = j % columns, row = j / columns;
        const Vec2 cell = j < cells ? Vec2((column + u.x) / columns, (row + u.y) / rows) : u;
        const Vec3 direction = sampleCosineHemisphere(n, cell.x, cell.y);
        if (glm::dot(direction, ng) <= 0.0) continue;  // below the true surface: no light
        const std::size_t pass = (firstPass + static_cast<std::size_t>(j)) % passes;
        const double mapWeight = (column + row + firstReader) % kMapEvery == 0 ? kMapEvery : 0.0;
        sum += gatherRadiance(ctx, Ray{offsetRayOrigin(hit.p, ng, direction), direction}, pass,
                              mapWeight, kShortBounces);
    }
    // Step 3: cosine-weighted rays make the estimate the plain mean: E = ∫ L cos θ dω and
    // pdf = cos θ / π, with A4's pixel values π L (see ch16-units), so E ≈ (1/N) Σ π L_j.
    return sum / static_cast<double>(rays);
}

Colour PhotonMapping::gatherRadiance(const ShadeContext& ctx, Ray ray, std::size_t pass,
                                     double mapWeight, int bounces) const {
    static const Material kUnitDiffuse = unitDiffuse();
    const Pipeline& pipeline = ctx.integrator.pipeline();
    MediumStack media = ctx.media;
    Colour throughput(1.0), sum(0.0);
    double length = 0.0;  // from the last diffuse surface
    for (int bounce = 0; bounce < kMaxSpecularBounces; ++bounce) {
        Hit y;
        ctx.counters.add(RayKind::Photon);  // counted with the photons: this chapter's rays
        if (!ctx.scene.aggregate->intersect(ray, std::numeric_limits<double>::infinity(), y) ||
            !y.material)
            break;  // the background lights nothing in A4
        for (const auto& normal : pipeline.normals) normal->apply(ray, y);
        const Material& own = *y.material;
        const Vec3 d = glm::normalize(ray.d);
        length += y.t * glm::length(ray.d);
        const double transparency = glass_ ? own.param("transparency") : 0.0;
        // Step 1: the diffuse part, (1 − τ) kd E, with E = its direct light (Phong's shading of
        // a white diffuse material, with every shadow ray), its caustic and its indirect light:
        // every path that reaches it, so the gathered light is exactly the L (S|D)* D S* paths
        // of the indirect map at the visible point, no more and no less.
        if (transparency < 1.0) {
            const Colour kd = pipeline.textureLookup && !own.textures.empty()
                                  ? pipeline.textureLookup(y).kd
                                  : own.kd;
            if (kd != Colour(0.0)) {
                const Colour albedo = (1.0 - transparency) * kd;
                const Vec3 ny = faceForward(y.ns, -d);
                Hit white = y;
                white.material = &kUnitDiffuse;
                const ShadeContext direct{ctx.scene,     ctx.integrator, ctx.sampler, ctx.counters,
                                          ctx.depth + 1, media,          ctx.weight,  false};
                Colour e = pipeline.surface(direct, ray, white);
                // Its caustic, by every ray: a bright caustic is a small, strong source seen
                // by few rays, and a quarter of them at four times the weight would speckle.
                e += caustics_.passIrradiance(y.p, ny, settings_.nearest, pass);
                if (mapWeight > 0.0) {
                    // Step 1a: the indirect light at y: the map, unless y is so close that
                    // the map's disc there may hang over an edge; then one more diffuse
                    // bounce, cosine-weighted, whose gather reads every map.
                    const double r = indirect_.radii[pass % indirect_.radii.size()];
                    if (length < kShortGather * r && bounces > 0) {
                        const Vec3 ngy = faceForward(y.ng, -d);
                        const Vec2 u = ctx.sampler.next2D();
                        const Vec3 next = sampleCosineHemisphere(ny, u.x, u.y);
                        if (glm::dot(next, ngy) > 0.0)
                            e += mapWeight *
                                 gatherRadiance(ctx, Ray{offsetRayOrigin(y.p, ngy, next), next},
                                                pass, 1.0, bounces - 1);
                    } else {
                        e += mapWeight * indirect_.passIrradiance(y.p, ny, settings_.nearest, pass);
                    }
                }
                sum += throughput * albedo * e;
            }
        }
        // Step 2: the specular part goes on, in the photon tracer's shares: glass with
        // probability τ (then reflected with Fresnel's F), else a mirror with probability
        // min(reflect, 1), its weight reflect / min(reflect, 1).
        const Vec3 incident = faceForward(y.ng, -d);
        const double mirror = scattering_.mirrors ? own.param("reflect") : 0.0;
        const double v = ctx.sampler.next1D();
        Vec3 next;
        Vec3 side = incident;
        if (v < transparency) {
            const DielectricSplit split = splitAtDielectric(
                d, y, own.param("ior", 1.0), media, scattering_.refraction->formulaFor(own));
            if (split.F >= 1.0 || ctx.sampler.next1D() < split.F) {
                next = split.reflected;
            } else {
                next = split.transmitted;
                side = -incident;
                media = split.media.beyond;
            }
        } else if ((v - transparency) / (1.0 - transparency) < std::min(mirror, 1.0)) {
            next = glm::normalize(reflect(d, faceForward(y.ns, -d)));
            throughput *= mirror / std::min(mirror, 1.0);
        } else {
            break;  // the rest was diffuse (added above) or absorbed
        }
        if (!scattering_.spread(own, side, ctx.sampler, next)) break;
        ray = Ray{offsetRayOrigin(y.p, y.ng, side), next};
    }
    return sum;
}
// [final-gather]

}  // namespace rb

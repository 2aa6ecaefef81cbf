#include "media/participating_media.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"
#include "media/henyey_greenstein.h"

namespace rb {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kInfinity = std::numeric_limits<double>::infinity();
/// The most times one ray is followed through one boundary; a closed shape a ray crosses
/// more often than this (a very wrinkled mesh) is taken as left after the last.
constexpr int kMaxCrossings = 64;

/// The largest channel.
double maxChannel(const Colour& c) {
    return std::max({c.r, c.g, c.b});
}

/// Where the ray crosses the surface of `boundary`, from t = 0 to infinity, in order.
int crossings(const Instance& boundary, const Ray& ray, double* ts) {
    double lo = 0.0, hi = kInfinity;
    if (!clipToBox(ray, boundary.worldBounds, lo, hi)) return 0;
    int count = 0;
    Ray r = ray;
    double base = 0.0;
    ObjectHit hit;
    while (count < kMaxCrossings && boundary.intersect(r, kInfinity, hit)) {
        base += hit.t;
        ts[count++] = base;
        // Go on from just beyond the surface, on the side the ray goes to.
        const Vec3 p = r.o + hit.t * r.d;
        const Vec3 n = boundary.normalToWorld * hit.n;
        r.o = offsetRayOrigin(p, n, r.d);
    }
    return count;
}

}  // namespace

ParticipatingMedia::ParticipatingMedia(std::vector<Instance> boundaries, const Medium* fog,
                                       const AABB& fogBox, const MediaSettings& settings)
    : boundaries_(std::move(boundaries)), fogBox_(fogBox), settings_(settings) {
    if (boundaries_.size() > 63)
        throw InputError("at most 63 nodes may hold a medium, the scene has " +
                         std::to_string(boundaries_.size()));
    for (const Instance& b : boundaries_) {
        // The density lives in the node's space: the shape's space, then its placement.
        const Mat4 placement = b.mediumPlacement ? *b.mediumPlacement : Mat4(1.0);
        AABB box;
        const AABB shapeBox = b.shape->bounds();
        for (int corner = 0; corner < 8; ++corner)
            box.extend(transformPoint(placement, Vec3(corner & 1 ? shapeBox.hi.x : shapeBox.lo.x,
                                                      corner & 2 ? shapeBox.hi.y : shapeBox.lo.y,
                                                      corner & 4 ? shapeBox.hi.z : shapeBox.lo.z)));
        tracked_.push_back(std::make_unique<TrackedMedium>(*b.medium, placement * b.worldToObject,
                                                           box, settings_.majorantResolution));
    }
    if (fog) {
        tracked_.push_back(
            std::make_unique<TrackedMedium>(*fog, Mat4(1.0), fogBox, settings_.majorantResolution));
        fog_ = tracked_.back().get();
    }
}

// [media-pieces]
void ParticipatingMedia::pieces(const Ray& ray, double tEnd, std::vector<Piece>& out) const {
    out.clear();
    // Step 1: every boundary's crossings. An odd count to infinity means the ray starts
    // inside (the camera in the fog box, a ray leaving a surface in the smoke).
    struct Crossing {
        double t;
        int region;
    };
    std::vector<Crossing> events;
    std::uint64_t inside = 0;
    double ts[kMaxCrossings];
    for (size_t r = 0; r < boundaries_.size(); ++r) {
        const int n = crossings(boundaries_[r], ray, ts);
        if (n % 2 == 1) inside |= std::uint64_t{1} << r;
        for (int k = 0; k < n && ts[k] < tEnd; ++k) events.push_back({ts[k], static_cast<int>(r)});
    }
    std::sort(events.begin(), events.end(),
              [](const Crossing& a, const Crossing& b) { return a.t < b.t; });
    // Step 2: between crossings, the medium of the latest node that holds the point (a node
    // nested in another comes later in the scene graph, so it wins inside); none: the fog.
    double fog0 = 0.0, fog1 = tEnd;
    const bool fogHere = fog_ && clipToBox(ray, fogBox_, fog0, fog1);
    auto emit = [&](double a, double b, std::uint64_t mask) {
        if (mask != 0) {
            const int region = 63 - __builtin_clzll(mask);
            if (a < b) out.push_back({a, b, tracked_[region].get()});
        } else if (fogHere) {
            a = std::max(a, fog0);
            b = std::min(b, fog1);
            if (a < b) out.push_back({a, b, fog_});
        }
    };
    double t = 0.0;
    for (const Crossing& e : events) {
        emit(t, e.t, inside);
        inside ^= std::uint64_t{1} << e.region;
        t = e.t;
    }
    emit(t, tEnd, inside);
}
// [media-pieces]

// [media-track]
FreeFlight::Event ParticipatingMedia::track(const ShadeContext& ctx, const Ray& ray, double tEnd,
                                            Colour& beta, Vec3& x, const Medium*& m) const {
    std::vector<Piece> stretches;
    pieces(ray, tEnd, stretches);
    for (const Piece& piece : stretches) {
        const FreeFlight flight =
            sampleFreeFlight(*piece.medium, ray, piece.t0, piece.t1, ctx.sampler);
        if (flight.event == FreeFlight::Event::Absorbed) return flight.event;
        beta *= flight.weight;
        if (flight.event == FreeFlight::Event::Scattered) {
            x = ray.o + flight.t * ray.d;
            m = &piece.medium->medium;
            return flight.event;
        }
    }
    return FreeFlight::Event::None;
}
// [media-track]

// [media-segment]
Colour ParticipatingMedia::segment(const ShadeContext& ctx, const Ray& ray, double tEnd,
                                   Colour& throughput) const {
    Colour beta(1.0), radiance(0.0);
    if (settings_.march) {
        // Ray marching: single scattering along every piece; the surface is seen through
        // what is left.
        std::vector<Piece> stretches;
        pieces(ray, tEnd, stretches);
        for (const Piece& piece : stretches) {
            radiance += march(ctx, ray, piece, beta);
            if (!(maxChannel(beta) > 0.0)) break;
        }
        throughput = beta;
        return radiance;
    }
    // A path through the media, one scattering after another (a loop, not recursion: a dense
    // cloud scatters light hundreds of times before it leaves).
    throughput = Colour(0.0);
    Ray r = ray;
    double end = tEnd;
    Hit hit;
    bool found = false;
    for (int bounce = 0;; ++bounce) {
        Vec3 x;
        const Medium* m = nullptr;
        const FreeFlight::Event event = track(ctx, r, end, beta, x, m);
        if (event == FreeFlight::Event::Absorbed) return radiance;
        if (event == FreeFlight::Event::None) {
            // The path leaves the media: the first ray's surface is the caller's to shade;
            // a scattered ray's surface (or the background) is shaded here.
            if (bounce == 0) {
                throughput = beta;
                return radiance;
            }
            const ShadeContext next{ctx.scene,
                                    ctx.integrator,
                                    ctx.sampler,
                                    ctx.counters,
                                    ctx.depth + 1,
                                    ctx.media,
                                    ctx.weight * maxChannel(beta),
                                    false};
            return radiance +
                   beta * (found ? ctx.integrator.shade(next, r, hit) : ctx.scene.background);
        }
        // Step 1: a particle at x scatters the lights' light towards us (single scattering),
        // and at the path's first scattering A4's ambient light, which stands for all the
        // indirect light: the rest of the path must not count it again.
        const Vec3 travel = glm::normalize(r.d);
        radiance += beta * lightScattered(ctx, x, travel, *m);
        if (bounce == 0 && ctx.ambient) radiance += beta * ctx.scene.ambient;
        // Step 2: and light from one direction the phase function draws (its pdf cancels the
        // phase function), until the path has scattered `bounces` more times.
        if (bounce >= settings_.bounces || ctx.weight * maxChannel(beta) < ctx.scene.minWeight)
            return radiance;
        r = Ray{x, sampleHenyeyGreenstein(travel, m->g, ctx.sampler.next2D())};
        ctx.counters.add(RayKind::Scatter);
        found = ctx.scene.aggregate->intersect(r, std::numeric_limits<double>::infinity(), hit);
        end = found ? hit.t : std::numeric_limits<double>::infinity();
    }
}
// [media-segment]

// [media-light-scattered]
Colour ParticipatingMedia::lightScattered(const ShadeContext& ctx, const Vec3& x,
                                          const Vec3& travel, const Medium& m) const {
    Colour light(0.0);
    for (const PointLight& source : ctx.scene.lights) {
        const bool area = source.shape && ctx.scene.sampleAreaLights;
        const int perAxis = !area                        ? 1
                            : ctx.scene.lightSamples > 0 ? ctx.scene.lightSamples
                                                         : source.shape->samplesPerAxis();
        Colour sum(0.0);
        for (int k = 0; k < perAxis * perAxis; ++k) {
            double emission = 1.0;
            const Vec3 from = area ? source.shape->samplePoint(source.position, x, k, perAxis,
                                                               ctx.sampler.next2D(), emission)
                                   : source.position;
            const Vec3 toLight = from - x;
            const double r = glm::length(toLight);
            if (!(r > 0.0) || emission <= 0.0) continue;
            if (ctx.integrator.occluded(Ray{x, toLight}, 1.0, ctx.counters)) continue;
            // A4's lights are in units where a white diffuse surface returns I cos θ / r²,
            // π times a physical point light's: the phase function is scaled to match.
            const double phase = kPi * henyeyGreenstein(glm::dot(travel, toLight / r), m.g);
            sum += emission * source.intensityAt(r) * phase *
                   transmittance(x, from, ctx.sampler, ctx.counters);
        }
        light += sum / static_cast<double>(perAxis * perAxis);
    }
    return light;
}
// [media-light-scattered]

// [media-march]
Colour ParticipatingMedia::march(const ShadeContext& ctx, const Ray& ray, const Piece& piece,
                                 Colour& tr) const {
    const Medium& m = piece.medium->medium;
    const Ray local = piece.medium->toMedium(ray);
    const double length = glm::length(ray.d);
    const double dt = settings_.step / length;
    const Vec3 travel = ray.d / length;
    Colour scattered(0.0);
    // Each step's point stands for the whole step: light scattered there, seen through the
    // medium so far, then the step's own extinction.
    for (double t = piece.t0 + ctx.sampler.next1D() * dt; t < piece.t1; t += dt) {
        const double density = m.density->at(local.o + t * local.d);
        if (!(density > 0.0)) continue;
        const Vec3 x = ray.o + t * ray.d;
        // Single scattering only: each step's particle is a path's one scattering, so it
        // counts A4's ambient light (which arrives from every direction alike, and the phase
        // function integrates to 1), as a white diffuse surface returns kd · ambient.
        const Colour ambient = ctx.ambient ? ctx.scene.ambient : Colour(0.0);
        scattered += tr * m.sigmaS * density * settings_.step *
                     (ambient + lightScattered(ctx, x, travel, m));
        tr *= beerLambert(m.sigmaT() * density, settings_.step);
        if (!(maxChannel(tr) > 0.0)) break;
    }
    return scattered;
}
// [media-march]

// [media-interaction]
bool ParticipatingMedia::sampleInteraction(const ShadeContext& ctx, const Ray& ray, double tEnd,
                                           Colour& beta, Interaction& interaction) const {
    // Chapter 18's path loop asks only where a path scatters; this chapter's free flights
    // answer (delta tracking, whatever --media says: ray marching has no free flights).
    Vec3 x;
    const Medium* m = nullptr;
    const FreeFlight::Event event = track(ctx, ray, tEnd, beta, x, m);
    if (event == FreeFlight::Event::None) return false;
    if (event == FreeFlight::Event::Absorbed) {
        beta = Colour(0.0);
        return true;
    }
    interaction.x = x;
    interaction.g = m->g;
    return true;
}

double ParticipatingMedia::phase(double g, const Vec3& travel, const Vec3& out) const {
    return henyeyGreenstein(glm::dot(travel, out), g);
}

Vec3 ParticipatingMedia::samplePhase(double g, const Vec3& travel, const Vec2& u) const {
    return sampleHenyeyGreenstein(travel, g, u);
}
// [media-interaction]

// [media-transmittance]
Colour ParticipatingMedia::transmittance(const Vec3& a, const Vec3& b, Sampler& sampler,
                                         RayCounters&) const {
    const Ray ray{a, b - a};
    std::vector<Piece> stretches;
    pieces(ray, 1.0, stretches);
    const TransmittanceMethod method =
        settings_.march ? TransmittanceMethod::March : settings_.shadows;
    Colour tr(1.0);
    for (const Piece& piece : stretches) {
        tr *= estimateTransmittance(*piece.medium, ray, piece.t0, piece.t1, method, settings_.step,
                                    sampler);
        if (!(maxChannel(tr) > 0.0)) break;
    }
    return tr;
}
// [media-transmittance]

}  // namespace rb

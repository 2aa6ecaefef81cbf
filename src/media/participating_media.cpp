#include "media/participating_media.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"
#include "media/equiangular.h"
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

/// A bound on the largest factor by which the linear part A of `m` stretches a vector, ‖A‖₂:
/// the root of Gershgorin's bound on the largest eigenvalue of AᵀA (exact for a rotation
/// times a uniform scale, where AᵀA = s²I).
double linearNormBound(const Mat4& m) {
    const glm::dmat3 a(m);
    const glm::dmat3 ata = glm::transpose(a) * a;
    double largest = 0.0;
    for (int i = 0; i < 3; ++i)
        largest =
            std::max(largest, std::abs(ata[i][0]) + std::abs(ata[i][1]) + std::abs(ata[i][2]));
    return std::sqrt(largest);
}

/// Where the ray crosses the surface of `boundary`, from t = 0 to infinity, in order.
int crossings(const Instance& boundary, const Ray& ray, double* ts) {
    double lo = 0.0, hi = kInfinity;
    if (!clipToBox(ray, boundary.worldBounds, lo, hi)) return 0;
    int count = 0;
    const bool convex = boundary.shape->convex();
    Ray r = ray;
    double base = 0.0;
    ObjectHit hit;
    while (count < kMaxCrossings && boundary.intersect(r, kInfinity, hit)) {
        base += hit.t;
        ts[count++] = base;
        // Go on from just beyond the surface, on the side the ray goes to.
        const Vec3 p = r.o + hit.t * r.d;
        const Vec3 n = boundary.normalToWorld * hit.n;
        // A convex shape, once left, is left for good: no need to look again (a walk through
        // a ball of milk asks this twice a scattering).
        if (convex && glm::dot(n, r.d) > 0.0) break;
        r.o = offsetRayOrigin(p, n, r.d);
    }
    return count;
}

/// Where single-scattering points go on one homogeneous piece of a ray, for one light. A light
/// that falls off as 1/r² near the ray gets equiangular points, which cancel the falloff; one
/// without falloff (A4's default, (1, 0, 0)) gets points spread as the piece's transmittance
/// from its start, a truncated exponential, which is all that varies along the ray then.
struct PiecePoints {
    EquiangularSegment seg;  ///< The piece in world distances along the ray, and the light.
    double sigma;            ///< The piece's extinction majorant, per unit length.
    bool equiangular;
    double reach;  ///< The chance that a flight from the piece's start meets a particle in it.

    /// One point on the piece: its distance s, its density there, and `fall`, the majorant's
    /// transmittance e^{−σ̄(s − a)} from the piece's start to it (which the flight's density and,
    /// in a grey medium, the light's way back to the ray's origin both need).
    struct Point {
        double s, pdf, fall;
    };
    Point sample(double u) const {
        if (equiangular) {
            const EquiangularSample e = sampleEquiangular(seg, u);
            return {e.s, e.pdf, std::exp(-sigma * (e.s - seg.a))};
        }
        // The truncated exponential's inverse: e^{−σ̄(s − a)} = 1 − u·reach, no exp needed.
        const double fall = 1.0 - u * reach;
        const double s = seg.a - std::log1p(-u * reach) / sigma;
        return {std::min(s, seg.b), sigma * fall / reach, fall};
    }
    /// The point at distance s, as sample would have drawn it.
    Point at(double s) const {
        const double fall = std::exp(-sigma * (s - seg.a));
        return {s, equiangular ? equiangularPdf(seg, s) : sigma * fall / reach, fall};
    }
};

/// How the points of `light` are placed on `piece` of `ray`.
PiecePoints piecePoints(const Ray& ray, const ParticipatingMedia::Piece& piece,
                        const PointLight& light) {
    const double length = glm::length(ray.d);
    const Vec3 u = ray.d / length;
    const Vec3 toLight = light.position - ray.o;
    const double delta = glm::dot(toLight, u);
    const double a = piece.t0 * length, b = piece.t1 * length;
    // A light on the ray's own line has h = 0, where the density has a pole: keep it a hair off
    // the line, which changes only how the points are spread, not what they estimate.
    const double h = std::max(glm::length(toLight - delta * u), 1e-9 * (b - a + std::abs(delta)));
    // Equiangular where the falloff c0 + c1 r + c2 r² is mostly its r² term at the ray's
    // nearest point; a medium thin enough to need no exponential gets uniform points that way.
    const Vec3 c = light.falloff;
    const double sigma = piece.medium->medium.sigmaTMax();
    const bool equiangular = c.z * h * h >= c.x + c.y * h || !(sigma * (b - a) > 1e-9);
    return {{a, b, delta, h}, sigma, equiangular, -std::expm1(-sigma * (b - a))};
}

/// The lamp points' share of single scattering at `point`, when they are `points` to the free
/// flight's one (the balance heuristic: each technique's density times its number of samples,
/// over their sum). The flight's density, per unit world length, is σs e^{−σ̄ d} at distance d
/// into the piece, with the largest channels (the tracking majorant σ̄ and σs) standing for all
/// three; only the weights use it.
double balanceShare(const Medium& m, const PiecePoints::Point& point, double points) {
    const double own = points * point.pdf;
    return own / (own + maxChannel(m.sigmaS) * point.fall);
}

/// The transmittance e^{−σt d} of a homogeneous medium over the distance whose majorant
/// transmittance is `fall`: `fall` itself when the medium is grey (σt = σ̄ in every channel).
Colour transmittanceFrom(const Medium& m, double d, double fall) {
    const Colour sigmaT = m.sigmaT();
    if (sigmaT.r == sigmaT.g && sigmaT.g == sigmaT.b) return Colour(fall);
    return beerLambert(sigmaT, d);
}

/// How soft the spread of a heterogeneous piece's points is: e^{−α τ̄} with α below 1, since
/// the majorant's optical depth τ̄ overstates the true one (by 2.7 on the plume at 16³ cells).
constexpr double kMajorantSoftening = 0.5;

/// Where single-scattering points go on one heterogeneous piece of a ray, for a light without
/// falloff: with density α σ̄(t) e^{−α τ̄(t)} / (1 − e^{−α τ̄(t1)}) per unit t, σ̄ the majorant grid's
/// bound per unit t and τ̄ its optical depth from the piece's start (piecewise linear, one
/// piece per cell), so the points follow the majorant's transmittance, softened by α.
struct MajorantPoints {
    /// One majorant cell along the ray: from a to b, σ̄ per unit t, and τ̄ at a.
    struct Cell {
        double a, b, mu, depth;
    };
    std::vector<Cell> cells;
    double total = 0.0;  ///< τ̄ at the piece's end.

    MajorantPoints(const TrackedMedium& m, const Ray& ray, double t0, double t1) {
        const double sigmaTMax = m.medium.sigmaTMax() * glm::length(ray.d);
        m.majorants.traverse(m.toMedium(ray), t0, t1, [&](double a, double b, double bound) {
            const double mu = bound * sigmaTMax;
            if (mu > 0.0) {
                cells.push_back({a, b, mu, total});
                total += mu * (b - a);
            }
            return true;
        });
    }
    /// The point for u in [0, 1), and its density per unit t (by inverting τ̄ in the cells).
    std::pair<double, double> sample(double u) const {
        const double alpha = kMajorantSoftening, reach = -std::expm1(-alpha * total);
        const double depth = std::min(-std::log1p(-u * reach) / alpha, total);
        auto cell = std::upper_bound(cells.begin(), cells.end(), depth,
                                     [](double d, const Cell& c) { return d < c.depth; });
        --cell;  // The last cell that starts at or before the depth.
        const double t = std::min(cell->a + (depth - cell->depth) / cell->mu, cell->b);
        return {t, alpha * cell->mu * std::exp(-alpha * depth) / reach};
    }
};

/// Points per axis at which a scattering samples `source`: n × n on an area light, 1 on a
/// point light.
int lightSamplesPerAxis(const ShadeContext& ctx, const PointLight& source) {
    if (!(source.shape && ctx.scene.sampleAreaLights)) return 1;
    return ctx.scene.lightSamples > 0 ? ctx.scene.lightSamples : source.shape->samplesPerAxis();
}

/// The first of an area light's n × n strata for a ray's lamp points (point k samples stratum
/// first + k, modulo n²): uniform, so each point's one sample stands for the whole light. A
/// point light has one stratum and draws no number.
int firstStratum(const ShadeContext& ctx, const PointLight& source) {
    const int n = lightSamplesPerAxis(ctx, source);
    if (n == 1) return 0;
    return std::min(n * n - 1, static_cast<int>(ctx.sampler.next1D() * (n * n)));
}

}  // namespace

ParticipatingMedia::ParticipatingMedia(std::vector<Instance> boundaries, const Medium* fog,
                                       const AABB& fogBox, const MediaSettings& settings,
                                       const std::vector<AABB>& everything)
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
    if (!settings_.nearFlights) return;
    for (std::size_t k = 0; k < boundaries_.size(); ++k) {
        const Instance& b = boundaries_[k];
        if (!b.shape->convex() || !b.medium->homogeneous()) continue;
        // Lone: the only instance whose bounds meet its own (itself).
        const auto meets = [&](const AABB& o) {
            return glm::all(glm::lessThanEqual(o.lo, b.worldBounds.hi)) &&
                   glm::all(glm::lessThanEqual(b.worldBounds.lo, o.hi));
        };
        if (std::count_if(everything.begin(), everything.end(), meets) != 1) continue;
        lone_.push_back({tracked_[k].get(), &b, 1.0 / linearNormBound(b.worldToObject)});
    }
}

// [media-pieces]
template <class Visit>
void ParticipatingMedia::forEachPiece(const Ray& ray, double tEnd, Visit&& visit) const {
    // Step 1: every boundary's crossings. An odd count to infinity means the ray starts
    // inside (the camera in the fog box, a ray leaving a surface in the smoke). They are kept
    // on the stack while they fit: a walk through a dense cloud asks this twice a scattering.
    struct Crossing {
        double t;
        int region;
    };
    constexpr int kOnStack = 16;
    Crossing onStack[kOnStack];
    std::vector<Crossing> onHeap;
    int count = 0;
    auto add = [&](const Crossing& c) {
        if (count < kOnStack) {
            onStack[count++] = c;
            return;
        }
        if (onHeap.empty()) onHeap.assign(onStack, onStack + kOnStack);
        onHeap.push_back(c);
        ++count;
    };
    std::uint64_t inside = 0;
    double ts[kMaxCrossings];
    for (size_t r = 0; r < boundaries_.size(); ++r) {
        const int n = crossings(boundaries_[r], ray, ts);
        if (n % 2 == 1) inside |= std::uint64_t{1} << r;
        for (int k = 0; k < n && ts[k] < tEnd; ++k) add({ts[k], static_cast<int>(r)});
    }
    Crossing* events = count <= kOnStack ? onStack : onHeap.data();
    std::sort(events, events + count,
              [](const Crossing& a, const Crossing& b) { return a.t < b.t; });
    // Step 2: between crossings, the medium of the latest node that holds the point (a node
    // nested in another comes later in the scene graph, so it wins inside); none: the fog.
    double fog0 = 0.0, fog1 = tEnd;
    const bool fogHere = fog_ && clipToBox(ray, fogBox_, fog0, fog1);
    auto emit = [&](double a, double b, std::uint64_t mask) {
        if (mask != 0) {
            const int region = 63 - __builtin_clzll(mask);
            if (a < b) return visit(Piece{a, b, tracked_[region].get()});
        } else if (fogHere) {
            a = std::max(a, fog0);
            b = std::min(b, fog1);
            if (a < b) return visit(Piece{a, b, fog_});
        }
        return true;
    };
    double t = 0.0;
    for (int k = 0; k < count; ++k) {
        if (!emit(t, events[k].t, inside)) return;
        inside ^= std::uint64_t{1} << events[k].region;
        t = events[k].t;
    }
    emit(t, tEnd, inside);
}

void ParticipatingMedia::pieces(const Ray& ray, double tEnd, std::vector<Piece>& out) const {
    out.clear();
    forEachPiece(ray, tEnd, [&](const Piece& piece) {
        out.push_back(piece);
        return true;
    });
}
// [media-pieces]

// [media-track]

FreeFlight::Event ParticipatingMedia::track(const ShadeContext& ctx, const Ray& ray,
                                            const std::vector<Piece>& stretches, Colour& beta,
                                            Vec3& x, const Medium*& m, FlightSite& site) const {
    for (const Piece& piece : stretches) {
        const FreeFlight flight =
            sampleFreeFlight(*piece.medium, ray, piece.t0, piece.t1, ctx.sampler);
        if (flight.event == FreeFlight::Event::Absorbed) return flight.event;
        beta *= flight.weight;
        if (flight.event == FreeFlight::Event::Scattered) {
            x = ray.o + flight.t * ray.d;
            m = &piece.medium->medium;
            site = {&ray, piece, flight.t, site.points};
            return flight.event;
        }
    }
    return FreeFlight::Event::None;
}
// [media-track]

// [media-first-flight]
FreeFlight::Event ParticipatingMedia::firstFlight(const ShadeContext& ctx, const Ray& ray,
                                                  const std::vector<Piece>& stretches, Colour& beta,
                                                  Vec3& x, const Medium*& m, FlightSite& site,
                                                  Colour& throughput) const {
    const bool closedForm = std::all_of(stretches.begin(), stretches.end(), [](const Piece& p) {
        return p.medium->medium.homogeneous() && std::isfinite(p.t1);
    });
    if (!closedForm) {
        // Delta tracking: the surface is seen exactly when the flight meets no particle.
        const FreeFlight::Event event = track(ctx, ray, stretches, beta, x, m, site);
        throughput = event == FreeFlight::Event::None ? beta : Colour(0.0);
        return event;
    }
    // Step 1: the surface beyond, seen through the pieces' closed-form transmittance.
    const double length = glm::length(ray.d);
    double total = 0.0;  // The ray's optical depth under the pieces' majorants.
    throughput = Colour(1.0);
    for (const Piece& p : stretches) {
        const Medium& medium = p.medium->medium;
        total += medium.sigmaTMax() * (p.t1 - p.t0) * length;
        throughput *= beerLambert(medium.sigmaT(), (p.t1 - p.t0) * length);
    }
    if (!(total > 0.0)) return FreeFlight::Event::None;
    // Step 2: an optical depth τ drawn from the exponential cut off at the total, which
    // the path meets with probability `reach` = 1 − e^{−total}.
    const double reach = -std::expm1(-total);
    const double depth = -std::log1p(-ctx.sampler.next1D() * reach);
    // Step 3: the piece and the distance at that depth; the path's weight is
    // T(0, t) σs / pdf(t), pdf(t) = σ̄ e^{−τ} / reach per channel (σs/σt · reach in grey fog).
    double left = depth;
    Colour seen(1.0);
    for (const Piece& p : stretches) {
        const Medium& medium = p.medium->medium;
        const double sigma = medium.sigmaTMax(), d = (p.t1 - p.t0) * length;
        if (left < sigma * d) {
            const double into = left / sigma;
            const double t = p.t0 + into / length;
            beta *= seen * beerLambert(medium.sigmaT(), into) * medium.sigmaS *
                    (reach / (sigma * std::exp(-depth)));
            x = ray.o + t * ray.d;
            m = &medium;
            site = {&ray, p, t, site.points};
            return FreeFlight::Event::Scattered;
        }
        left -= sigma * d;
        seen *= beerLambert(medium.sigmaT(), d);
    }
    return FreeFlight::Event::None;  // Rounding put the depth just past the last piece.
}
// [media-first-flight]

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
    Ray r = ray;
    double end = tEnd;
    Hit hit;
    bool found = false;
    std::vector<Piece> stretches;
    // The walk's guess of the largest transmittance to a light at its next scattering
    // (walkLight): 1 until a shadow ray has measured it.
    double shadowGuess = 1.0;
    const TrackedMedium* at = nullptr;  // The medium of the last scattering.
    for (int bounce = 0;; ++bounce) {
        Vec3 x;
        const Medium* m = nullptr;
        // Only the first ray takes lamp points: on the later rays of a walk through thin fog
        // they cost more than they save (chapter 17's scene: 2.4 times the time for a tenth
        // less error).
        const double points = bounce == 0 ? settings_.pointsPerRay : 0.0;
        FlightSite site{nullptr, {}, 0.0, points};
        FreeFlight::Event event = FreeFlight::Event::None;
        bool anyTracked = false;
        Colour seen(1.0);
        if (bounce == 0 || !nearFlight(ctx, r, at, beta, x, m, site, event)) {
            // Step 0: the surface this ray reaches (the first ray's is the caller's), the media
            // along it, and single scattering towards the lights at points placed for each
            // (equiangular, or by transmittance), weighted against what the free flight of
            // step 1 finds (multiple importance sampling).
            if (bounce > 0) {
                found = ctx.scene.aggregate->intersect(r, kInfinity, hit);
                end = found ? hit.t : kInfinity;
            }
            pieces(r, end, stretches);
            // On heterogeneous pieces the points carry all the single scattering (and A4's
            // ambient light), and their ratio-tracking passes show the surface beyond (`seen`)
            // in place of the free flight's coin toss.
            const auto tracked = [&](const Piece& p) { return trackedOn(p, points); };
            anyTracked = !ctx.scene.lights.empty() &&
                         std::any_of(stretches.begin(), stretches.end(), tracked);
            if (points > 0 && settings_.direct != MediaDirect::FreeFlight)
                radiance +=
                    beta * pointsScattered(ctx, r, stretches, points, anyTracked ? &seen : nullptr);
            // A path that may not scatter again needs no free flight where nothing is left to
            // it.
            if (anyTracked && settings_.bounces == 0 &&
                std::all_of(stretches.begin(), stretches.end(), [&](const Piece& p) {
                    return tracked(p) || !(maxChannel(p.medium->medium.sigmaS) > 0.0);
                })) {
                throughput = seen;
                return radiance;
            }
            event = bounce == 0 ? firstFlight(ctx, r, stretches, beta, x, m, site, throughput)
                                : track(ctx, r, stretches, beta, x, m, site);
        }
        if (anyTracked) throughput = seen;
        if (event == FreeFlight::Event::Absorbed) return radiance;
        if (event == FreeFlight::Event::None) {
            // The path leaves the media: the first ray's surface is the caller's to shade,
            // through `throughput`; a scattered ray's surface (or the background) is shaded
            // here.
            if (bounce == 0) return radiance;
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
        at = site.piece.medium;
        // Step 1: a particle at x scatters the lights' light towards us (single scattering,
        // each light's MIS share), and at the path's first scattering A4's ambient light, which
        // stands for all the indirect light: the rest of the path must not count it again.
        const Vec3 travel = glm::normalize(r.d);
        radiance += beta * (bounce == 0 ? lightScattered(ctx, x, travel, *m, &site)
                                        : walkLight(ctx, r.o, x, travel, *m, shadowGuess));
        if (bounce == 0 && ctx.ambient && !(anyTracked && trackedOn(site.piece, points)))
            radiance += beta * ctx.scene.ambient;
        // Step 2: and light from one direction the phase function draws (its pdf cancels the
        // phase function), until the path has scattered `bounces` more times.
        if (bounce >= settings_.bounces || ctx.weight * maxChannel(beta) < ctx.scene.minWeight)
            return radiance;
        r = Ray{x, sampleHenyeyGreenstein(travel, m->g, ctx.sampler.next2D())};
        ctx.counters.add(RayKind::Scatter);
    }
}

bool ParticipatingMedia::nearFlight(const ShadeContext& ctx, const Ray& ray,
                                    const TrackedMedium* at, Colour& beta, Vec3& x,
                                    const Medium*& m, FlightSite& site,
                                    FreeFlight::Event& event) const {
    const auto lone =
        std::find_if(lone_.begin(), lone_.end(), [&](const Lone& l) { return l.medium == at; });
    if (lone == lone_.end()) return false;
    // Step 1: how far the boundary is at least, in the ray's parameter.
    const Instance& b = *lone->boundary;
    const double depth = b.shape->depthInside(transformPoint(b.worldToObject, ray.o)) *
                         lone->worldPerObject / glm::length(ray.d);
    if (!(depth > 0.0)) return false;
    // Step 2: the flight over [0, depth), which is the full flight's start: the same piece
    // (its medium from t = 0 to beyond depth), so the same numbers give the same flight.
    Sampler copy = ctx.sampler;
    const FreeFlight flight = sampleFreeFlight(*at, ray, 0.0, depth, copy);
    if (flight.event == FreeFlight::Event::None) return false;
    ctx.sampler = copy;
    event = flight.event;
    if (event == FreeFlight::Event::Absorbed) return true;
    beta *= flight.weight;
    x = ray.o + flight.t * ray.d;
    m = &at->medium;
    site = {&ray, {0.0, depth, at}, flight.t, 0.0};
    return true;
}
// [media-segment]

// [media-light-scattered]
Colour ParticipatingMedia::lightScattered(const ShadeContext& ctx, const Vec3& x,
                                          const Vec3& travel, const Medium& m,
                                          const FlightSite* site) const {
    Colour light(0.0);
    for (const PointLight& source : ctx.scene.lights) {
        const double share =
            site ? 1.0 - pointsShare(*site->ray, site->piece, site->t, source, site->points) : 1.0;
        if (share > 0.0) light += share * lightFrom(ctx, source, x, travel, m);
    }
    return light;
}

Colour ParticipatingMedia::walkLight(const ShadeContext& ctx, const Vec3& previous, const Vec3& x,
                                     const Vec3& travel, const Medium& m, double& guess) const {
    // Step 1: the guess grows by e^{σ̄ ℓ} over the flight of length ℓ from the previous
    // scattering, as much as a flight straight towards the light would gain (a guess where the
    // medium curves or changes: the roulette's weight keeps the mean whatever it guesses).
    guess = std::min(1.0, guess * std::exp(m.sigmaTMax() * glm::length(x - previous)));
    // Step 2: where the light is likely far out of reach, this scattering's shadow rays are
    // played for by Russian roulette, before any is traced.
    const double chance = std::clamp(guess / kShadowRouletteBelow, kLeastShadowChance, 1.0);
    if (chance < 1.0 && ctx.sampler.next1D() >= chance) return Colour(0.0);
    // Step 3: each light's shadow rays (their own roulette on the transmittance they measure),
    // which set the next guess.
    Colour light(0.0);
    double largest = 0.0;
    for (const PointLight& source : ctx.scene.lights)
        light += lightFrom(ctx, source, x, travel, m, true, &largest);
    guess = largest;
    return light / chance;
}

double shadowRayChance(const Colour& tr) {
    return std::min(1.0, maxChannel(tr) / kShadowRouletteBelow);
}

Colour ParticipatingMedia::lightFrom(const ShadeContext& ctx, const PointLight& source,
                                     const Vec3& x, const Vec3& travel, const Medium& m,
                                     bool roulette, double* largest, int stratum) const {
    const bool area = source.shape && ctx.scene.sampleAreaLights;
    const int perAxis = lightSamplesPerAxis(ctx, source);
    // All n × n points, or the one of them a lamp point takes.
    const int first = stratum < 0 ? 0 : stratum % (perAxis * perAxis);
    const int end = stratum < 0 ? perAxis * perAxis : first + 1;
    Colour sum(0.0);
    for (int k = first; k < end; ++k) {
        double emission = 1.0;
        const Vec3 from = area ? source.shape->samplePoint(source.position, x, k, perAxis,
                                                           ctx.sampler.next2D(), emission)
                               : source.position;
        const Vec3 toLight = from - x;
        const double r = glm::length(toLight);
        if (!(r > 0.0) || emission <= 0.0) continue;
        // A4's lights are in units where a white diffuse surface returns I cos θ / r², π
        // times a physical point light's: the phase function is scaled to match.
        const double phase = kPi * henyeyGreenstein(glm::dot(travel, toLight / r), m.g);
        if (roulette) {
            // On a walk the transmittance comes first (closed form through homogeneous
            // media): deep in a cloud it is e^{−σt d}, next to nothing, and the shadow ray
            // that would confirm it is played for by Russian roulette.
            const Colour tr = transmittance(x, from, ctx.sampler, ctx.counters);
            if (largest) *largest = std::max(*largest, maxChannel(tr));
            const double keep = shadowRayChance(tr);
            if (!(keep > 0.0) || (keep < 1.0 && ctx.sampler.next1D() >= keep)) continue;
            if (ctx.integrator.occluded(Ray{x, toLight}, 1.0, ctx.counters)) continue;
            sum += emission * source.intensityAt(r) * phase * tr / keep;
            continue;
        }
        if (ctx.integrator.occluded(Ray{x, toLight}, 1.0, ctx.counters)) continue;
        sum += emission * source.intensityAt(r) * phase *
               transmittance(x, from, ctx.sampler, ctx.counters);
    }
    return sum / static_cast<double>(end - first);
}
// [media-light-scattered]

// [media-equiangular]
bool ParticipatingMedia::pointsOn(const Piece& piece, double points) const {
    const Medium& m = piece.medium->medium;
    return points > 0 && settings_.direct != MediaDirect::FreeFlight && !settings_.march &&
           maxChannel(m.sigmaS) > 0.0;
}

bool ParticipatingMedia::trackedOn(const Piece& piece, double points) const {
    return pointsOn(piece, points) && !piece.medium->medium.homogeneous();
}

double ParticipatingMedia::pointsShare(const Ray& ray, const Piece& piece, double t,
                                       const PointLight& light, double points) const {
    if (!pointsOn(piece, points)) return 0.0;
    // A free flight's density in a heterogeneous piece is unknown, so no MIS there: its points
    // carry all of its single scattering.
    if (settings_.direct == MediaDirect::LightPoints || trackedOn(piece, points)) return 1.0;
    const PiecePoints place = piecePoints(ray, piece, light);
    return balanceShare(piece.medium->medium, place.at(t * glm::length(ray.d)), points);
}

Colour ParticipatingMedia::pointsScattered(const ShadeContext& ctx, const Ray& ray,
                                           const std::vector<Piece>& stretches, double points,
                                           Colour* seen) const {
    if (ctx.scene.lights.empty()) return Colour(0.0);
    // Only pieces up to the last one with points matter, unless the transmittance to the end
    // is asked for.
    size_t last = stretches.size();
    for (size_t k = 0; k < stretches.size(); ++k)
        if (pointsOn(stretches[k], points)) last = k;
    if (seen) last = stretches.empty() ? stretches.size() : stretches.size() - 1;
    if (last == stretches.size()) return Colour(0.0);
    const Vec3 travel = glm::normalize(ray.d);
    Colour tr(1.0), light(0.0);
    for (size_t k = 0; k <= last; ++k) {
        const Piece& piece = stretches[k];
        const Medium& m = piece.medium->medium;
        if (trackedOn(piece, points)) {
            // A heterogeneous piece: its points read one ratio-tracking pass, which also
            // carries `tr` through it.
            light += trackedScattered(ctx, ray, piece, points, tr);
            if (!(maxChannel(tr) > 0.0)) break;
            continue;
        }
        if (pointsOn(piece, points)) {
            for (const PointLight& source : ctx.scene.lights) {
                const PiecePoints place = piecePoints(ray, piece, source);
                // Step 1: `points` of them (a whole number), each sampling one stratum of an
                // area light: the points average over the light as they average over the ray.
                const int n = static_cast<int>(points);
                const int stratum = firstStratum(ctx, source);
                for (int k = 0; k < n; ++k) {
                    // Step 2: a point on the piece, where this light's single scattering is
                    // (the points stratified: one in each equal share of the distribution).
                    const double u = (k + ctx.sampler.next1D()) / n;
                    const PiecePoints::Point e = place.sample(u);
                    const double t = e.s / glm::length(ray.d);
                    const double share = settings_.direct == MediaDirect::LightPoints
                                             ? 1.0
                                             : balanceShare(m, e, points);
                    if (!(e.pdf > 0.0) || !(share > 0.0)) continue;
                    // Step 3: the light it scatters towards the ray's origin, seen through the
                    // media before it (closed form in this piece), over the point's density.
                    const Colour back = tr * transmittanceFrom(m, e.s - place.seg.a, e.fall);
                    light += back * m.sigmaS * (share / (points * e.pdf)) *
                             lightFrom(ctx, source, ray.o + t * ray.d, travel, m, false, nullptr,
                                       stratum + k);
                }
            }
        }
        // Step 3: what gets through this piece, for the pieces beyond it.
        if (k < last || seen)
            tr *= m.homogeneous()
                      ? beerLambert(m.sigmaT(), (piece.t1 - piece.t0) * glm::length(ray.d))
                      : estimateTransmittance(*piece.medium, ray, piece.t0, piece.t1,
                                              settings_.shadows, settings_.step, ctx.sampler);
        if (!(maxChannel(tr) > 0.0)) break;
    }
    if (seen) *seen = tr;
    return light;
}
// [media-equiangular]

// [media-tracked]
Colour ParticipatingMedia::trackedScattered(const ShadeContext& ctx, const Ray& ray,
                                            const Piece& piece, double points, Colour& tr) const {
    const Medium& m = piece.medium->medium;
    const double length = glm::length(ray.d);
    const Vec3 travel = ray.d / length;
    // Step 1: each light's points on the piece, stratified as on a homogeneous piece:
    // equiangular for a light that falls off, else spread as the majorant's transmittance.
    struct Point {
        double t;
        double pdf;  // Per unit world length.
        const PointLight* light;
        int stratum;  // The area light's stratum it samples (lightFrom).
    };
    std::vector<Point> spots;
    const MajorantPoints spread(*piece.medium, ray, piece.t0, piece.t1);
    if (spread.total > 0.0)
        for (const PointLight& source : ctx.scene.lights) {
            const PiecePoints place = piecePoints(ray, piece, source);
            const int n = static_cast<int>(points);
            const int stratum = firstStratum(ctx, source);
            for (int k = 0; k < n; ++k) {
                const double u = (k + ctx.sampler.next1D()) / n;
                if (place.equiangular) {
                    const EquiangularSample e = sampleEquiangular(place.seg, u);
                    spots.push_back({e.s / length, e.pdf, &source, stratum + k});
                } else {
                    const auto [t, pdf] = spread.sample(u);
                    spots.push_back({t, pdf / length, &source, stratum + k});
                }
            }
        }
    std::sort(spots.begin(), spots.end(), [](const Point& a, const Point& b) { return a.t < b.t; });
    // Step 2: one ratio-tracking pass along the piece, read at every point: the collisions do
    // not depend on the points, so each read's expectation is the transmittance to its point.
    std::vector<double> at(spots.size());
    std::vector<Colour> trAt(spots.size());
    for (size_t i = 0; i < spots.size(); ++i) at[i] = spots[i].t;
    const int count = static_cast<int>(at.size());
    const Colour through = exactOn(*piece.medium, settings_.shadows)
                               ? exactTransmittance(*piece.medium, ray, piece.t0, piece.t1,
                                                    at.data(), trAt.data(), count)
                               : ratioTrackReading(*piece.medium, ray, piece.t0, piece.t1,
                                                   at.data(), trAt.data(), count, ctx.sampler);
    // Step 3: the light each point scatters towards the ray's origin, over its density; a point
    // the pass did not reach, or in empty space, needs no shadow ray.
    const Ray local = piece.medium->toMedium(ray);
    Colour light(0.0);
    for (size_t i = 0; i < spots.size(); ++i) {
        if (!(maxChannel(trAt[i]) > 0.0) || !(spots[i].pdf > 0.0)) continue;
        const double density = m.density->at(local.o + spots[i].t * local.d);
        if (!(density > 0.0)) continue;
        light += trAt[i] * m.sigmaS * (density / (points * spots[i].pdf)) *
                 lightFrom(ctx, *spots[i].light, ray.o + spots[i].t * ray.d, travel, m, false,
                           nullptr, spots[i].stratum);
    }
    // Step 4: A4's ambient light scattered once along the piece needs no points: the density
    // scales σs and σt alike, so ∫ σs ρ T dt = σs/σt (1 − T(t1)), read from the same pass.
    if (ctx.ambient) {
        const Colour st = m.sigmaT(), ss = m.sigmaS;
        const Colour albedo(st.r > 0.0 ? ss.r / st.r : 0.0, st.g > 0.0 ? ss.g / st.g : 0.0,
                            st.b > 0.0 ? ss.b / st.b : 0.0);
        light += ctx.scene.ambient * albedo * (Colour(1.0) - through);
    }
    const Colour seenBefore = tr;
    tr *= through;
    return seenBefore * light;
}
// [media-tracked]

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
    FlightSite site{};
    std::vector<Piece> stretches;
    pieces(ray, tEnd, stretches);
    const FreeFlight::Event event = track(ctx, ray, stretches, beta, x, m, site);
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
    return transmittanceAlong(Ray{a, b - a}, 1.0, sampler);
}

Colour ParticipatingMedia::transmittanceAlong(const Ray& ray, double tEnd, Sampler& sampler) const {
    const TransmittanceMethod method =
        settings_.march ? TransmittanceMethod::March : settings_.shadows;
    Colour tr(1.0);
    forEachPiece(ray, tEnd, [&](const Piece& piece) {
        tr *= estimateTransmittance(*piece.medium, ray, piece.t0, piece.t1, method, settings_.step,
                                    sampler);
        return maxChannel(tr) > 0.0;
    });
    return tr;
}
// [media-transmittance]

}  // namespace rb

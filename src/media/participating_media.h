/// \file
/// ParticipatingMedia: chapter 17's term in the integrator. It finds which medium fills each
/// stretch of a ray, tracks light through it, and scatters towards the lights.
#pragma once

#include <memory>
#include <vector>

#include "core/instance.h"
#include "core/integrator.h"
#include "media/tracking.h"

namespace rb {

/// Where single scattering towards A4's lights is sampled along a ray in a homogeneous medium.
enum class MediaDirect {
    Mis,          ///< Both below, weighted by the balance heuristic (the default).
    FreeFlight,   ///< Only where the free flight scatters.
    LightPoints,  ///< Only at points placed for each light (free flights carry the path on).
};

/// Below this transmittance to a light, a shadow ray from a walk's later scatterings is traced
/// only by Russian roulette (shadowRayChance): deep in a dense cloud nearly all are.
constexpr double kShadowRouletteBelow = 0.05;

/// The chance that a walk's shadow ray of transmittance `tr` is traced: 1 from
/// kShadowRouletteBelow up (in the largest channel), in proportion below, so that a traced
/// ray's tr / chance is kShadowRouletteBelow, never more than an untouched ray carries.
double shadowRayChance(const Colour& tr);

/// The least chance with which a walk's scattering traces its shadow rays, however far out of
/// reach the walk guesses the light is (walkLight): a wrong guess weighs at most 1 / this.
constexpr double kLeastShadowChance = 0.02;

/// The largest --media-bounces, and the default: a safety net, not a model (a unit ball of
/// σs = 100 scatters a path about ten thousand times).
constexpr int kMaxMediaBounces = 1000000;

/// How a render treats its media: gr.option values, overridden by the command line.
struct MediaSettings {
    bool march = false;  ///< Ray marching (single scattering only) instead of tracking.
    TransmittanceMethod shadows = TransmittanceMethod::Exact;  ///< Shadow-ray estimator.
    double step = 0.0;  ///< Marching step in world units; 0: 1/400 of the fog box diagonal.
    int majorantResolution = 16;  ///< Majorant grid cells per axis.
    /// Scatterings a path may take in media after the first (0: single scattering only). By
    /// default no cap a scene meets: a walk ends where it leaves the media, is absorbed or
    /// weighs less than the scene's min_weight (a cap of 256 darkened a dense ball by 2.1%).
    int bounces = kMaxMediaBounces;
    MediaDirect direct = MediaDirect::Mis;  ///< Where single scattering is sampled.
    /// Lamp points per lamp per pixel, shared among the pixel's samples (--media-points).
    int points = 64;
    /// Lamp points per lamp along a path's first ray: points / samples per pixel rounded, and
    /// at least 1 (its later rays take none).
    double pointsPerRay = 4.0;
    /// A walk's flight that ends deep inside a lone medium skips the scene (nearFlight);
    /// --media-near-flights off traces every flight, for the same image, slower.
    bool nearFlights = true;
};

/// The media of one render: the closed shapes that bound media (node:set_medium) and the fog
/// (gr.fog) that fills all space outside them, within the scene's bounds.
class ParticipatingMedia final : public MediaTerm {
  public:
    /// `boundaries` are the instances whose medium is set, in the scene graph's order (a node's
    /// medium nested under another's comes later and wins inside it). `fogBox` is where fog
    /// ends: beyond it rays reach the background. `everything` holds the world bounds of every
    /// instance, boundaries included: a boundary whose bounds meet no other's is lone.
    ParticipatingMedia(std::vector<Instance> boundaries, const Medium* fog, const AABB& fogBox,
                       const MediaSettings& settings, const std::vector<AABB>& everything = {});
    Colour segment(const ShadeContext& ctx, const Ray& ray, double tEnd,
                   Colour& throughput) const override;
    Colour transmittance(const Vec3& a, const Vec3& b, Sampler& sampler,
                         RayCounters& counters) const override;
    bool sampleInteraction(const ShadeContext& ctx, const Ray& ray, double tEnd, Colour& beta,
                           Interaction& interaction) const override;
    double phase(double g, const Vec3& travel, const Vec3& out) const override;
    Vec3 samplePhase(double g, const Vec3& travel, const Vec2& u) const override;

    /// One stretch of a ray inside one medium (or in none: medium == nullptr).
    struct Piece {
        double t0, t1;
        const TrackedMedium* medium;
    };
    /// The stretches of the ray between t = 0 and tEnd, in order; empty space is left out.
    void pieces(const Ray& ray, double tEnd, std::vector<Piece>& out) const;
    /// The same stretches, each passed to `visit` in order, until it returns false (no list
    /// is built: a shadow ray needs none).
    template <class Visit>
    void forEachPiece(const Ray& ray, double tEnd, Visit&& visit) const;

    /// Where a free flight scattered: the ray, the piece and the parameter t, which the
    /// multiple importance sampling weights need.
    struct FlightSite {
        const Ray* ray;
        Piece piece;
        double t;
        double points;  ///< Lamp points per lamp on that ray (0: none).
    };

    /// The light that a particle at x of medium m scatters along the unit direction `travel`
    /// reversed from every light, through attenuated shadow rays (single scattering). With a
    /// free flight's `site`, each light's share is its MIS weight against equiangular
    /// sampling; without one (ray marching), all of it. A4's ambient light is the caller's to
    /// add, once per path.
    Colour lightScattered(const ShadeContext& ctx, const Vec3& x, const Vec3& travel,
                          const Medium& m, const FlightSite* site = nullptr) const;
    /// lightScattered on a walk's later scatterings (no lamp points there, so no MIS share):
    /// x reached by a flight from `previous`. `guess` is the walk's guess of the largest
    /// transmittance to a light here, from the last shadow rays: below kShadowRouletteBelow
    /// the shadow rays are traced only with a chance (at least kLeastShadowChance), their light
    /// divided by it; they set the next guess.
    Colour walkLight(const ShadeContext& ctx, const Vec3& previous, const Vec3& x,
                     const Vec3& travel, const Medium& m, double& guess) const;

  private:
    /// A homogeneous medium inside a convex boundary whose bounds meet no other instance's:
    /// from a point inside it, no surface and no other medium is nearer than its boundary.
    struct Lone {
        const TrackedMedium* medium;
        const Instance* boundary;
        /// World length per unit of object length, at least, in any direction: 1 / ‖A‖ for
        /// the linear part A of the boundary's world-to-object transform.
        double worldPerObject;
    };
    /// A walk's flight along `ray` from a scattering in `at` (the previous flight's medium),
    /// when it ends nearer than the lone medium's boundary: then no surface or other medium
    /// can lie before it, and the scene and the pieces are not asked (a walk through milk
    /// scatters hundreds of times, nearly all deep inside). It draws the numbers the full
    /// flight would draw, from a copy of the sampler, which it keeps only when the flight ends
    /// there: the image is the same bits either way. False when it does not apply.
    bool nearFlight(const ShadeContext& ctx, const Ray& ray, const TrackedMedium* at, Colour& beta,
                    Vec3& x, const Medium*& m, FlightSite& site, FreeFlight::Event& event) const;
    /// What a ray meets in the media along `stretches` (its pieces): nothing (`beta` holds the
    /// transmittance), absorption, or a scattering at x in medium m (`beta` holds the path's
    /// weight), at `site`.
    FreeFlight::Event track(const ShadeContext& ctx, const Ray& ray,
                            const std::vector<Piece>& stretches, Colour& beta, Vec3& x,
                            const Medium*& m, FlightSite& site) const;
    /// The first ray's flight (track's part for a path's first ray). Where every piece is
    /// homogeneous, the surface beyond is seen through the closed-form transmittance
    /// (`throughput`) and the path scatters at a distance drawn from the exponential cut off at
    /// the pieces' end, weighted by the chance it stands for (forced scattering): neither part
    /// is a coin toss. Elsewhere delta tracking decides between them.
    FreeFlight::Event firstFlight(const ShadeContext& ctx, const Ray& ray,
                                  const std::vector<Piece>& stretches, Colour& beta, Vec3& x,
                                  const Medium*& m, FlightSite& site, Colour& throughput) const;
    /// The transmittance along the ray from t = 0 to tEnd: closed form in homogeneous pieces,
    /// the shadow-ray estimator in the others.
    Colour transmittanceAlong(const Ray& ray, double tEnd, Sampler& sampler) const;
    /// The light of one source, scattered at x along `travel` reversed (lightScattered's term).
    /// With `roulette` (a walk's later scatterings), a shadow ray whose transmittance is below
    /// kShadowRouletteBelow is traced with the chance shadowRayChance, its light divided by it,
    /// and `largest` (if given) becomes at least the largest transmittance measured. An area
    /// light is sampled at its n × n points, or with `stratum` ≥ 0 (a lamp point's) at point
    /// stratum mod n² alone, which stands for the whole light when the caller draws it
    /// uniformly.
    Colour lightFrom(const ShadeContext& ctx, const PointLight& source, const Vec3& x,
                     const Vec3& travel, const Medium& m, bool roulette = false,
                     double* largest = nullptr, int stratum = -1) const;
    /// Single scattering towards every light along the ray's `stretches`, at `points` stratified
    /// points per light on each piece (equiangular, or by transmittance for a light without
    /// falloff): on a homogeneous piece MIS-weighted against free flights, on a heterogeneous
    /// one all of it (trackedScattered). With `seen`, the transmittance to the ray's end too.
    Colour pointsScattered(const ShadeContext& ctx, const Ray& ray,
                           const std::vector<Piece>& stretches, double points,
                           Colour* seen = nullptr) const;
    /// Single scattering towards every light and of A4's ambient light on one heterogeneous
    /// piece, from `points` points per light read off one ratio-tracking pass along it; `tr`,
    /// the transmittance before the piece, is carried through it by the same pass.
    Colour trackedScattered(const ShadeContext& ctx, const Ray& ray, const Piece& piece,
                            double points, Colour& tr) const;
    /// True when single scattering on `piece` is sampled at lamp points, `points` per lamp (0
    /// on the later rays of a path).
    bool pointsOn(const Piece& piece, double points) const;
    /// True when `piece` is heterogeneous and sampled at lamp points: they carry all of its
    /// single scattering, and free flights none.
    bool trackedOn(const Piece& piece, double points) const;
    /// The light points' share of single scattering towards `light` at parameter t of `piece`,
    /// when they are `points` to the free flight's one: 0 where only free flights sample it, 1
    /// where only light points do.
    double pointsShare(const Ray& ray, const Piece& piece, double t, const PointLight& light,
                       double points) const;
    /// Ray marching through one piece: the single-scattered light it adds, and `tr` dimmed.
    Colour march(const ShadeContext& ctx, const Ray& ray, const Piece& piece, Colour& tr) const;

    std::vector<Instance> boundaries_;
    std::vector<std::unique_ptr<TrackedMedium>> tracked_;  ///< One per boundary, then the fog.
    const TrackedMedium* fog_ = nullptr;
    std::vector<Lone> lone_;  ///< The lone media (nearFlight), usually none or a few.
    AABB fogBox_;
    MediaSettings settings_;
};

}  // namespace rb

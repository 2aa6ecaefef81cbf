/// \file
/// Tracking: how far light travels in a medium before it meets a particle, and how much of it
/// gets through (chapter 17). Delta tracking samples free flights, ratio tracking estimates
/// transmittance, and ray marching is the lesson's first, biased step.
#pragma once

#include "core/ray.h"
#include "core/sampler.h"
#include "media/majorant_grid.h"
#include "media/medium.h"

namespace rb {

/// One medium as a ray meets it: its coefficients, the map from world space to the medium's
/// own space (where its density lives) and the majorants of its density.
struct TrackedMedium {
    TrackedMedium(const Medium& medium, const Mat4& worldToMedium, const AABB& shapeBox,
                  int majorantResolution);
    const Medium& medium;
    Mat4 worldToMedium;
    MajorantGrid majorants;
    /// The ray in the medium's space: the same parameter t names the same point.
    Ray toMedium(const Ray& worldRay) const {
        return {transformPoint(worldToMedium, worldRay.o),
                transformVector(worldToMedium, worldRay.d)};
    }
};

/// What a ray meets on its way from t0 to t1 through a medium.
struct FreeFlight {
    enum class Event { None, Scattered, Absorbed };
    Event event = Event::None;
    double t = 0.0;      ///< Where it scattered.
    Colour weight{1.0};  ///< Throughput from t0 to the event (or to t1 when there is none).
};

/// Follow a ray from t0 to t1 by delta tracking against the majorant grid (spectral tracking
/// for coloured media: one path carries all three channels, weighted).
/// Source: Woodcock et al. 1965; Kutz, Habel, Li and Novák, "Spectral and decomposition
/// tracking for rendering heterogeneous volumes", SIGGRAPH 2017, section 4.
FreeFlight sampleFreeFlight(const TrackedMedium& m, const Ray& ray, double t0, double t1,
                            Sampler& sampler);

/// How a shadow ray's transmittance is estimated.
enum class TransmittanceMethod {
    Exact,  ///< The optical depth integrated exactly where the density allows (a voxel grid),
            ///< else ratio tracking.
    Ratio,  ///< Ratio tracking: the product of 1 − μt/μ̄ at each tentative collision.
    Delta,  ///< Delta tracking: 1 if the ray meets no real particle, else 0.
    March,  ///< Ray marching with a fixed step: biased, the baseline.
};

/// The transmittance from t0 to t1 (closed form e^{−σt·d} in a homogeneous medium; otherwise
/// the method's estimate). `step` is the marching step in world units.
/// Source: Novák, Selle and Jarosz, "Residual ratio tracking for estimating attenuation in
/// participating media", SIGGRAPH Asia 2014 (ratio tracking, eq. 7).
Colour estimateTransmittance(const TrackedMedium& m, const Ray& ray, double t0, double t1,
                             TransmittanceMethod method, double step, Sampler& sampler);

/// Ratio tracking from t0 to t1, as estimateTransmittance's Ratio method, that also reads its
/// running product at the parameters `at` (`count` of them, sorted, in [t0, t1]) into `trAt`:
/// the product over the tentative collisions before each. The collisions do not depend on where
/// they are read, so each read is an unbiased estimate of the transmittance from t0 to its
/// parameter, as the result is to t1. Below kRouletteBelow the product plays Russian roulette
/// (it survives with chance product / kRouletteBelow, then worth kRouletteBelow), so a walk
/// into a thick cloud ends, and the reads past its end cost no shadow ray.
/// Source: Novák, Selle and Jarosz 2014 (ratio tracking); Russian roulette keeps each read's
/// expectation (Arvo and Kirk, "Particle transport and image synthesis", SIGGRAPH 1990).
Colour ratioTrackReading(const TrackedMedium& m, const Ray& ray, double t0, double t1,
                         const double* at, Colour* trAt, int count, Sampler& sampler);

/// The transmittance from t0 to t1 of a medium whose density integrates exactly along a line
/// (DensityField::integrable(), a voxel grid), and from t0 to each of the `count` sorted
/// parameters `at` (into trAt): e^{−σt τ} with τ the optical depth, no estimate. Only the
/// majorant grid's non-empty cells are integrated.
Colour exactTransmittance(const TrackedMedium& m, const Ray& ray, double t0, double t1,
                          const double* at, Colour* trAt, int count);
/// True when the transmittance through `m` by `method` is exactTransmittance's.
bool exactOn(const TrackedMedium& m, TransmittanceMethod method);
/// Where ratioTrackReading starts Russian roulette: a product below this.
constexpr double kRouletteBelow = 0.05;

/// The exact transmittance of a homogeneous medium over a world length d: e^{−σt d} per
/// channel (Beer–Lambert).
Colour beerLambert(const Colour& sigmaT, double d);

}  // namespace rb

#include "media/tracking.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace rb {

namespace {

/// The largest channel.
double maxChannel(const Colour& c) {
    return std::max({c.r, c.g, c.b});
}

/// True when the three channels are equal.
bool grey(const Colour& c) {
    return c.r == c.g && c.g == c.b;
}

/// The next tentative collision after t with majorant mu per unit of t: an exponential step.
double nextCollision(double t, double mu, Sampler& sampler) {
    return t - std::log(1.0 - sampler.next1D()) / mu;
}

}  // namespace

TrackedMedium::TrackedMedium(const Medium& medium_, const Mat4& worldToMedium_,
                             const AABB& shapeBox, int majorantResolution)
    : medium(medium_),
      worldToMedium(worldToMedium_),
      majorants(
          *medium_.density,
          [&] {
              // Track only where the density and the medium's shape overlap.
              AABB box = medium_.density->bounds();
              box.lo = glm::max(box.lo, shapeBox.lo);
              box.hi = glm::min(box.hi, shapeBox.hi);
              return box;
          }(),
          majorantResolution) {}

Colour beerLambert(const Colour& sigmaT, double d) {
    // Grey media (most of them) need one exponential, not three.
    if (grey(sigmaT)) return Colour(std::exp(-sigmaT.r * d));
    return {std::exp(-sigmaT.r * d), std::exp(-sigmaT.g * d), std::exp(-sigmaT.b * d)};
}

// [free-flight]
FreeFlight sampleFreeFlight(const TrackedMedium& m, const Ray& ray, double t0, double t1,
                            Sampler& sampler) {
    FreeFlight flight;
    // Coefficients per unit of t: σ per unit length times the length of ray.d.
    const double length = glm::length(ray.d);
    if (m.medium.homogeneous() && grey(m.medium.sigmaA) && grey(m.medium.sigmaS)) {
        // A homogeneous grey medium (milk, most fog): the exponential in closed form, then
        // absorption or scattering by their shares of σt; the loop below would find no null
        // collision, and a walk through milk takes hundreds of these flights.
        const double mu = m.medium.sigmaTMax() * length;
        if (!(mu > 0.0)) return flight;
        const double t = nextCollision(t0, mu, sampler);
        if (t >= t1) return flight;
        flight.t = t;
        flight.event = sampler.next1D() * mu < m.medium.sigmaA.r * length
                           ? FreeFlight::Event::Absorbed
                           : FreeFlight::Event::Scattered;
        return flight;
    }
    const Ray local = m.toMedium(ray);
    const Colour sigmaA = m.medium.sigmaA * length, sigmaS = m.medium.sigmaS * length;
    const double sigmaTMax = m.medium.sigmaTMax() * length;
    // A homogeneous medium has density 1 all along the piece: one majorant, no grid to walk (a
    // walk through milk takes hundreds of flights, each a cell or two long).
    auto forEachCell = [&](auto&& cell) {
        if (m.medium.homogeneous())
            cell(t0, t1, 1.0);
        else
            m.majorants.traverse(local, t0, t1, cell);
    };
    forEachCell([&](double a, double b, double bound) {
        // μ̄: this cell's majorant. An empty cell holds no particle.
        const double mu = bound * sigmaTMax;
        if (!(mu > 0.0)) return true;
        // [exercise-delta-tracking]
        // Exercise 17.2, delta tracking: read ch17-tracking.
        // Blank: return true;
        double t = a;
        while (true) {
            // Step 1: the next tentative collision; past the cell, the memoryless exponential
            // lets the next cell start afresh.
            t = nextCollision(t, mu, sampler);
            if (t >= b) return true;
            // Step 2: real or null? The density at t splits μ̄ into absorption, scattering
            // and null collisions; for colour, each is chosen by its largest weighted channel.
            const double density = m.medium.density->at(local.o + t * local.d);
            const Colour muA = sigmaA * density, muS = sigmaS * density;
            // A bound leaves no channel a negative null coefficient, whatever the rounding.
            const Colour muN = glm::max(Colour(mu) - muA - muS, Colour(0.0));
            const double pA = maxChannel(muA * flight.weight);
            const double pS = maxChannel(muS * flight.weight);
            const double pN = maxChannel(muN * flight.weight);
            const double total = pA + pS + pN;
            if (!(total > 0.0)) {
                flight.event = FreeFlight::Event::Absorbed;
                return false;
            }
            const double u = sampler.next1D() * total;
            if (u < pA) {
                flight.event = FreeFlight::Event::Absorbed;
                flight.t = t;
                return false;
            }
            if (u < pA + pS) {
                // Step 3: a real scattering; the weight keeps the channels unbiased.
                flight.weight *= muS * (total / (mu * pS));
                flight.event = FreeFlight::Event::Scattered;
                flight.t = t;
                return false;
            }
            flight.weight *= muN * (total / (mu * pN));
        }
        // [exercise-delta-tracking]
    });
    return flight;
}
// [free-flight]

// [ratio-track-reading]
Colour ratioTrackReading(const TrackedMedium& m, const Ray& ray, double t0, double t1,
                         const double* at, Colour* trAt, int count, Sampler& sampler) {
    const double length = glm::length(ray.d);
    const Colour sigmaT = m.medium.sigmaT() * length;
    const double sigmaTMax = m.medium.sigmaTMax() * length;
    const Ray local = m.toMedium(ray);
    Colour tr(1.0);
    int next = 0;  // The first read not yet taken.
    const auto readBefore = [&](double t) {
        for (; next < count && at[next] < t; ++next) trAt[next] = tr;
    };
    m.majorants.traverse(local, t0, t1, [&](double a, double b, double bound) {
        const double mu = bound * sigmaTMax;
        if (!(mu > 0.0)) return true;
        for (double t = nextCollision(a, mu, sampler); t < b; t = nextCollision(t, mu, sampler)) {
            // Step 1: the reads before this collision see the product so far.
            readBefore(t);
            // Step 2: the collision's ratio of null to majorant, as in estimateTransmittance.
            const double density = m.medium.density->at(local.o + t * local.d);
            tr *= (Colour(mu) - sigmaT * density) / mu;
            // Step 3: Russian roulette on a small product, which keeps its expectation.
            const double largest = maxChannel(tr);
            if (largest < kRouletteBelow) {
                if (!(sampler.next1D() * kRouletteBelow < largest)) {
                    tr = Colour(0.0);
                    return false;
                }
                tr *= kRouletteBelow / largest;
            }
        }
        return true;
    });
    // The reads after the last collision (or after the walk ended: 0).
    readBefore(std::numeric_limits<double>::infinity());
    return tr;
}
// [ratio-track-reading]

// [exact-transmittance]
bool exactOn(const TrackedMedium& m, TransmittanceMethod method) {
    return method == TransmittanceMethod::Exact && !m.medium.homogeneous() &&
           m.medium.density->integrable();
}

Colour exactTransmittance(const TrackedMedium& m, const Ray& ray, double t0, double t1,
                          const double* at, Colour* trAt, int count) {
    const Ray local = m.toMedium(ray);
    // Optical depth per unit t is σt · density · |ray.d|: the density's integral, scaled.
    const Colour sigmaT = m.medium.sigmaT() * glm::length(ray.d);
    // Step 1: the stretches of the majorant grid's cells that may hold density, merged.
    std::vector<std::pair<double, double>> runs;
    m.majorants.traverse(local, t0, t1, [&](double a, double b, double bound) {
        if (!(bound > 0.0)) return true;
        if (!runs.empty() && runs.back().second == a)
            runs.back().second = b;
        else
            runs.emplace_back(a, b);
        return true;
    });
    // Step 2: each stretch integrated; a reading before or between them keeps the depth so far.
    std::vector<double> depthAt(count);
    double depth = 0.0;
    int k = 0;
    for (const auto& [a, b] : runs) {
        for (; k < count && at[k] <= a; ++k) depthAt[k] = depth;
        int end = k;
        while (end < count && at[end] < b) ++end;
        const double before = depth;
        depth +=
            m.medium.density->depth(local.o, local.d, a, b, at + k, depthAt.data() + k, end - k);
        for (int i = k; i < end; ++i) depthAt[i] += before;
        k = end;
    }
    for (; k < count; ++k) depthAt[k] = depth;
    for (int i = 0; i < count; ++i) trAt[i] = beerLambert(sigmaT, depthAt[i]);
    return beerLambert(sigmaT, depth);
}
// [exact-transmittance]

// [transmittance]
Colour estimateTransmittance(const TrackedMedium& m, const Ray& ray, double t0, double t1,
                             TransmittanceMethod method, double step, Sampler& sampler) {
    const double length = glm::length(ray.d);
    const Colour sigmaT = m.medium.sigmaT() * length;
    // A homogeneous medium needs no estimate: Beer–Lambert.
    if (m.medium.homogeneous()) return beerLambert(sigmaT, t1 - t0);
    // A voxel grid needs no estimate either: its optical depth, integrated cell by cell.
    if (exactOn(m, method)) return exactTransmittance(m, ray, t0, t1, nullptr, nullptr, 0);
    if (method == TransmittanceMethod::Exact) method = TransmittanceMethod::Ratio;
    const Ray local = m.toMedium(ray);
    Colour tr(1.0);
    if (method == TransmittanceMethod::March) {
        // Fixed steps of `step` world units from one jittered start: each step's density
        // stands for the whole step (the estimate of the optical depth is unbiased, but its
        // exponential is not). One cell at a time, so no step is spent on empty cells.
        const double dt = step / length;
        const double jitter = sampler.next1D();
        m.majorants.traverse(local, t0, t1, [&](double a, double b, double bound) {
            if (!(bound > 0.0)) return true;
            double opticalDepth = 0.0;
            for (double t = a + jitter * dt; t < b; t += dt)
                opticalDepth += m.medium.density->at(local.o + t * local.d) * dt;
            tr *= beerLambert(sigmaT, opticalDepth);
            return maxChannel(tr) > 0.0;
        });
        return tr;
    }
    const double sigmaTMax = m.medium.sigmaTMax() * length;
    m.majorants.traverse(local, t0, t1, [&](double a, double b, double bound) {
        const double mu = bound * sigmaTMax;
        if (!(mu > 0.0)) return true;
        for (double t = nextCollision(a, mu, sampler); t < b; t = nextCollision(t, mu, sampler)) {
            const double density = m.medium.density->at(local.o + t * local.d);
            const Colour muN = glm::max(Colour(mu) - sigmaT * density, Colour(0.0));
            if (method == TransmittanceMethod::Ratio) {
                // [exercise-ratio-tracking]
                // Exercise 17.3, ratio tracking: read ch17-tracking.
                // Blank: tr *= 1.0;
                tr *= muN / mu;
                // [exercise-ratio-tracking]
            } else {
                // Delta tracking: a real collision stops the light; a null one passes it on,
                // weighted so that each channel stays unbiased.
                const double pReal = maxChannel((Colour(mu) - muN) * tr);
                const double pNull = maxChannel(muN * tr);
                if (sampler.next1D() * (pReal + pNull) < pReal) {
                    tr = Colour(0.0);
                    return false;
                }
                tr *= muN * ((pReal + pNull) / (mu * pNull));
            }
            if (!(maxChannel(tr) > 0.0)) return false;
        }
        return true;
    });
    return tr;
}
// [transmittance]

}  // namespace rb

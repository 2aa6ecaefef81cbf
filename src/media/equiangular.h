/// \file
/// Equiangular sampling: points along a ray, placed with a density proportional to 1/r² from a
/// light, so that the light's falloff cancels (chapter 17).
#pragma once

namespace rb {

/// Where a light stands relative to a stretch [a, b] of a ray, in world distances along the
/// ray's unit direction.
struct EquiangularSegment {
    double a, b;   ///< The stretch, a < b.
    double delta;  ///< The distance along the ray of the point nearest the light.
    double h;      ///< The light's distance from the ray's line (> 0).
};

/// A distance s in [a, b] and its density there, per unit world length.
struct EquiangularSample {
    double s;
    double pdf;
};

/// Draw s in [a, b] with density proportional to 1 / (h² + (s − Δ)²): uniform in the angle
/// under which the light sees the point. `u` is uniform in [0, 1).
/// Source: Kulla and Fajardo, "Importance Sampling Techniques for Path Tracing in
/// Participating Media", EGSR 2012, section 3 (equiangular sampling, eq. 6).
EquiangularSample sampleEquiangular(const EquiangularSegment& seg, double u);

/// The density of sampleEquiangular at s, per unit world length: h / (θ_ab (h² + (s − Δ)²)),
/// θ_ab the angle the stretch subtends at the light.
double equiangularPdf(const EquiangularSegment& seg, double s);

}  // namespace rb

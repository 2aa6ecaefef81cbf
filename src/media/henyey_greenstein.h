/// \file
/// The Henyey–Greenstein phase function: how a medium spreads the light it scatters.
#pragma once

#include "core/vec.h"

namespace rb {

/// p(cos θ) = (1 − g²) / (4π (1 + g² − 2g cos θ)^{3/2}), θ between the light's direction of
/// travel before and after scattering; it integrates to 1 over the sphere.
/// Source: Henyey and Greenstein, "Diffuse radiation in the galaxy", ApJ 93, 1941.
double henyeyGreenstein(double cosTheta, double g);

/// Draw a direction of travel after scattering, for light travelling along the unit vector
/// `forward`, with density henyeyGreenstein(dot(forward, result), g).
Vec3 sampleHenyeyGreenstein(const Vec3& forward, double g, const Vec2& u);

/// The cosine of the sampled direction with `forward`: the inverse of the HG CDF at u.
/// Source: pbrt-v3, section 15.2.3 (the inversion of the HG distribution in cos θ).
double sampleHenyeyGreensteinCos(double g, double u);

}  // namespace rb

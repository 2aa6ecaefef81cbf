/// \file
/// A sampler as the sampling lab (rt's `--warptest` option) sees it: how to draw its points, on
/// which 2-D domain to bin them, and the density the chapter's code states on that domain.
/// Each chapter that samples lists its samplers as Warp records (its `*_warps.cpp`), and its
/// Feature hands them to the lab, so a chapter binary offers the samplers of its chapters only.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "core/sampler.h"
#include "core/vec.h"

namespace rb {

/// One parameter of a sampler, set on the command line as name=value.
struct WarpParameter {
    std::string name;  ///< e.g. "exponent".
    double value;      ///< The default.
    double min, max;   ///< The allowed range (inclusive).
    std::string help;  ///< One line for the list.
};

/// The rectangle [x0, x1] × [y0, y1] the points are binned on. Directions are binned as
/// (φ, cos θ) about an axis: that map has Jacobian 1, so a pdf per unit solid angle is also
/// the density per unit φ per unit cos θ.
struct WarpDomain {
    double x0 = 0.0, x1 = 1.0, y0 = 0.0, y1 = 1.0;
    std::string xLabel = "x", yLabel = "y";
};

/// A sampler with its parameters fixed: what the lab draws and what it compares against.
struct WarpSetup {
    WarpDomain domain;
    /// Append about `count` points (domain coordinates) drawn with random streams keyed by
    /// `seed`; a sampler that draws a grid of points at a time may round the count up. A point
    /// off the domain, or NaN, is counted as outside it.
    std::function<void(std::uint64_t count, std::uint64_t seed, std::vector<Vec2>& points)> draw;
    /// The density the chapter's code states at a point of the domain.
    std::function<double(const Vec2& point)> pdf;
    /// What the figure's title says about the parameters, e.g. "exponent n = 20".
    std::string caption;
};

/// A sampler of the book, for the lab.
struct Warp {
    std::string name;      ///< What a reader types: ./rt --warptest NAME.
    int chapter;           ///< The chapter that writes it.
    std::string title;     ///< One line: what it samples, and its pdf.
    std::string exercise;  ///< The exercises whose code it runs ("7.1"), or "".
    std::vector<WarpParameter> parameters;
    /// The setup for the given value of every parameter (checked against its range).
    std::function<WarpSetup(const std::map<std::string, double>& values)> setup;
};

/// The lab's frame (s, t) about unit `axis`: its own (Duff et al.'s basis), independent of any
/// sampler's.
/// Source: T. Duff et al., "Building an Orthonormal Basis, Revisited", JCGT 6(1), 2017.
inline void labFrame(const Vec3& axis, Vec3& s, Vec3& t) {
    const double sign = std::copysign(1.0, axis.z);
    const double a = -1.0 / (sign + axis.z);
    const double b = axis.x * axis.y * a;
    s = Vec3(1.0 + sign * axis.x * axis.x * a, sign * b, -sign * axis.x);
    t = Vec3(b, sign + axis.y * axis.y * a, -axis.y);
}

/// The lab's coordinates of unit direction w about unit `axis`: (φ in [0, 2π), cos θ) in the
/// lab's frame. A direction that is not of unit length (a sampler's bug) gets NaN: it counts
/// as outside the domain.
inline Vec2 directionCoordinates(const Vec3& w, const Vec3& axis) {
    if (!(std::abs(glm::dot(w, w) - 1.0) < 1e-9)) return Vec2(std::nan(""));
    Vec3 s, t;
    labFrame(axis, s, t);
    double phi = std::atan2(glm::dot(w, t), glm::dot(w, s));
    if (phi < 0.0) phi += 2.0 * M_PI;
    return {phi, glm::dot(w, axis)};
}

/// The unit direction whose lab coordinates about `axis` are q = (φ, cos θ): the inverse of
/// directionCoordinates, for a pdf stated per direction.
inline Vec3 directionFromCoordinates(const Vec2& q, const Vec3& axis) {
    Vec3 s, t;
    labFrame(axis, s, t);
    const double sinTheta = std::sqrt(std::max(0.0, 1.0 - q.y * q.y));
    return sinTheta * std::cos(q.x) * s + sinTheta * std::sin(q.x) * t + q.y * axis;
}

/// Append `count` points, point i being `point(sampler)` with a sampler of its own, stream
/// (seed, stream, i): how the lab runs a sampler that takes fresh random numbers per point.
template <typename Point>
void drawEach(std::uint64_t count, std::uint64_t seed, std::uint64_t stream,
              std::vector<Vec2>& points, Point point) {
    for (std::uint64_t i = 0; i < count; ++i) {
        Sampler sampler(seed, stream, i);
        points.push_back(point(sampler));
    }
}

/// A parameter's value for a caption: up to 4 significant digits ("2", "0.5", "1e+04").
inline std::string warpNumber(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.4g", v);
    return buffer;
}

/// The domain of directions about an axis whose cos θ lies in [cosLow, cosHigh].
inline WarpDomain directionDomain(double cosLow, double cosHigh = 1.0) {
    return {0.0, 2.0 * M_PI, cosLow, cosHigh, "azimuth φ", "cos θ"};
}

}  // namespace rb

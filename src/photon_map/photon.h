/// \file
/// Photon: one stored photon, in 20 bytes as Jensen packs it (position, RGBE power, incoming
/// direction in two bytes).
#pragma once

#include <array>
#include <cmath>
#include <cstdint>

#include "core/vec.h"

namespace rb {

// [photon-record]
/// A photon stored where it landed on a diffuse surface. Source: H. W. Jensen, "Realistic
/// Image Synthesis Using Photon Mapping" (2001), section 5.2: 20 bytes per photon.
struct Photon {
    float position[3];       ///< Where it landed, in world space.
    std::uint8_t power[4];   ///< Its flux Φ, packed as shared-exponent RGBE (Ward's format).
    std::uint8_t theta;      ///< The direction it travelled: polar angle, 256 steps over [0, π].
    std::uint8_t phi;        ///< ... and azimuth, 256 steps over [−π, π).
    std::uint16_t reserved;  ///< Padding to 20 bytes (Jensen keeps the kd-tree's split axis here).
};
static_assert(sizeof(Photon) == 20, "a photon record is 20 bytes");
// [photon-record]

/// Pack a non-negative colour as RGBE. Each mantissa is rounded down after adding `dither` in
/// [0, 1): a uniform random dither makes the stored flux exact on average (plain truncation
/// would bias every photon down by half a step, and rounding to nearest would bias a whole map
/// of photons of one flux, all rounded the same way, by up to 1/256); 0.5 rounds to nearest.
inline void packRgbe(const Colour& c, std::uint8_t out[4], double dither = 0.5) {
    const double v = std::max(c.r, std::max(c.g, c.b));
    if (!(v > 1e-32)) {
        out[0] = out[1] = out[2] = out[3] = 0;
        return;
    }
    int e = 0;
    std::frexp(v, &e);  // v = m·2^e with m in [0.5, 1)
    // The largest channel may round up to 256: then use the next exponent.
    if (std::floor(v * std::ldexp(1.0, 8 - e) + dither) > 255.0) ++e;
    const double scale = std::ldexp(1.0, 8 - e);
    auto byte = [&](double x) {
        return static_cast<std::uint8_t>(std::min(255.0, std::floor(x * scale + dither)));
    };
    out[0] = byte(c.r);
    out[1] = byte(c.g);
    out[2] = byte(c.b);
    out[3] = static_cast<std::uint8_t>(e + 128);
}

/// The colour packRgbe stored. The exponent's scale comes from a table of 256 (Jensen keeps
/// such tables too): a gather unpacks every photon it accepts.
inline Colour unpackRgbe(const std::uint8_t in[4]) {
    static const std::array<double, 256> scale = [] {
        std::array<double, 256> t{};
        for (int e = 1; e < 256; ++e) t[e] = std::ldexp(1.0, e - (128 + 8));
        return t;  // t[0] = 0: a zero colour
    }();
    const double f = scale[in[3]];
    return Colour(in[0] * f, in[1] * f, in[2] * f);
}

/// Quantise a unit direction to (θ, φ) bytes.
inline void packDirection(const Vec3& d, std::uint8_t& theta, std::uint8_t& phi) {
    const double t = std::acos(std::clamp(d.z, -1.0, 1.0)) * (256.0 / M_PI);
    const double p = (std::atan2(d.y, d.x) + M_PI) * (256.0 / (2.0 * M_PI));
    theta = static_cast<std::uint8_t>(std::min(255.0, t));
    phi = static_cast<std::uint8_t>(static_cast<int>(p) & 255);
}

/// The unit direction at the centre of the (θ, φ) bin packDirection chose, from tables of the
/// 256 sines and cosines of each angle (a gather tests every photon's direction; computing
/// them took half its time). Source: Jensen (2001), section 5.2.
inline Vec3 unpackDirection(std::uint8_t theta, std::uint8_t phi) {
    struct Table {
        double cosTheta[256], sinTheta[256], cosPhi[256], sinPhi[256];
    };
    static const Table table = [] {
        Table t{};
        for (int i = 0; i < 256; ++i) {
            const double angleTheta = (i + 0.5) * (M_PI / 256.0);
            const double anglePhi = (i + 0.5) * (2.0 * M_PI / 256.0) - M_PI;
            t.cosTheta[i] = std::cos(angleTheta);
            t.sinTheta[i] = std::sin(angleTheta);
            t.cosPhi[i] = std::cos(anglePhi);
            t.sinPhi[i] = std::sin(anglePhi);
        }
        return t;
    }();
    return {table.sinTheta[theta] * table.cosPhi[phi], table.sinTheta[theta] * table.sinPhi[phi],
            table.cosTheta[theta]};
}

}  // namespace rb

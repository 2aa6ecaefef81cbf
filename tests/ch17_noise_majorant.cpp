/// \file
/// Chapter 17 tests: the majorant grid of a procedural (noise) smoke.
///
/// Delta and ratio tracking are unbiased only while the majorant is never below the density.
/// The noise smoke's cells are bounded by interval arithmetic on the noise's own formula
/// (media/noise_bound.h). The tests sample the density densely inside random boxes, of sizes
/// from a hundredth of a lattice cell to several cells, and check that no sample lies above
/// its box's bound. Then that the bound is of first order in the box's size, as interval
/// arithmetic on a smooth function is: a box ten times smaller leaves at least five times less
/// room above the density at its centre. Last, that the bound pays where a cell is small beside the
/// smoke's wisps: the grid's mean bound is well below the flat bound 1 the smoke had before.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>

#include "core/sampler.h"
#include "media/majorant_grid.h"
#include "media/medium.h"
#include "media/noise_bound.h"

using rb::Vec3;

namespace {

/// A random point in the box [lo, hi].
Vec3 pointIn(const Vec3& lo, const Vec3& hi, rb::Sampler& sampler) {
    const double u = sampler.next1D(), v = sampler.next1D(), w = sampler.next1D();
    return lo + Vec3(u, v, w) * (hi - lo);
}

}  // namespace

SCENARIO("A noise smoke's majorant is never below its density", "[ch17]") {
    // The bathhouse's steam (scenes/seeds/000-bathhouse.lua), its mirror image (a negative
    // gain bounds the noise from below) and a one-octave smoke.
    const rb::NoiseDensity steam(2.2, 3, 0.05, 1.2, 7), inverted(2.2, 3, 0.6, -1.5, 7),
        plain(1.0, 1, 0.5, 1.0, 3);
    for (const rb::NoiseDensity* density : {&steam, &inverted, &plain}) {
        GIVEN("300 random boxes from 0.005 to 2 units wide, each sampled at 300 points") {
            int below = 0, samples = 0;
            for (int b = 0; b < 300; ++b) {
                rb::Sampler sampler(1, static_cast<std::uint64_t>(b), 0);
                const Vec3 lo = 6.0 * Vec3(sampler.next1D(), sampler.next1D(), sampler.next1D()) -
                                Vec3(3.0);
                const double size = 0.005 * std::pow(400.0, sampler.next1D());
                const Vec3 hi = lo + size * Vec3(0.5 + sampler.next1D(), 0.5 + sampler.next1D(),
                                                 0.5 + sampler.next1D());
                const double bound = density->maxIn(lo, hi);
                for (int k = 0; k < 300; ++k, ++samples)
                    if (density->at(pointIn(lo, hi, sampler)) > bound) ++below;
                // The box's corners, where the bound's interval ends are.
                for (int c = 0; c < 8; ++c, ++samples) {
                    const Vec3 corner(c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y,
                                      c & 4 ? hi.z : lo.z);
                    if (density->at(corner) > bound) ++below;
                }
            }
            THEN("no sample of the density lies above its box's majorant") {
                INFO(samples << " samples");
                CHECK(below == 0);
            }
        }
    }
}

SCENARIO("A noise smoke's majorant closes in on the density as the box shrinks", "[ch17]") {
    GIVEN("the bathhouse's steam and boxes of side h around 50 random points") {
        const rb::NoiseDensity steam(2.2, 3, 0.05, 1.2, 7);
        // Room above the density at the centre, largest over the points, for boxes of side h.
        const auto room = [&](double h) {
            double worst = 0.0;
            for (int i = 0; i < 50; ++i) {
                rb::Sampler sampler(1, static_cast<std::uint64_t>(i), 1);
                const Vec3 p = pointIn(Vec3(-2.0), Vec3(2.0), sampler);
                // Only where the clamp does not hide the noise: inside (0, 1).
                const double d = steam.at(p);
                if (d <= 0.05 || d >= 0.95) continue;
                worst = std::max(worst, steam.maxIn(p - Vec3(h / 2), p + Vec3(h / 2)) - d);
            }
            return worst;
        };
        WHEN("h goes from 0.01 to 0.001") {
            const double coarse = room(0.01), fine = room(0.001);
            THEN("the room above the density shrinks at least five times (first order in h)") {
                INFO("room " << coarse << " at h = 0.01, " << fine << " at h = 0.001");
                CHECK(coarse > 0.0);
                CHECK(fine * 5.0 < coarse);
            }
        }
    }
}

SCENARIO("A smoke whose wisps are larger than a cell gets a majorant grid, not a flat bound",
         "[ch17]") {
    GIVEN("a one-octave smoke of frequency 1 (wisps about a unit wide) in 16³ cells of a unit box") {
        const rb::NoiseDensity smoke(1.0, 1, 0.1, 1.0, 5);
        const int res = 16;
        double sum = 0.0;
        for (int z = 0; z < res; ++z)
            for (int y = 0; y < res; ++y)
                for (int x = 0; x < res; ++x) {
                    const Vec3 lo = Vec3(x, y, z) / double(res);
                    sum += smoke.maxIn(lo, lo + Vec3(1.0 / res));
                }
        THEN("the mean cell bound is below half the flat bound 1 the smoke had before") {
            // Each cell is a sixteenth of a lattice cell, where the bound's room above the
            // density is small (the scenario above); the rest is the smoke's own variation.
            const double mean = sum / (res * res * res);
            INFO("mean bound " << mean);
            CHECK(mean < 0.5);
        }
    }
}

// Chapter 17: how the majorant grid's resolution pays, on the chapter's VDB plume.
//
//   ch17_majorant [PLUME.nvdb [RAYS]]   (defaults: scenes/assets/plume.nvdb, 100000)
//
// The plume's density grid (rb::loadVdbDensity) fills a medium with the chapter scene's
// coefficients (sigma_s 30, sigma_a 3 per unit of the grid's own space; no scaling, so the
// medium's space is world space) whose DensityField is wrapped in a counter: delta and ratio
// tracking call at() once per tentative collision, so the calls are the tentative collisions.
// For each resolution N = 1, 2, 4, ..., 64 of the majorant grid (rb::TrackedMedium(medium,
// Mat4(1), box, N); N = 1 is one global majorant, the density's maximum over the whole box),
// the same RAYS rays cross the plume's box: each from a random point on a sphere around the box
// (radius 2, about the box's centre) towards a random point inside the box, over its whole
// length. On each ray:
//   - rb::sampleFreeFlight (delta tracking): a real collision is a flight that returns an event
//     (scattered or absorbed); null collisions = tentative collisions - real collisions;
//   - rb::estimateTransmittance with ratio tracking: every tentative collision is a lookup.
// Each ray uses the sampler stream (seed 17, ray index, 0) at every resolution. Times: the
// fastest of 5 passes over all rays, one thread; the majorant grid's build time is the fastest
// of 3 builds. Prints a table (one row per N: N, build ms, tentative collisions per flight,
// real collisions (events) per flight, null per real, ns per flight, ratio-tracking lookups
// per ray, ns per transmittance estimate) and "target NAME VALUE" lines:
//   target null_per_real_global V    (N = 1)
//   target null_per_real_16 V        (N = 16, the default --media-majorant)
//   target flight_speedup_16 V       (time per flight at N = 1 over N = 16)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "core/error.h"
#include "media/medium.h"
#include "media/tracking.h"
#include "media/vdb_density.h"

namespace {

/// A density field that counts its lookups (one per tentative collision).
class CountingDensity final : public rb::DensityField {
  public:
    explicit CountingDensity(std::shared_ptr<const rb::DensityField> inner)
        : inner_(std::move(inner)) {}
    double at(const rb::Vec3& p) const override {
        ++calls;
        return inner_->at(p);
    }
    double maxIn(const rb::Vec3& lo, const rb::Vec3& hi) const override {
        return inner_->maxIn(lo, hi);
    }
    rb::AABB bounds() const override { return inner_->bounds(); }
    bool constant() const override { return inner_->constant(); }
    mutable unsigned long long calls = 0;  ///< at() calls since the last reset.

  private:
    std::shared_ptr<const rb::DensityField> inner_;
};

double seconds(std::chrono::steady_clock::time_point a, std::chrono::steady_clock::time_point b) {
    return std::chrono::duration<double>(b - a).count();
}

}  // namespace

int main(int argc, char** argv) {
    const std::string path = argc > 1 ? argv[1] : "scenes/assets/plume.nvdb";
    const std::size_t rays = argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 100000;
    if (rays < 100) {
        std::fprintf(stderr, "usage: ch17_majorant [PLUME.nvdb [RAYS >= 100]]\n");
        return 2;
    }
    if (!rb::vdbSupported()) {
        std::printf("(ch17_majorant: this build reads no VDB files; nothing measured)\n");
        return 0;
    }
    std::shared_ptr<const rb::DensityField> grid;
    try {
        grid = rb::loadVdbDensity(path, "density", nullptr);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "ch17_majorant: %s\n", e.what());
        return 1;
    }
    auto counting = std::make_shared<CountingDensity>(grid);
    rb::Medium medium;
    medium.sigmaS = rb::Colour(30.0);
    medium.sigmaA = rb::Colour(3.0);
    medium.g = 0.2;
    medium.density = counting;
    medium.where = "ch17_majorant";
    const rb::AABB box = grid->bounds();

    // The rays: from a sphere around the box towards a point inside it.
    std::mt19937_64 rng(17);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    const rb::Vec3 centre = 0.5 * (box.lo + box.hi);
    std::vector<rb::Ray> paths(rays);
    for (rb::Ray& r : paths) {
        const double z = 2.0 * uniform(rng) - 1.0, phi = 2.0 * M_PI * uniform(rng);
        const double s = std::sqrt(std::max(0.0, 1.0 - z * z));
        const rb::Vec3 from = centre + 2.0 * rb::Vec3(s * std::cos(phi), s * std::sin(phi), z);
        const rb::Vec3 to = box.lo + rb::Vec3(uniform(rng), uniform(rng), uniform(rng)) *
                                         (box.hi - box.lo);
        r = rb::Ray{from, glm::normalize(to - from)};
    }
    const double far = 10.0;  // past the box from every start; the grid clips to the box

    std::printf(
        "Majorant grid against null collisions (chapter 17): %s, box (%.2f %.2f %.2f)-(%.2f "
        "%.2f %.2f),\n",
        path.c_str(), box.lo.x, box.lo.y, box.lo.z, box.hi.x, box.hi.y, box.hi.z);
    std::printf(
        "sigma_s 30, sigma_a 3; %zu rays from a sphere of radius 2 into the box; 1 thread, "
        "fastest of 5 passes.\n",
        rays);
    std::printf("%4s %9s %11s %11s %10s %11s %11s %11s\n", "N", "build ms", "tentative",
                "real", "null/real", "ns/flight", "ratio look", "ns/ratio");
    double nullGlobal = 0.0, null16 = 0.0, ns1 = 0.0, ns16 = 0.0;
    for (int n = 1; n <= 64; n *= 2) {
        double build = 1e300;
        std::unique_ptr<rb::TrackedMedium> tracked;
        for (int i = 0; i < 3; ++i) {
            const auto t0 = std::chrono::steady_clock::now();
            auto m = std::make_unique<rb::TrackedMedium>(medium, rb::Mat4(1.0), box, n);
            build = std::min(build, seconds(t0, std::chrono::steady_clock::now()));
            tracked = std::move(m);
        }
        double flightBest = 1e300, ratioBest = 1e300;
        unsigned long long tentative = 0, real = 0, lookups = 0;
        double transmitted = 0.0;
        for (int pass = 0; pass < 5; ++pass) {
            counting->calls = 0;
            real = 0;
            auto t0 = std::chrono::steady_clock::now();
            for (std::size_t i = 0; i < rays; ++i) {
                rb::Sampler sampler(17, i, 0);
                const rb::FreeFlight f = rb::sampleFreeFlight(*tracked, paths[i], 0.0, far, sampler);
                if (f.event != rb::FreeFlight::Event::None) ++real;
            }
            flightBest = std::min(flightBest, seconds(t0, std::chrono::steady_clock::now()));
            tentative = counting->calls;
            counting->calls = 0;
            transmitted = 0.0;
            t0 = std::chrono::steady_clock::now();
            for (std::size_t i = 0; i < rays; ++i) {
                rb::Sampler sampler(17, i, 1);
                transmitted += rb::estimateTransmittance(*tracked, paths[i], 0.0, far,
                                                         rb::TransmittanceMethod::Ratio, 0.0,
                                                         sampler)
                                   .r;
            }
            ratioBest = std::min(ratioBest, seconds(t0, std::chrono::steady_clock::now()));
            lookups = counting->calls;
        }
        const double perRay = 1.0 / static_cast<double>(rays);
        const double nullPerReal =
            real ? static_cast<double>(tentative - real) / static_cast<double>(real) : 0.0;
        const double nsFlight = flightBest * perRay * 1e9;
        std::printf("%4d %9.2f %11.3f %11.4f %10.3f %11.1f %11.3f %11.1f\n", n, build * 1e3,
                    tentative * perRay, real * perRay, nullPerReal, nsFlight, lookups * perRay,
                    ratioBest * perRay * 1e9);
        if (n == 1) {
            nullGlobal = nullPerReal;
            ns1 = nsFlight;
        }
        if (n == 16) {
            null16 = nullPerReal;
            ns16 = nsFlight;
        }
        (void)transmitted;
    }
    std::printf(
        "Global majorant (N = 1): %.2f null collisions per real one; the default grid (N = 16): "
        "%.2f, and a free flight %.2fx as fast.\n",
        nullGlobal, null16, ns16 > 0 ? ns1 / ns16 : 0.0);
    std::printf("target null_per_real_global %.3f\n", nullGlobal);
    std::printf("target null_per_real_16 %.3f\n", null16);
    std::printf("target flight_speedup_16 %.2f\n", ns16 > 0 ? ns1 / ns16 : 0.0);
    return 0;
}

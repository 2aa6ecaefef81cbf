// Chapter 16's speed benchmark for the photon grid (make bench runs it through
// tests/perf/ch16/photon_speed.sh): the time to build a PhotonGrid per million photons, and the
// time of one fixed-radius gather that finds 50 photons, on one thread.
//
//   ch16_photon_speed [PHOTONS]   (default 1000000)
//
// The photons are synthetic, as a caustic or indirect map of a Cornell box stores them: spread
// uniformly over the five walls of the box [-1, 1] x [0, 2] x [-1, 1] (floor, ceiling, back,
// left, right; each 2 x 2), each arriving from inside the box along a cosine-distributed
// direction, each with flux 1 (RGBE stores 1 exactly, so a gather's red flux counts the photons
// it took). The gather radius r gives 50 photons on average: the walls hold N/20 photons per
// unit area, so pi r^2 N / 20 = 50. The gathers are at random points on the walls at least r
// from their edges, with the wall's inward normal, as a shading point asks. Times: the median of
// 7 builds (each of a fresh copy of the photons; the copy is not timed), and the fastest of 3
// passes over 500,000 gathers. Both on the calling thread (the grid and the gather use no
// threads). The grid is built for radius r, as a render builds each pass's grid for its own
// radius. The k-nearest gather (k = 50 within r, so it takes every photon there when fewer are
// that close) is timed too, for comparison.
// Prints a short report and "target NAME VALUE" lines for make bench's summary:
//   target grid_build_ms_per_million V   (issue 20: <= 50)
//   target gather_50_us V                (issue 20: <= 2)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

#include "photon_map/photon.h"
#include "photon_map/photon_grid.h"

namespace {

/// A wall of the box: a point on it from two numbers in [0, 1), and its inward normal.
struct Wall {
    int axis;   ///< The axis the wall is normal to.
    double at;  ///< Its coordinate on that axis.
    double in;  ///< +1 or -1: the inward direction along the axis.
};
constexpr Wall kWalls[5] = {
    {1, 0.0, 1.0}, {1, 2.0, -1.0}, {2, -1.0, 1.0}, {0, -1.0, 1.0}, {0, 1.0, -1.0}};

/// The point of wall w at (u, v) in [0, 1)^2 shrunk by `margin` from the edges.
rb::Vec3 onWall(const Wall& w, double u, double v, double margin) {
    const double a = -1.0 + margin + (2.0 - 2.0 * margin) * u;
    const double b = -1.0 + margin + (2.0 - 2.0 * margin) * v;
    rb::Vec3 p(0.0);
    p[w.axis] = w.at;
    const int i = (w.axis + 1) % 3, j = (w.axis + 2) % 3;
    p[i] = i == 1 ? a + 1.0 : a;  // y spans [0, 2]
    p[j] = j == 1 ? b + 1.0 : b;
    return p;
}

rb::Vec3 inward(const Wall& w) {
    rb::Vec3 n(0.0);
    n[w.axis] = w.in;
    return n;
}

double seconds(std::chrono::steady_clock::time_point a, std::chrono::steady_clock::time_point b) {
    return std::chrono::duration<double>(b - a).count();
}

}  // namespace

int main(int argc, char** argv) {
    const std::size_t n = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 1000000;
    if (n < 1000) {
        std::fprintf(stderr, "usage: ch16_photon_speed [PHOTONS >= 1000]\n");
        return 2;
    }
    const double radius = std::sqrt(20.0 * 50.0 / (M_PI * static_cast<double>(n)));
    std::mt19937_64 rng(16);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);

    // The photons: a wall, a point, an arriving direction (against the inward normal).
    std::vector<rb::Photon> photons(n);
    for (rb::Photon& p : photons) {
        const Wall& w =
            kWalls[std::min<std::size_t>(4, static_cast<std::size_t>(uniform(rng) * 5))];
        const rb::Vec3 x = onWall(w, uniform(rng), uniform(rng), 0.0);
        for (int a = 0; a < 3; ++a) p.position[a] = static_cast<float>(x[a]);
        rb::packRgbe(rb::Colour(1.0), p.power, 0.5);
        // A cosine-distributed direction about the inward normal, travelling towards the wall.
        const double r = std::sqrt(uniform(rng)), phi = 2.0 * M_PI * uniform(rng);
        rb::Vec3 d(0.0);
        const int i = (w.axis + 1) % 3, j = (w.axis + 2) % 3;
        d[i] = r * std::cos(phi);
        d[j] = r * std::sin(phi);
        d[w.axis] = -w.in * std::sqrt(std::max(0.0, 1.0 - r * r));
        rb::packDirection(d, p.theta, p.phi);
        p.reserved = 0;
    }

    // Build: the median of 7, each from a fresh copy.
    std::vector<double> builds;
    rb::PhotonGrid grid;
    for (int run = 0; run < 7; ++run) {
        std::vector<rb::Photon> copy = photons;
        const auto t0 = std::chrono::steady_clock::now();
        rb::PhotonGrid built(std::move(copy), radius);
        const auto t1 = std::chrono::steady_clock::now();
        builds.push_back(seconds(t0, t1));
        if (run == 0) grid = std::move(built);
    }
    std::sort(builds.begin(), builds.end());
    const double buildMs = builds[builds.size() / 2] * 1e3;
    const double buildPerMillion = buildMs * 1e6 / static_cast<double>(n);

    // The gather points: on the walls, at least 2r from their edges (a full disk of photons).
    constexpr std::size_t kGathers = 500000;
    std::vector<rb::Vec3> at(kGathers), normal(kGathers);
    for (std::size_t g = 0; g < kGathers; ++g) {
        const Wall& w =
            kWalls[std::min<std::size_t>(4, static_cast<std::size_t>(uniform(rng) * 5))];
        at[g] = onWall(w, uniform(rng), uniform(rng), 2.0 * radius);
        normal[g] = inward(w);
    }
    auto fixedPass = [&](double& found) {
        found = 0.0;
        const auto t0 = std::chrono::steady_clock::now();
        for (std::size_t g = 0; g < kGathers; ++g)
            found += grid.gatherFlux(at[g], normal[g], radius).r;
        return seconds(t0, std::chrono::steady_clock::now());
    };
    auto nearestPass = [&](double& found) {
        found = 0.0;
        const auto t0 = std::chrono::steady_clock::now();
        for (std::size_t g = 0; g < kGathers; ++g) {
            double r2 = 0.0;
            found += grid.gatherNearest(at[g], normal[g], 50, r2).r;
        }
        return seconds(t0, std::chrono::steady_clock::now());
    };
    double fixedBest = 1e300, nearestBest = 1e300, fixedFound = 0.0, nearestFound = 0.0;
    for (int run = 0; run < 3; ++run) {
        fixedBest = std::min(fixedBest, fixedPass(fixedFound));
        nearestBest = std::min(nearestBest, nearestPass(nearestFound));
    }
    const double fixedUs = fixedBest / kGathers * 1e6;
    const double nearestUs = nearestBest / kGathers * 1e6;

    std::printf(
        "Photon grid, 1 thread: %zu synthetic photons on the five walls of a Cornell box, "
        "grid and gather radius %.5f\n",
        n, radius);
    std::printf(
        "  build (median of 7):              %8.2f ms = %6.2f ms per million photons "
        "(target <= 50)\n",
        buildMs, buildPerMillion);
    std::printf(
        "  gather, radius %.5f (%zu gathers, fastest of 3): mean %.1f photons, %.3f us per "
        "gather (target <= 2)\n",
        radius, kGathers, fixedFound / kGathers, fixedUs);
    std::printf(
        "  gather, k = 50 nearest within the same radius: mean %.1f photons, %.3f us per "
        "gather\n",
        nearestFound / kGathers, nearestUs);
    std::printf("target grid_build_ms_per_million %.2f\n", buildPerMillion);
    std::printf("target gather_50_us %.3f\n", fixedUs);
    return 0;
}

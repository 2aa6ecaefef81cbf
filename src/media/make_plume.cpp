/// \file
/// rb_make_plume: writes chapter 17's smoke plume, scenes/assets/plume.nvdb, a NanoVDB float
/// grid named "density" (a fog volume).
///
/// How the shipped file was made (from the repository's top folder):
///
///     cmake -S . -B build-vdb -DCMAKE_BUILD_TYPE=Release
///     cmake --build build-vdb --target rb_make_plume
///     build-vdb/rb_make_plume scenes/assets/plume.nvdb
///
/// Every parameter is a constant below; the program takes only the output path. It is
/// deterministic: chapter 11's gradient noise with fixed seeds, no random numbers, so each run
/// writes the same bytes (build flags that change floating-point results, such as FMA
/// contraction, could change the last bits of some values).
///
/// The plume fills a box 1 wide, 2 tall and 1 deep, standing on y = 0 and centred on the y
/// axis, in 40 × 80 × 40 voxels of 0.025. Its density is a Gaussian profile around the axis
/// that widens as the smoke rises, fades with height, and is stirred by fractal noise: the
/// point is displaced sideways (more so higher up, where the smoke has become turbulent) and
/// the density is modulated into wisps. Values below kCutoff are left inactive, so the grid
/// stores only the smoke, not the empty air around it.

#include <nanovdb/util/GridBuilder.h>
#include <nanovdb/util/IO.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <iostream>

#include "bump/gradient_noise.h"

namespace {

constexpr int kWidth = 40;            ///< Voxels across x and z.
constexpr int kHeight = 80;           ///< Voxels up y.
constexpr double kVoxel = 0.025;      ///< Voxel size in world units.
constexpr double kBaseRadius = 0.06;  ///< Plume radius at the source, y = 0.
constexpr double kSpread = 0.28;      ///< Radius gained from the source to the top.
constexpr double kSway = 0.22;        ///< Sideways displacement by noise at the top.
constexpr double kCutoff = 0.02;      ///< Densities below this stay inactive (zero).

/// The plume's density at world point p, in [0, 1].
double plumeDensity(const rb::Vec3& p) {
    const double h = p.y / (kHeight * kVoxel);  // 0 at the source, 1 at the top
    // Turbulence: displace the point sideways, more so higher up
    const rb::Vec3 q =
        p + kSway * h *
                rb::Vec3(rb::fractalNoise(3.0 * p, 3, 11), 0.0, rb::fractalNoise(3.0 * p, 3, 12));
    // A Gaussian profile around the axis that widens with height
    const double radius = kBaseRadius + kSpread * h;
    const double r2 = (q.x * q.x + q.z * q.z) / (radius * radius);
    const double profile = std::exp(-2.0 * r2);
    // Thinning with height, and wisps from finer noise
    const double thinning = std::pow(std::max(0.0, 1.0 - h), 1.5);
    const double wisps = std::clamp(0.6 + 0.9 * rb::fractalNoise(6.0 * q, 3, 13), 0.0, 1.0);
    return std::clamp(1.3 * profile * thinning * wisps, 0.0, 1.0);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: rb_make_plume OUT.nvdb   (writes the chapter 17 smoke plume)\n";
        return 2;
    }
    try {
        // Voxel (i, j, k) has its centre at origin + kVoxel * (i, j, k)
        const nanovdb::Vec3d origin(-0.5 * (kWidth - 1) * kVoxel, 0.5 * kVoxel,
                                    -0.5 * (kWidth - 1) * kVoxel);
        nanovdb::GridBuilder<float> builder(0.0f, nanovdb::GridClass::FogVolume);
        const auto density = [&](const nanovdb::Coord& ijk) {
            const rb::Vec3 p(origin[0] + kVoxel * ijk[0], origin[1] + kVoxel * ijk[1],
                             origin[2] + kVoxel * ijk[2]);
            const double d = plumeDensity(p);
            // The builder leaves a voxel inactive when its value equals the background, 0
            return d < kCutoff ? 0.0f : static_cast<float>(d);
        };
        builder(density, nanovdb::CoordBBox(nanovdb::Coord(0),
                                            nanovdb::Coord(kWidth - 1, kHeight - 1, kWidth - 1)));
        const auto handle = builder.getHandle(kVoxel, origin, "density");
        nanovdb::io::writeGrid(argv[1], handle);
        const auto* grid = handle.grid<float>();
        std::cout << argv[1] << ": " << grid->activeVoxelCount() << " active voxels, "
                  << handle.size() << " bytes\n";
    } catch (const std::exception& e) {
        std::cerr << "rb_make_plume: " << e.what() << "\n";
        return 1;
    }
    return 0;
}

/// \file
/// Where on the lens a camera ray starts: the aperture shapes of chapter 13 as maps from the unit
/// square, each beside its pdf, and the stratified pairing of lens samples with a pixel's rays.
#pragma once

#include <cstdint>

#include "core/camera_rays.h"
#include "core/sampler.h"
#include "core/vec.h"

namespace rb {

/// The shape of the aperture.
enum class ApertureShape {
    Disk,   ///< A round iris: the physical lens, raybook's default.
    Square  ///< Seed 001's square aperture.
};

/// Shirley and Chiu's concentric map of the unit square onto the unit disk. It maps squares
/// about the centre to rings, so it keeps strata compact and adjacent strata adjacent.
/// Source: P. Shirley and K. Chiu, "A Low Distortion Map Between Disk and Square", Journal of
/// Graphics Tools 2(3), 1997.
Vec2 concentricDisk(const Vec2& u);
/// The density of concentricDisk's points over the unit disk: uniform, 1/π.
double concentricDiskPdf(const Vec2& p);

/// The unit square [0,1)² mapped onto the square [-1,1)²: seed 001's aperture, side 2.
Vec2 squareAperture(const Vec2& u);
/// The density of squareAperture's points over [-1,1)²: uniform, 1/4.
double squareAperturePdf(const Vec2& p);

/// A point of the aperture shape of radius 1 (the unit disk, or the square [-1,1)²) from a
/// point u of the unit square.
Vec2 aperturePoint(ApertureShape shape, const Vec2& u);

/// The rows of the most nearly square grid of `count` cells: the largest divisor of count that
/// is at most √count (cols = count / rows). 16 → 4 × 4; 12 → 3 × 4; 7 → 1 × 7.
int strataRows(int count);

/// A permutation of 0 … count − 1 chosen by `key`: index i goes to permuteIndex(i, count, key).
/// A bijection on the smallest power of two ≥ count, walked until it lands below count, so
/// it needs no table and costs O(1) on average.
std::uint32_t permuteIndex(std::uint32_t i, std::uint32_t count, std::uint64_t key);

/// The lens sample, in the unit square, for ray `slot` of a pixel: the unit square is cut into
/// slot.count cells (strataRows × the rest), each of the pixel's rays gets one cell through a
/// per-pixel shuffle (so lens strata and pixel strata are paired at random, one each), and a
/// uniform point in the cell comes from `sampler`. The density over the unit square is 1.
Vec2 stratifiedLensSample(const RaySlot& slot, Sampler& sampler);

}  // namespace rb

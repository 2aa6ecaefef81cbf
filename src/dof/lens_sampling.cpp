#include "dof/lens_sampling.h"

#include <cmath>
#include <glm/gtc/constants.hpp>

namespace rb {

// [concentric-disk]
Vec2 concentricDisk(const Vec2& u) {
    // [exercise-concentric-disk]
    // Exercise 13.2, the concentric disk map: read ch13-disk.
    // Blank: return Vec2(0.0);
    // Map u to [-1,1]²; the centre of the square is the centre of the disk.
    const double a = 2.0 * u.x - 1.0, b = 2.0 * u.y - 1.0;
    // Catch the centre: the angle below would divide by zero.
    if (a == 0.0 && b == 0.0) return Vec2(0.0);
    // The square of "radius" max(|a|, |b|) goes to the circle of that radius; the position
    // along the square's edge becomes the angle, an eighth of a turn per half edge.
    const double quarterPi = 0.25 * glm::pi<double>();
    double r, phi;
    if (std::abs(a) > std::abs(b)) {
        r = a;
        phi = quarterPi * (b / a);
    } else {
        r = b;
        phi = 2.0 * quarterPi - quarterPi * (a / b);
    }
    return {r * std::cos(phi), r * std::sin(phi)};
    // [exercise-concentric-disk]
}

double concentricDiskPdf(const Vec2& p) {
    return glm::dot(p, p) <= 1.0 ? 1.0 / glm::pi<double>() : 0.0;
}
// [concentric-disk]

Vec2 squareAperture(const Vec2& u) {
    return 2.0 * u - 1.0;
}

double squareAperturePdf(const Vec2& p) {
    return std::abs(p.x) <= 1.0 && std::abs(p.y) <= 1.0 ? 0.25 : 0.0;
}

Vec2 aperturePoint(ApertureShape shape, const Vec2& u) {
    return shape == ApertureShape::Disk ? concentricDisk(u) : squareAperture(u);
}

int strataRows(int count) {
    int rows = static_cast<int>(std::sqrt(static_cast<double>(count)));
    while (rows > 1 && (rows * rows > count || count % rows != 0)) --rows;
    return std::max(rows, 1);
}

std::uint32_t permuteIndex(std::uint32_t i, std::uint32_t count, std::uint64_t key) {
    // The smallest 2^bits ≥ count, as a mask.
    std::uint32_t mask = count - 1;
    mask |= mask >> 1;
    mask |= mask >> 2;
    mask |= mask >> 4;
    mask |= mask >> 8;
    mask |= mask >> 16;
    int bits = 0;
    while ((mask >> bits) != 0) ++bits;
    const std::uint32_t shift = static_cast<std::uint32_t>(std::max(1, bits / 2));
    const auto k0 = static_cast<std::uint32_t>(key), k1 = static_cast<std::uint32_t>(key >> 32);
    // Each step is a bijection of the bits-bit integers: adding or xoring a constant,
    // multiplying by an odd number, and xoring in the value's own high bits shifted down.
    // Applied until the value falls below count, they permute 0 … count − 1 (cycle walking).
    do {
        i = (i * 0x9e3779b1u + k0) & mask;
        i ^= i >> shift;
        i = ((i ^ k1) * 0x85ebca6bu) & mask;
        i ^= i >> shift;
        i = (i * 0xc2b2ae35u + (k1 >> 7)) & mask;
        i ^= i >> shift;
    } while (i >= count);
    return i;
}

// [stratified-lens]
Vec2 stratifiedLensSample(const RaySlot& slot, Sampler& sampler) {
    // [exercise-stratified-lens]
    // Exercise 13.3, lens strata paired with pixel strata: read ch13-strata.
    // Blank: return sampler.next2D();
    // The cells: a rows × cols grid over the unit square.
    const int rows = strataRows(slot.count), cols = slot.count / rows;
    // This ray's cell: a shuffle of the ray numbers, fixed for the pixel, so the pixel's
    // stratum k and the lens's stratum π(k) go together and each lens stratum is used once.
    const std::uint64_t pixelKey = mix64(mix64(slot.seed ^ 0x6c656e73ULL) ^ slot.pixel);
    const std::uint32_t cell = permuteIndex(static_cast<std::uint32_t>(slot.index),
                                            static_cast<std::uint32_t>(slot.count), pixelKey);
    // A uniform point inside the cell.
    const Vec2 xi = sampler.next2D();
    const auto columns = static_cast<std::uint32_t>(cols);
    return {(static_cast<double>(cell % columns) + xi.x) / cols,
            (static_cast<double>(cell / columns) + xi.y) / rows};
    // [exercise-stratified-lens]
}
// [stratified-lens]

}  // namespace rb

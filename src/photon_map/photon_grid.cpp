#include "photon_map/photon_grid.h"

#include <algorithm>
#include <bit>
#include <cmath>

namespace rb {

namespace {

/// The cell coordinate of x along one axis.
std::int64_t cellOf(double x, double inverseCell) {
    return static_cast<std::int64_t>(std::floor(x * inverseCell));
}

}  // namespace

// [grid-hash]
std::uint32_t PhotonGrid::bucket(std::int64_t i, std::int64_t j, std::int64_t k) const {
    // Source: M. Teschner et al., "Optimized Spatial Hashing for Collision Detection of
    // Deformable Objects", VMV 2003: three large primes, XOR-ed.
    const std::uint64_t h = static_cast<std::uint64_t>(i) * 73856093ULL ^
                            static_cast<std::uint64_t>(j) * 19349663ULL ^
                            static_cast<std::uint64_t>(k) * 83492791ULL;
    return static_cast<std::uint32_t>(h) & mask_;
}
// [grid-hash]

// [grid-build]
PhotonGrid::PhotonGrid(std::vector<Photon> photons, double radius)
    : radius_(radius), inverseCell_(1.0 / (2.0 * radius)) {
    // A power-of-two table with at least one bucket per photon keeps buckets short.
    const std::uint32_t buckets =
        std::bit_ceil(std::max<std::uint32_t>(16, static_cast<std::uint32_t>(photons.size())));
    mask_ = buckets - 1;
    // Step 1: each photon's bucket, and how many photons each bucket holds.
    std::vector<std::uint32_t> of(photons.size());
    start_.assign(buckets + 1, 0);
    for (std::size_t p = 0; p < photons.size(); ++p) {
        const float* x = photons[p].position;
        of[p] = bucket(cellOf(x[0], inverseCell_), cellOf(x[1], inverseCell_),
                       cellOf(x[2], inverseCell_));
        ++start_[of[p] + 1];
    }
    // Step 2: prefix sums give each bucket's first slot.
    for (std::uint32_t b = 0; b < buckets; ++b) start_[b + 1] += start_[b];
    // Step 3: place the photons, each bucket in the photons' original order.
    photons_.resize(photons.size());
    std::vector<std::uint32_t> next(start_.begin(), start_.end() - 1);
    for (std::size_t p = 0; p < photons.size(); ++p) photons_[next[of[p]]++] = photons[p];
}
// [grid-build]

int PhotonGrid::bucketsAround(const Vec3& x, std::uint32_t out[8]) const {
    // The cells are 2r wide, so [x − r, x + r] lies in the two cells nearest x on each axis.
    const std::int64_t i = cellOf(x.x * inverseCell_ - 0.5, 1.0);
    const std::int64_t j = cellOf(x.y * inverseCell_ - 0.5, 1.0);
    const std::int64_t k = cellOf(x.z * inverseCell_ - 0.5, 1.0);
    int n = 0;
    for (int c = 0; c < 8; ++c) {
        const std::uint32_t b = bucket(i + (c & 1), j + ((c >> 1) & 1), k + (c >> 2));
        // Two cells may share a bucket: visit it once, or its photons would count twice.
        if (std::find(out, out + n, b) == out + n) out[n++] = b;
    }
    return n;
}

// [gather-tests]
template <class F>
void PhotonGrid::forEachNear(const Vec3& x, const Vec3& n, double radius, F&& f) const {
    if (photons_.empty()) return;
    std::uint32_t buckets[8];
    const int count = bucketsAround(x, buckets);
    // The distance tests run in float, as the positions are stored: a gather tests five to
    // fifteen photons for each it accepts, and converting each to double cost a fifth of it.
    const float r2 = static_cast<float>(radius * radius), slab = static_cast<float>(0.25 * radius);
    const float xf[3] = {static_cast<float>(x.x), static_cast<float>(x.y), static_cast<float>(x.z)};
    const float nf[3] = {static_cast<float>(n.x), static_cast<float>(n.y), static_cast<float>(n.z)};
    for (int b = 0; b < count; ++b)
        for (std::uint32_t p = start_[buckets[b]]; p < start_[buckets[b] + 1]; ++p) {
            const Photon& photon = photons_[p];
            const float dx = photon.position[0] - xf[0], dy = photon.position[1] - xf[1],
                        dz = photon.position[2] - xf[2];
            const float d2 = dx * dx + dy * dy + dz * dz;
            if (d2 > r2 || std::abs(dx * nf[0] + dy * nf[1] + dz * nf[2]) > slab) continue;
            // Only photons that arrived from the side the gather looks at.
            if (glm::dot(unpackDirection(photon.theta, photon.phi), n) >= 0.0) continue;
            f(photon, d2);
        }
}
// [gather-tests]

// [gather]
Colour PhotonGrid::gatherFlux(const Vec3& x, const Vec3& n, double radius, int* count) const {
    Colour flux(0.0);
    int found = 0;
    forEachNear(x, n, std::min(radius, radius_), [&](const Photon& p, double) {
        flux += unpackRgbe(p.power);
        ++found;
    });
    if (count) *count = found;
    return flux;
}
// [gather]


std::vector<std::pair<double, const Photon*>> PhotonGrid::nearest(const Vec3& x, const Vec3& n,
                                                                  int k, double& r2) const {
    std::vector<std::pair<double, const Photon*>> found;
    forEachNear(x, n, radius_, [&](const Photon& p, double d2) { found.push_back({d2, &p}); });
    r2 = radius_ * radius_;
    if (static_cast<int>(found.size()) > k) {
        // The k nearest, ties broken by position in the grid, so the choice is deterministic;
        // the k-th ends up last.
        std::nth_element(found.begin(), found.begin() + (k - 1), found.end());
        r2 = found[k - 1].first;
        found.resize(k);
    }
    return found;
}

/// Σ Φ of the photons in `found`.
Colour PhotonGrid::fluxOf(const std::vector<std::pair<double, const Photon*>>& found) {
    Colour flux(0.0);
    for (const auto& [d2, p] : found) flux += unpackRgbe(p->power);
    return flux;
}

Colour PhotonGrid::gatherNearest(const Vec3& x, const Vec3& n, int k, double& r2) const {
    return fluxOf(nearest(x, n, k, r2));
}

// [gather-nearer]
Colour PhotonGrid::gatherNearer(const Vec3& x, const Vec3& n, int m, double& r2) const {
    auto found = nearest(x, n, m, r2);
    // The disk through the m-th nearest photon holds the m − 1 nearer ones: (m − 1) photons
    // per π r_m² is unbiased for a uniform density (the m-th's disk covers a Beta(m, N − m + 1)
    // share of N photons' area, and E[(m − 1)/U] = N).
    if (static_cast<int>(found.size()) == m) {
        // The m-th nearest is the farthest of the m (exactly m in reach leaves them unsorted).
        const auto mth = std::max_element(found.begin(), found.end());
        r2 = mth->first;
        found.erase(mth);
    }
    return fluxOf(found);  // fewer than m: all of them, over the grid's whole disk
}
// [gather-nearer]

}  // namespace rb

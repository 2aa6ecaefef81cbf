/// \file
/// PhotonGrid: a hashed uniform grid over stored photons, for gathers within a fixed radius
/// and for the k nearest photons within it.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "photon_map/photon.h"

namespace rb {

/// Photons sorted into the buckets of a hashed uniform grid whose cells are twice the gather
/// radius wide, so a gather visits the 2 × 2 × 2 cells nearest its point. Building is a
/// counting sort: linear, and the same order for any thread count.
class PhotonGrid {
  public:
    /// Bytes a grid over n photons takes beside the photons themselves (its bucket table).
    static std::uint64_t bytesPerPhoton() { return 2 * sizeof(std::uint32_t); }

    PhotonGrid() = default;
    /// A grid over `photons` for gathers of radius up to `radius` (> 0).
    PhotonGrid(std::vector<Photon> photons, double radius);

    /// The gather: Σ Φ over the photons within `radius` (≤ the grid's) of x that arrived on
    /// the side the unit normal n faces, and lie within radius/4 of the plane through x
    /// (so a gather on one wall does not take the photons of the wall across a corner).
    /// `count`, when given, receives how many photons the gather took.
    Colour gatherFlux(const Vec3& x, const Vec3& n, double radius, int* count = nullptr) const;

    /// The k nearest such photons within the grid's radius: their Σ Φ, and in r2 the squared
    /// distance of the k-th (the grid's radius², when fewer than k are that close).
    Colour gatherNearest(const Vec3& x, const Vec3& n, int k, double& r2) const;

    /// How much wider than the gathers a grown gather may reach (chapter 16's wide grids).
    static constexpr double kWidestGrowth = 3.0;

    /// The grown gather: the disk through the m-th nearest photon within the grid's radius,
    /// and the Σ Φ of the m − 1 nearer ones; in r2 the disk's squared radius. Fewer than m
    /// within the grid's radius: all of them, and r2 is the grid's radius².
    Colour gatherNearer(const Vec3& x, const Vec3& n, int m, double& r2) const;

    double radius() const { return radius_; }                        ///< The largest gather radius.
    std::size_t size() const { return photons_.size(); }             ///< Photons stored.
    const std::vector<Photon>& photons() const { return photons_; }  ///< In bucket order.

  private:
    /// The bucket of cell (i, j, k).
    std::uint32_t bucket(std::int64_t i, std::int64_t j, std::int64_t k) const;
    /// The distinct buckets of the 2 × 2 × 2 cells around x; returns how many.
    int bucketsAround(const Vec3& x, std::uint32_t out[8]) const;
    /// The k nearest photons the gather at (x, n) accepts within the grid's radius, with their
    /// squared distances, the k-th last; r2 is its squared distance (the grid's radius² when
    /// fewer than k are that close, and then all of them).
    std::vector<std::pair<double, const Photon*>> nearest(const Vec3& x, const Vec3& n, int k,
                                                         double& r2) const;
    /// Σ Φ of the photons in `found`.
    static Colour fluxOf(const std::vector<std::pair<double, const Photon*>>& found);
    /// Call f(photon, squared distance) for each photon the gather at (x, n) accepts.
    template <class F>
    void forEachNear(const Vec3& x, const Vec3& n, double radius, F&& f) const;

    double radius_ = 0.0, inverseCell_ = 0.0;
    std::uint32_t mask_ = 0;
    std::vector<Photon> photons_;       // sorted by bucket
    std::vector<std::uint32_t> start_;  // bucket b holds photons_[start_[b], start_[b + 1])
};

}  // namespace rb

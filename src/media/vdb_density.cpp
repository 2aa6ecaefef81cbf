#include "media/vdb_density.h"

#include "core/error.h"

#ifdef RB_HAVE_NANOVDB

#include <nanovdb/NanoVDB.h>
#include <nanovdb/util/GridChecksum.h>
#include <nanovdb/util/GridHandle.h>
#include <nanovdb/util/GridStats.h>
#include <nanovdb/util/IO.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <vector>

namespace rb {

namespace {

using FloatGrid = nanovdb::NanoGrid<float>;
using RootNode = FloatGrid::TreeType::RootType;
using UpperNode = RootNode::ChildNodeType;
using LowerNode = UpperNode::ChildNodeType;
using LeafNode = LowerNode::ChildNodeType;

/// Longest grid name read from a file's directory; a longer one is taken as corruption.
constexpr std::uint32_t kMaxNameBytes = 4096;
/// Largest index coordinate of an active voxel: at(p) adds 1 to indices, which must not overflow.
constexpr std::int32_t kMaxIndex = 1 << 30;
constexpr double kInfinity = std::numeric_limits<double>::infinity();
/// Slack, in voxels, when maxIn maps its box to voxel indices: at(p) maps p with its own
/// rounding, which under a rotated transform can land a hair outside the box's mapped corners.
constexpr double kIndexSlack = 1e-6;

/// One grid listed in a NanoVDB file: its description, and where its bytes lie in the file.
struct GridEntry {
    nanovdb::io::MetaData meta;
    std::string name;
    nanovdb::io::Codec codec = nanovdb::io::Codec::NONE;
    std::uint64_t offset = 0;
};

[[noreturn]] void corrupt(const std::string& path, const std::string& what) {
    throw InputError(path + ": truncated or corrupt NanoVDB file: " + what);
}

/// Read `bytes` bytes at the current position of `in`; the caller has checked they exist.
void readBytes(std::istream& in, void* out, std::uint64_t bytes, const std::string& path) {
    in.read(static_cast<char*>(out), static_cast<std::streamsize>(bytes));
    if (!in) corrupt(path, "reading it failed");
}

/// "float", "Vec3f", ...: the name of a grid's value type, for messages.
std::string typeName(nanovdb::GridType type) {
    return type < nanovdb::GridType::End ? nanovdb::toStr(type) : "unknown";
}

/// "32.4.2": a NanoVDB version number.
std::string versionName(const nanovdb::Version& version) {
    return std::to_string(version.getMajor()) + "." + std::to_string(version.getMinor()) + "." +
           std::to_string(version.getPatch());
}

/// The message for a file that does not start with NanoVDB's magic number.
InputError notNanoVdb(const std::string& path, std::uint64_t magic) {
    // Source: OpenVDB's io/Archive.cc, OPENVDB_MAGIC = 0x56444220 (" BDV"), the first 4 bytes.
    if ((magic & 0xFFFFFFFFu) == 0x56444220u) {
        return InputError(path +
                          ": an OpenVDB (.vdb) file, but raybook reads NanoVDB (.nvdb) files: "
                          "convert it with OpenVDB's nanovdb_convert tool");
    }
    return InputError(path +
                      ": not a NanoVDB file (it does not start with NanoVDB's magic "
                      "number \"NanoVDB0\")");
}

/// Every grid of the open file `in` (`fileSize` bytes). A file is a list of segments: a header,
/// one description and name per grid, then the grids' bytes. Every size the file declares is
/// checked against the bytes that really follow before it is trusted.
std::vector<GridEntry> readDirectory(std::istream& in, std::uint64_t fileSize,
                                     const std::string& path) {
    std::vector<GridEntry> grids;
    std::uint64_t offset = 0;
    while (offset < fileSize) {
        // The segment header: the magic number first, even when the file is shorter than a header
        nanovdb::io::Header header;
        header.magic = 0;
        const std::uint64_t headerBytes = std::min<std::uint64_t>(sizeof header, fileSize - offset);
        readBytes(in, &header, headerBytes, path);
        if (header.magic != NANOVDB_MAGIC_NUMBER) {
            if (offset == 0) throw notNanoVdb(path, header.magic);
            corrupt(path, "no segment header at byte " + std::to_string(offset));
        }
        if (headerBytes < sizeof header) corrupt(path, "it ends inside a segment header");
        if (header.version.getMajor() != NANOVDB_MAJOR_VERSION_NUMBER) {
            throw InputError(path + ": written by NanoVDB " + versionName(header.version) +
                             ", but raybook reads NanoVDB " +
                             std::to_string(NANOVDB_MAJOR_VERSION_NUMBER) + ".x files");
        }
        offset += sizeof header;

        // The grids' descriptions and names
        const std::size_t first = grids.size();
        for (std::uint16_t i = 0; i < header.gridCount; ++i) {
            GridEntry entry;
            const std::string which = "grid " + std::to_string(grids.size() + 1);
            if (fileSize - offset < sizeof entry.meta) {
                corrupt(path, "it ends inside the description of " + which);
            }
            readBytes(in, &entry.meta, sizeof entry.meta, path);
            offset += sizeof entry.meta;
            const std::uint32_t nameBytes = entry.meta.nameSize;
            if (nameBytes == 0 || nameBytes > kMaxNameBytes || nameBytes > fileSize - offset) {
                corrupt(path, which + " declares a name of " + std::to_string(nameBytes) +
                                  " bytes, but " + std::to_string(fileSize - offset) +
                                  " bytes are left");
            }
            entry.name.assign(nameBytes, '\0');
            readBytes(in, entry.name.data(), nameBytes, path);
            if (entry.name.back() != '\0') corrupt(path, which + "'s name is not terminated");
            entry.name.resize(std::strlen(entry.name.c_str()));
            offset += nameBytes;
            entry.codec = header.codec;
            grids.push_back(std::move(entry));
        }

        // The grids' bytes, one block after the other
        for (std::size_t g = first; g < grids.size(); ++g) {
            grids[g].offset = offset;
            if (grids[g].meta.fileSize > fileSize - offset) {
                corrupt(path, "grid '" + grids[g].name + "' declares " +
                                  std::to_string(grids[g].meta.fileSize) + " bytes, but only " +
                                  std::to_string(fileSize - offset) + " follow");
            }
            offset += grids[g].meta.fileSize;
        }
        in.seekg(static_cast<std::streamoff>(offset));
    }
    return grids;
}

/// Checks that a grid's bytes can be read without ever leaving them: every node offset lands
/// inside the buffer, aligned, and no level is reached more often than its nodes could fit
/// (a corrupt file could otherwise send a reader anywhere, or make a small file take forever to
/// walk). Also checks that every active value is a finite number.
class GridChecker {
  public:
    GridChecker(const std::uint8_t* bytes, std::uint64_t size, const std::string& where)
        : bytes_(bytes), size_(size), where_(where) {}

    /// Check the tree below the root at byte `rootOffset`; return true when it has active values.
    bool checkTree(std::uint64_t rootOffset) {
        const auto& root = *reinterpret_cast<const RootNode::DataType*>(bytes_ + rootOffset);
        const std::uint64_t tableBytes =
            std::uint64_t(root.mTableSize) * sizeof(RootNode::DataType::Tile);
        if (tableBytes > size_ - rootOffset - sizeof root) fail("its root table overruns the grid");
        for (std::uint32_t i = 0; i < root.mTableSize; ++i) {
            const RootNode::DataType::Tile& tile = *root.tile(i);
            if (tile.isChild()) {
                checkNode<UpperNode>(childOffset<UpperNode>(rootOffset, tile.child));
            } else if (tile.state) {
                checkValue(tile.value, tile.origin());
                hasActive_ = true;
            }
        }
        return hasActive_;
    }

  private:
    [[noreturn]] void fail(const std::string& what) const {
        throw InputError(where_ + ": corrupt NanoVDB grid: " + what);
    }

    void checkValue(float value, const nanovdb::Coord& ijk) const {
        if (!std::isfinite(value)) {
            fail("voxel (" + std::to_string(ijk[0]) + ", " + std::to_string(ijk[1]) + ", " +
                 std::to_string(ijk[2]) + ") holds " + std::to_string(value) +
                 "; densities must be finite numbers");
        }
    }

    /// The byte offset of a child node `relative` bytes from its parent at byte `parent`.
    template <typename NodeT>
    std::uint64_t childOffset(std::uint64_t parent, std::int64_t relative) {
        if (relative < -static_cast<std::int64_t>(parent)) fail("a node lies before the grid");
        // Unsigned arithmetic wraps, so this is parent + relative for a negative relative too
        const std::uint64_t offset = parent + static_cast<std::uint64_t>(relative);
        if (offset > size_ || size_ - offset < sizeof(NodeT)) fail("a node lies past its end");
        if (offset % NANOVDB_DATA_ALIGNMENT != 0) fail("a node is misaligned");
        // In a sound tree each node has one parent, so a level holds at most size / node size
        if (++visits_[NodeT::LEVEL] > size_ / sizeof(NodeT)) fail("its nodes are shared");
        return offset;
    }

    template <typename NodeT>
    void checkNode(std::uint64_t offset) {
        const auto& node = *reinterpret_cast<const NodeT*>(bytes_ + offset);
        const auto& data = *node.data();
        if constexpr (NodeT::LEVEL == 0) {
            for (auto it = data.mValueMask.beginOn(); it; ++it) {
                checkValue(data.mValues[*it], node.offsetToGlobalCoord(*it));
                hasActive_ = true;
            }
        } else {
            for (auto it = data.mChildMask.beginOn(); it; ++it) {
                using ChildT = typename NodeT::ChildNodeType;
                checkNode<ChildT>(childOffset<ChildT>(offset, data.mTable[*it].child));
            }
            for (auto it = data.mValueMask.beginOn(); it; ++it) {
                if (data.mChildMask.isOn(*it)) continue;  // The child holds the values
                checkValue(data.mTable[*it].value, node.offsetToGlobalCoord(*it));
                hasActive_ = true;
            }
        }
    }

    const std::uint8_t* bytes_;
    std::uint64_t size_;
    std::string where_;
    std::uint64_t visits_[3] = {0, 0, 0};
    bool hasActive_ = false;
};

/// Check the grid in `buffer` (read from the file, not yet trusted), then recompute its nodes'
/// bounding boxes and min/max statistics, which maxIn relies on. Returns the grid.
FloatGrid& checkGrid(nanovdb::HostBuffer& buffer, const std::string& where, bool& empty) {
    const std::uint64_t size = buffer.size();
    std::uint8_t* bytes = buffer.data();
    constexpr std::uint64_t kTreeOffset = sizeof(nanovdb::GridData);
    constexpr std::uint64_t kRootOffset = kTreeOffset + sizeof(FloatGrid::TreeType::DataType);
    const auto fail = [&](const std::string& what) {
        throw InputError(where + ": corrupt NanoVDB grid: " + what);
    };
    if (size < kRootOffset + sizeof(RootNode::DataType)) fail("too short for a grid");

    // The grid's header must agree with the file's directory
    const auto& data = *reinterpret_cast<const nanovdb::GridData*>(bytes);
    if (data.mMagic != NANOVDB_MAGIC_NUMBER) fail("no NanoVDB magic number at its start");
    if (data.mGridSize != size) fail("its size differs from the file's directory");
    if (data.mGridType != nanovdb::GridType::Float) fail("it is not a float grid");
    if (data.mVersion.getMajor() != NANOVDB_MAJOR_VERSION_NUMBER) fail("wrong NanoVDB version");
    auto& grid = *reinterpret_cast<FloatGrid*>(bytes);

    // The index-to-world transform must be finite and invertible
    const double* m = data.mMap.mMatD;
    const double det = m[0] * (m[4] * m[8] - m[5] * m[7]) - m[1] * (m[3] * m[8] - m[5] * m[6]) +
                       m[2] * (m[3] * m[7] - m[4] * m[6]);
    bool finite = std::isfinite(det) && det != 0.0;
    for (int i = 0; i < 9; ++i) finite = finite && std::isfinite(data.mMap.mInvMatD[i]);
    for (int i = 0; i < 3; ++i) finite = finite && std::isfinite(data.mMap.mVecD[i]);
    if (!finite) fail("its index-to-world transform is not finite and invertible");

    // The root follows the tree, which follows the grid (NanoVDB's layout; the checksum
    // below covers those three as one block)
    const auto& tree = *reinterpret_cast<const FloatGrid::TreeType::DataType*>(bytes + kTreeOffset);
    if (tree.mNodeOffset[3] != kRootOffset - kTreeOffset) fail("its root is not after its tree");
    GridChecker checker(bytes, size, where);
    const bool hasActive = checker.checkTree(kRootOffset);

    // A checksum of the grid, tree and root, when the writer stored one
    const nanovdb::GridChecksum stored(grid.checksum());
    if (stored.crc32(0) != nanovdb::CRC32::EMPTY) {
        nanovdb::GridChecksum actual;
        actual(grid, nanovdb::ChecksumMode::Partial);
        if (actual.crc32(0) != stored.crc32(0)) fail("its header checksum does not match");
    }

    // Statistics from the values themselves, not from the file
    empty = !hasActive;
    if (!empty) {
        nanovdb::gridStats(grid, nanovdb::StatsMode::MinMax);
        const nanovdb::CoordBBox& box = grid.tree().root().bbox();
        for (int i = 0; i < 3; ++i) {
            if (box.min()[i] < -kMaxIndex || box.max()[i] > kMaxIndex) {
                fail("its active voxels lie beyond index ±2^30");
            }
        }
    }
    return grid;
}

/// A density field sampled from a NanoVDB float grid.
class VdbDensity final : public DensityField {
  public:
    VdbDensity(nanovdb::GridHandle<nanovdb::HostBuffer> handle, const FloatGrid& grid, bool empty)
        : handle_(std::move(handle)), grid_(&grid) {
        if (empty) return;
        active_ = grid.tree().root().bbox();
        // Trilinear interpolation reaches one voxel beyond the active ones
        const nanovdb::Vec3d lo = active_.min().asVec3d() - nanovdb::Vec3d(1.0);
        const nanovdb::Vec3d hi = active_.max().asVec3d() + nanovdb::Vec3d(1.0);
        for (int corner = 0; corner < 8; ++corner) {
            const nanovdb::Vec3d x = grid.indexToWorld(nanovdb::Vec3d(corner & 1 ? hi[0] : lo[0],
                                                                      corner & 2 ? hi[1] : lo[1],
                                                                      corner & 4 ? hi[2] : lo[2]));
            bounds_.extend(Vec3(x[0], x[1], x[2]));
        }
    }

    /// Trilinear interpolation of the eight voxels around p, inactive ones counting as 0.
    double at(const Vec3& p) const override {
        const nanovdb::Vec3d x = grid_->worldToIndex(nanovdb::Vec3d(p.x, p.y, p.z));
        // Beyond the active box grown by a voxel every weight falls on inactive voxels (a NaN
        // coordinate stops here too)
        for (int i = 0; i < 3; ++i) {
            if (!(x[i] > active_.min()[i] - 1.0 && x[i] < active_.max()[i] + 1.0)) return 0.0;
        }
        const nanovdb::Coord base = x.floor();
        const nanovdb::Vec3d t = x - base.asVec3d();
        auto accessor = grid_->getAccessor();
        double density = 0.0;
        for (int corner = 0; corner < 8; ++corner) {
            const nanovdb::Coord offset(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
            double weight = 1.0;
            for (int i = 0; i < 3; ++i) weight *= offset[i] ? t[i] : 1.0 - t[i];
            float value = 0.0f;
            if (accessor.probeValue(base + offset, value) && value > 0.0f) {
                density += weight * value;
            }
        }
        return density;
    }

    /// The largest active value among the voxels that at(p) reads for p in the box, found from
    /// the nodes' min/max statistics wherever a whole node lies inside.
    double maxIn(const Vec3& lo, const Vec3& hi) const override {
        if (active_.empty() || !(lo.x <= hi.x && lo.y <= hi.y && lo.z <= hi.z)) return 0.0;
        // The box in index space: the hull of its eight mapped corners
        nanovdb::Vec3d a(std::numeric_limits<double>::infinity()), b(-a);
        for (int corner = 0; corner < 8; ++corner) {
            const nanovdb::Vec3d x = grid_->worldToIndex(nanovdb::Vec3d(
                corner & 1 ? hi.x : lo.x, corner & 2 ? hi.y : lo.y, corner & 4 ? hi.z : lo.z));
            a.minComponent(x);
            b.maxComponent(x);
        }
        // at(x) reads voxels floor(x) and floor(x) + 1 on each axis; the active box clips them
        nanovdb::CoordBBox voxels = active_;
        for (int i = 0; i < 3; ++i) {
            if (!(a[i] <= b[i])) continue;  // NaN from an infinite box: keep every voxel
            const double first = std::floor(a[i] - kIndexSlack * (1.0 + std::abs(a[i])));
            const double last = std::floor(b[i] + kIndexSlack * (1.0 + std::abs(b[i]))) + 1.0;
            if (last < active_.min()[i] || first > active_.max()[i]) return 0.0;
            voxels.min()[i] = static_cast<std::int32_t>(std::max<double>(first, active_.min()[i]));
            voxels.max()[i] = static_cast<std::int32_t>(std::min<double>(last, active_.max()[i]));
        }
        // getExtrema also counts inactive values of partly covered nodes: a looser bound, never
        // a lower one. A NaN statistic is never taken as a maximum.
        return std::max(0.0, double(nanovdb::getExtrema(*grid_, voxels).max()));
    }

    AABB bounds() const override { return bounds_; }

    bool integrable() const override { return !active_.empty(); }

    // [vdb-depth]
    /// The values at() reads at the eight corners of the lattice cell whose lowest corner is
    /// `cell` (inactive or negative ones as 0), into v (bit i of the index: +1 on axis i);
    /// false when all eight are 0.
    template <class Accessor>
    static bool corners(const Accessor& accessor, const nanovdb::Coord& cell, double v[8]) {
        float value = 0.0f;
        auto fetch = [&](auto&& probe) {
            bool any = false;
            for (int c = 0; c < 8; ++c) {
                const nanovdb::Coord corner = cell + nanovdb::Coord(c & 1, (c >> 1) & 1, c >> 2);
                v[c] = probe(corner, value) && value > 0.0f ? value : 0.0;
                any = any || v[c] > 0.0;
            }
            return any;
        };
        const int leafDim = 8;  // NanoVDB's leaf nodes hold 8³ voxels.
        const bool oneLeaf = (cell[0] & (leafDim - 1)) < leafDim - 1 &&
                             (cell[1] & (leafDim - 1)) < leafDim - 1 &&
                             (cell[2] & (leafDim - 1)) < leafDim - 1;
        if (!oneLeaf)
            return fetch(
                [&](const nanovdb::Coord& c, float& x) { return accessor.probeValue(c, x); });
        // All eight in one leaf's block (most cells): find the leaf once; where the tree has
        // none, the block is one tile of its parent, the same value at every corner.
        if (const auto* leaf = accessor.probeLeaf(cell))
            return fetch([&](const nanovdb::Coord& c, float& x) { return leaf->probeValue(c, x); });
        const double tile = accessor.probeValue(cell, value) && value > 0.0f ? value : 0.0;
        std::fill(v, v + 8, tile);
        return tile > 0.0;
    }

    /// Exact, cell by cell: within one cell of the voxel lattice the trilinear interpolant
    /// along a line is a product of three linear functions of t, a cubic, and Simpson's rule
    /// integrates a cubic exactly.
    /// Source: Simpson's rule is exact for polynomials of degree 3 (Burden and Faires,
    /// "Numerical Analysis", 9th ed., section 4.3); Amanatides and Woo, "A fast voxel traversal
    /// algorithm for ray tracing", Eurographics 1987 (the walk from cell to cell).
    double depth(const Vec3& o, const Vec3& d, double t0, double t1, const double* at,
                 double* depthAt, int count) const override {
        const nanovdb::Vec3d xo = grid_->worldToIndex(nanovdb::Vec3d(o.x, o.y, o.z));
        const nanovdb::Vec3d xd = grid_->worldToIndexDir(nanovdb::Vec3d(d.x, d.y, d.z));
        // Step 1: only where at() can be non-zero, the active box grown by a voxel.
        double a = t0, b = t1;
        for (int i = 0; i < 3 && a < b; ++i) {
            const double lo = active_.min()[i] - 1.0, hi = active_.max()[i] + 1.0;
            if (xd[i] == 0.0) {
                if (!(xo[i] > lo && xo[i] < hi)) b = a;
                continue;
            }
            const double ta = (lo - xo[i]) / xd[i], tb = (hi - xo[i]) / xd[i];
            a = std::max(a, std::min(ta, tb));
            b = std::min(b, std::max(ta, tb));
        }
        int k = 0;
        for (; k < count && !(at[k] > a); ++k) depthAt[k] = 0.0;
        if (!(a < b)) {
            for (; k < count; ++k) depthAt[k] = 0.0;
            return 0.0;
        }
        // Step 2: the cell holding the segment's start, and where the line leaves it on each
        // axis (Amanatides and Woo's tMax and tDelta).
        const double start = a + 1e-9 * (b - a);
        nanovdb::Coord cell;
        double next[3], delta[3];
        int step[3];
        for (int i = 0; i < 3; ++i) {
            cell[i] = static_cast<std::int32_t>(std::floor(xo[i] + start * xd[i]));
            step[i] = xd[i] > 0.0 ? 1 : -1;
            next[i] =
                xd[i] == 0.0 ? kInfinity : (cell[i] + (xd[i] > 0.0 ? 1.0 : 0.0) - xo[i]) / xd[i];
            delta[i] = xd[i] == 0.0 ? kInfinity : 1.0 / std::abs(xd[i]);
        }
        // Step 3: each cell's stretch [ta, tb], integrated by Simpson's rule on its eight
        // corner values; readings inside it integrate [ta, t] the same way.
        auto accessor = grid_->getAccessor();
        double total = 0.0, ta = a;
        const int most =
            3 + static_cast<int>(std::abs(xd[0]) * (b - a) + std::abs(xd[1]) * (b - a) +
                                 std::abs(xd[2]) * (b - a));
        for (int steps = 0; ta < b && steps < most; ++steps) {
            const int axis =
                next[0] < next[1] ? (next[0] < next[2] ? 0 : 2) : (next[1] < next[2] ? 1 : 2);
            const double tb = std::min(next[axis], b);
            double v[8];
            const bool any = corners(accessor, cell, v);
            // The interpolant at parameter t, in the cell's own coordinates.
            auto density = [&](double t) {
                double f[3];
                for (int i = 0; i < 3; ++i) f[i] = xo[i] + t * xd[i] - cell[i];
                const double x00 = v[0] + f[0] * (v[1] - v[0]), x10 = v[2] + f[0] * (v[3] - v[2]);
                const double x01 = v[4] + f[0] * (v[5] - v[4]), x11 = v[6] + f[0] * (v[7] - v[6]);
                const double y0 = x00 + f[1] * (x10 - x00), y1 = x01 + f[1] * (x11 - x01);
                return y0 + f[2] * (y1 - y0);
            };
            auto simpson = [&](double s0, double s1) {
                return (s1 - s0) / 6.0 *
                       (density(s0) + 4.0 * density(0.5 * (s0 + s1)) + density(s1));
            };
            for (; k < count && at[k] < tb; ++k)
                depthAt[k] = total + (any && at[k] > ta ? simpson(ta, at[k]) : 0.0);
            if (any && tb > ta) total += std::max(0.0, simpson(ta, tb));
            ta = tb;
            cell[axis] += step[axis];
            next[axis] += delta[axis];
        }
        for (; k < count; ++k) depthAt[k] = total;
        return total;
    }
    // [vdb-depth]

  private:
    nanovdb::GridHandle<nanovdb::HostBuffer> handle_;  ///< Owns the grid's bytes.
    const FloatGrid* grid_;
    nanovdb::CoordBBox active_;  ///< Index box of the active values; empty when there are none.
    AABB bounds_;
};

/// Load grid `gridName` of the NanoVDB file in `in`, `fileSize` bytes, named `path` in messages.
std::shared_ptr<const DensityField> loadFromStream(std::istream& in, std::uint64_t fileSize,
                                                   const std::string& path,
                                                   const std::string& gridName,
                                                   const MemoryBudget* memory) {
    if (fileSize == 0) throw InputError(path + ": empty file, not a NanoVDB file");

    // The grid asked for
    const std::vector<GridEntry> grids = readDirectory(in, fileSize, path);
    const auto found = std::find_if(grids.begin(), grids.end(),
                                    [&](const GridEntry& g) { return g.name == gridName; });
    if (found == grids.end()) {
        std::string names;
        for (const GridEntry& g : grids) {
            names += (names.empty() ? "" : ", ") + ("'" + g.name + "' (") +
                     typeName(g.meta.gridType) + ")";
        }
        throw InputError(path + ": no grid named '" + gridName + "'; " +
                         (grids.empty() ? "the file holds no grids" : "its grids are " + names));
    }
    const GridEntry& entry = *found;
    const std::string where = path + ", grid '" + gridName + "'";
    if (entry.meta.gridType != nanovdb::GridType::Float) {
        throw InputError(where + ": holds " + typeName(entry.meta.gridType) +
                         " values, but a density needs a float grid");
    }
    if (entry.meta.gridClass == nanovdb::GridClass::LevelSet) {
        throw InputError(where +
                         ": a level set (signed distances to a surface), not a density; "
                         "convert it to a fog volume first");
    }
    if (entry.codec != nanovdb::io::Codec::NONE) {
        const bool known = entry.codec < nanovdb::io::Codec::END;
        throw InputError(where + ": compressed (" +
                         (known ? nanovdb::io::toStr(entry.codec) : "unknown codec") +
                         "), but raybook reads uncompressed NanoVDB files: save it again "
                         "without compression");
    }
    if (entry.meta.gridSize != entry.meta.fileSize) {
        corrupt(path, "grid '" + gridName + "' is uncompressed, yet its size in memory (" +
                          std::to_string(entry.meta.gridSize) +
                          " bytes) differs from its size "
                          "in the file (" +
                          std::to_string(entry.meta.fileSize) + " bytes)");
    }

    // Charge the memory, then read the grid's bytes into a 32-byte aligned buffer
    if (memory) memory->require(entry.meta.gridSize, path, "the density grid '" + gridName + "'");
    nanovdb::HostBuffer buffer = nanovdb::HostBuffer::create(entry.meta.gridSize);
    in.clear();
    in.seekg(static_cast<std::streamoff>(entry.offset));
    readBytes(in, buffer.data(), entry.meta.gridSize, path);

    bool empty = true;
    const FloatGrid& grid = checkGrid(buffer, where, empty);
    return std::make_shared<VdbDensity>(nanovdb::GridHandle<nanovdb::HostBuffer>(std::move(buffer)),
                                        grid, empty);
}

}  // namespace

std::shared_ptr<const DensityField> loadVdbDensity(const std::string& path,
                                                   const std::string& gridName,
                                                   const MemoryBudget* memory) {
    // The file and its real size
    std::error_code error;
    const auto status = std::filesystem::status(path, error);
    if (!std::filesystem::exists(status)) throw InputError(path + ": no such file");
    if (!std::filesystem::is_regular_file(status)) throw InputError(path + ": not a file");
    const std::uint64_t fileSize = std::filesystem::file_size(path, error);
    if (error) throw InputError(path + ": cannot read its size (" + error.message() + ")");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path + ": cannot open it for reading");
    return loadFromStream(in, fileSize, path, gridName, memory);
}

std::shared_ptr<const DensityField> loadVdbDensityBytes(const std::string& bytes,
                                                        const std::string& name,
                                                        const std::string& gridName,
                                                        const MemoryBudget* memory) {
    std::istringstream in(bytes);
    return loadFromStream(in, bytes.size(), name, gridName, memory);
}

bool vdbSupported() {
    return true;
}

}  // namespace rb

#else  // No NanoVDB headers when this build was configured

namespace rb {

std::shared_ptr<const DensityField> loadVdbDensity(const std::string& path, const std::string&,
                                                   const MemoryBudget*) {
    throw InputError(path +
                     ": this build of raybook cannot read VDB files (NanoVDB's headers "
                     "were missing when it was configured): run make deps, which "
                     "installs libnanovdb-dev, then configure and build again");
}

std::shared_ptr<const DensityField> loadVdbDensityBytes(const std::string&, const std::string& name,
                                                        const std::string& gridName,
                                                        const MemoryBudget* memory) {
    return loadVdbDensity(name, gridName, memory);
}

bool vdbSupported() {
    return false;
}

}  // namespace rb

#endif

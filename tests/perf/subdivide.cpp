// subdivide: Loop subdivision of a triangle mesh, for the BVH scaling chart (make charts makes
// the bunny at 3.7k, 15k, 59k and 235k triangles with it, into BUILD/bench/; never committed).
//
// usage: subdivide in.obj out.obj [steps]     (default 1 step; each step quadruples the triangles)
//
// Only positions and triangles are kept (normals and texture coordinates are dropped).
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/error.h"
#include "bvh/obj.h"

namespace {

/// A 64-bit key for the undirected edge (a, b).
std::uint64_t edgeKey(int a, int b) {
    if (a > b) std::swap(a, b);
    return (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint32_t>(b);
}

/// What one undirected edge knows: the corners opposite it (one per adjacent triangle, two on a
/// closed manifold) and the index of its new midpoint vertex.
struct EdgeInfo {
    int opposite[2] = {-1, -1};
    int faces = 0;
    int point = -1;
};

// [loop-subdivision]
/// One step of Loop subdivision: every triangle becomes four, keeping its winding. A new edge
/// point is 3/8·(a + b) + 1/8·(c + d) (the edge's ends and the two opposite corners); an old
/// vertex with n neighbours moves to (1 − nβ)·v + β·Σ neighbours, with Warren's β = 3/16 for
/// n = 3 and 3/(8n) otherwise. Boundaries are handled simply: an edge without exactly two
/// triangles takes its midpoint, and a vertex on such an edge stays where it is.
/// Source: C. Loop, "Smooth Subdivision Surfaces Based on Triangles", M.S. thesis, University
/// of Utah, 1987; J. Warren, "Subdivision methods for geometric design", 1995.
rb::ObjData loopSubdivide(const rb::ObjData& in) {
    const size_t nv = in.positions.size();
    std::unordered_map<std::uint64_t, EdgeInfo> edges;
    edges.reserve(in.triangles.size() * 2);
    for (const auto& t : in.triangles)
        for (int k = 0; k < 3; ++k) {
            EdgeInfo& e = edges[edgeKey(t[k].v, t[(k + 1) % 3].v)];
            if (e.faces < 2) e.opposite[e.faces] = t[(k + 2) % 3].v;
            ++e.faces;
        }

    // Neighbour sums and counts of the old vertices, and which lie on a boundary.
    std::vector<rb::Vec3> neighbourSum(nv, rb::Vec3(0.0));
    std::vector<int> valence(nv, 0);
    std::vector<char> boundary(nv, 0);
    for (const auto& [key, e] : edges) {
        const int a = static_cast<int>(key >> 32), b = static_cast<int>(key & 0xffffffffu);
        neighbourSum[a] += in.positions[b];
        neighbourSum[b] += in.positions[a];
        ++valence[a];
        ++valence[b];
        if (e.faces != 2) boundary[a] = boundary[b] = 1;
    }

    rb::ObjData out;
    out.positions.reserve(nv + edges.size());
    for (size_t v = 0; v < nv; ++v) {
        const int n = valence[v];
        if (boundary[v] || n < 3) {
            out.positions.push_back(in.positions[v]);
            continue;
        }
        const double beta = n == 3 ? 3.0 / 16.0 : 3.0 / (8.0 * n);
        out.positions.push_back((1.0 - n * beta) * in.positions[v] + beta * neighbourSum[v]);
    }
    // One new point per edge.
    for (auto& [key, e] : edges) {
        const rb::Vec3& a = in.positions[key >> 32];
        const rb::Vec3& b = in.positions[key & 0xffffffffu];
        e.point = static_cast<int>(out.positions.size());
        out.positions.push_back(e.faces == 2 ? 0.375 * (a + b) + 0.125 * (in.positions[e.opposite[0]] +
                                                                          in.positions[e.opposite[1]])
                                             : 0.5 * (a + b));
    }
    // Four triangles for each old one, keeping the winding.
    out.triangles.reserve(4 * in.triangles.size());
    for (const auto& t : in.triangles) {
        const int a = t[0].v, b = t[1].v, c = t[2].v;
        const int ab = edges[edgeKey(a, b)].point, bc = edges[edgeKey(b, c)].point,
                  ca = edges[edgeKey(c, a)].point;
        for (const auto& tri : {std::array<int, 3>{a, ab, ca}, std::array<int, 3>{ab, b, bc},
                                std::array<int, 3>{ca, bc, c}, std::array<int, 3>{ab, bc, ca}})
            out.triangles.push_back(
                {rb::ObjCorner{tri[0]}, rb::ObjCorner{tri[1]}, rb::ObjCorner{tri[2]}});
    }
    return out;
}
// [loop-subdivision]

/// Write positions and triangles as OBJ (1-based indices).
void writeObj(const rb::ObjData& data, const std::string& path, const std::string& comment) {
    const std::string tmp = path + ".tmp";
    std::FILE* f = std::fopen(tmp.c_str(), "w");
    if (!f) throw rb::InputError(path + ": cannot write");
    std::fprintf(f, "# %s\n# %zu vertices, %zu triangles\n", comment.c_str(),
                 data.positions.size(), data.triangles.size());
    for (const auto& p : data.positions) std::fprintf(f, "v %.9g %.9g %.9g\n", p.x, p.y, p.z);
    for (const auto& t : data.triangles)
        std::fprintf(f, "f %d %d %d\n", t[0].v + 1, t[1].v + 1, t[2].v + 1);
    if (std::fclose(f) != 0 || std::rename(tmp.c_str(), path.c_str()) != 0)
        throw rb::InputError(path + ": cannot write");
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 3 || argc > 4) {
        std::fprintf(stderr, "usage: subdivide in.obj out.obj [steps]\n");
        return 2;
    }
    try {
        const int steps = argc == 4 ? std::atoi(argv[3]) : 1;
        rb::ObjData data = rb::loadObj(argv[1]);
        for (int i = 0; i < steps; ++i) data = loopSubdivide(data);
        writeObj(data, argv[2],
                 std::string(argv[1]) + " Loop-subdivided " + std::to_string(steps) +
                     " time(s) by tests/perf/subdivide");
        std::printf("subdivide: %s -> %s: %zu triangles\n", argv[1], argv[2], data.triangles.size());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "subdivide: %s\n", e.what());
        return 1;
    }
    return 0;
}

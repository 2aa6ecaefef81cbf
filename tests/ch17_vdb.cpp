/// \file
/// Chapter 17 tests: density grids read from NanoVDB files.
///
/// Chapter 17 claims that a smoke grid saved by another program becomes a density field that
/// reads the file's own voxels: at a voxel's centre the density is the voxel's value, between
/// centres it is the trilinear blend of the eight voxels around the point, and beyond the active
/// voxels (one voxel further, where the blend has faded out) it is zero. The majorant needs
/// maxIn, an upper bound over a box; the tests check it at many random points of random boxes,
/// under a plain and a rotated transform, and that it is exact where the true maximum is known.
/// Files the tests write themselves with NanoVDB's builder give the expected values; broken
/// files (missing, garbage, truncated, a corrupted node offset, a wrong grid name or type, too
/// big for the memory budget) must be refused with a message naming the file. Last, the
/// chapter's own plume, scenes/assets/plume.nvdb, must load with densities in [0, 1].
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/memory_budget.h"
#include "media/tracking.h"
#include "media/vdb_density.h"
#include "test_helpers.h"

#if __has_include(<nanovdb/NanoVDB.h>)
#include <nanovdb/util/GridBuilder.h>
#include <nanovdb/util/IO.h>
#define RB_TEST_NANOVDB 1
#endif

using Catch::Contains;
using rb::Vec3;
using rbtest::meanAndError;
using rbtest::sidak;

namespace {

/// The message of the InputError that loading grid `name` of `path` throws ("" if none).
std::string vdbError(const std::string& path, const std::string& name = "density",
                     const rb::MemoryBudget* memory = nullptr) {
    try {
        rb::loadVdbDensity(path, name, memory);
    } catch (const rb::InputError& e) {
        return e.what();
    }
    return "";
}

/// The bytes of a file.
std::string readAll(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

#ifdef RB_TEST_NANOVDB

/// The test grid's voxel size and the world position of voxel (0, 0, 0)'s centre.
constexpr double kVoxel = 0.5;
const Vec3 kOrigin(1.0, 2.0, 3.0);

/// The value of voxel (i, j, k) of the 4 × 4 × 4 block at indices 0..3: linear in the index.
float blockValue(int i, int j, int k) {
    return float(0.25 + 0.05 * i + 0.1 * j + 0.15 * k);
}

/// The isolated voxel at index (10, 10, 10) and its value.
const nanovdb::Coord kLone(10, 10, 10);
constexpr float kLoneValue = 0.8f;

/// World point of index-space point x in the test grid.
Vec3 world(const Vec3& x) {
    return kOrigin + kVoxel * x;
}

/// The test grid "density": the block and the lone voxel, under `map` (index to world).
nanovdb::GridHandle<> densityGrid(const nanovdb::Map& map) {
    nanovdb::GridBuilder<float> builder(0.0f, nanovdb::GridClass::FogVolume);
    auto voxels = builder.getAccessor();
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) {
            for (int k = 0; k < 4; ++k)
                voxels.setValue(nanovdb::Coord(i, j, k), blockValue(i, j, k));
        }
    }
    voxels.setValue(kLone, kLoneValue);
    return builder.getHandle(map, "density");
}

/// The plain map: world = kOrigin + kVoxel · index.
nanovdb::Map plainMap() {
    nanovdb::Map map;
    map.set(kVoxel, nanovdb::Vec3d(kOrigin.x, kOrigin.y, kOrigin.z), 1.0);
    return map;
}

/// A map that also turns the grid 30° about y and 20° about x.
nanovdb::Map rotatedMap() {
    const double a = 30.0 * M_PI / 180.0, b = 20.0 * M_PI / 180.0;
    const double ry[3][3] = {
        {std::cos(a), 0, std::sin(a)}, {0, 1, 0}, {-std::sin(a), 0, std::cos(a)}};
    const double rx[3][3] = {
        {1, 0, 0}, {0, std::cos(b), -std::sin(b)}, {0, std::sin(b), std::cos(b)}};
    double mat[3][3], inv[3][3];
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) {
            double sum = 0.0;
            for (int n = 0; n < 3; ++n) sum += ry[r][n] * rx[n][c];
            mat[r][c] = kVoxel * sum;
        }
    }
    // A rotation's inverse is its transpose
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) inv[r][c] = mat[c][r] / (kVoxel * kVoxel);
    }
    nanovdb::Map map;
    map.set(mat, inv, nanovdb::Vec3d(kOrigin.x, kOrigin.y, kOrigin.z), 1.0);
    return map;
}

/// A file holding "density" (float), "temperature" (float) and "velocity" (Vec3f).
std::string writeThreeGrids(const rbtest::TempDir& dir) {
    std::vector<nanovdb::GridHandle<>> handles;
    handles.push_back(densityGrid(plainMap()));
    nanovdb::GridBuilder<float> temperature(0.0f);
    temperature.getAccessor().setValue(nanovdb::Coord(0), 300.0f);
    handles.push_back(temperature.getHandle(1.0, nanovdb::Vec3d(0.0), "temperature"));
    nanovdb::GridBuilder<nanovdb::Vec3f> velocity(nanovdb::Vec3f(0.0f));
    velocity.getAccessor().setValue(nanovdb::Coord(0), nanovdb::Vec3f(1.0f, 0.0f, 0.0f));
    handles.push_back(velocity.getHandle(1.0, nanovdb::Vec3d(0.0), "velocity"));
    const std::string path = (dir.path() / "three.nvdb").string();
    nanovdb::io::writeGrids(path, handles);
    return path;
}

/// A file holding only the test grid "density" under `map`.
std::string writeDensity(const rbtest::TempDir& dir, const std::string& name,
                         const nanovdb::Map& map) {
    const std::string path = (dir.path() / name).string();
    nanovdb::io::writeGrid(path, densityGrid(map));
    return path;
}

/// World point of index-space point x under `map`.
Vec3 mapped(const nanovdb::Map& map, const Vec3& x) {
    const nanovdb::Vec3d w = map.applyMap(nanovdb::Vec3d(x.x, x.y, x.z));
    return Vec3(w[0], w[1], w[2]);
}

/// The test grid under `map`, written to a file in `dir` and read back as a scene reads it.
std::shared_ptr<const rb::DensityField> loadTestGrid(const rbtest::TempDir& dir,
                                                     const nanovdb::Map& map) {
    return rb::loadVdbDensity(writeDensity(dir, "grid.nvdb", map), "density", nullptr);
}

#endif

}  // namespace

#ifdef RB_TEST_NANOVDB

SCENARIO("a density grid written with NanoVDB reads back voxel for voxel", "[ch17]") {
    REQUIRE(rb::vdbSupported());
    GIVEN("a 4 × 4 × 4 block of voxels and one lone voxel, 0.5 apart, voxel 0 at (1, 2, 3)") {
        rbtest::TempDir dir;
        const auto field = loadTestGrid(dir, plainMap());
        WHEN("the density is read at voxel centres") {
            THEN("it is each voxel's value exactly") {
                for (int i = 0; i < 4; ++i) {
                    for (int j = 0; j < 4; ++j) {
                        for (int k = 0; k < 4; ++k) {
                            CAPTURE(i, j, k);
                            REQUIRE(field->at(world(Vec3(i, j, k))) == blockValue(i, j, k));
                        }
                    }
                }
                REQUIRE(field->at(world(Vec3(10, 10, 10))) == kLoneValue);
            }
        }
        WHEN("it is read between the block's voxel centres") {
            THEN("it is the linear function the voxels sample") {
                // Trilinear interpolation reproduces a function linear in each coordinate, so
                // inside the block at(x) = 0.25 + 0.05 x + 0.1 y + 0.15 z (x, y, z in voxels);
                // the voxels hold that function rounded to float (relative error 6e-8).
                rbtest::Rng rng(1);
                for (int n = 0; n < 200; ++n) {
                    const Vec3 x(rng.uniform(0, 3), rng.uniform(0, 3), rng.uniform(0, 3));
                    CAPTURE(x.x, x.y, x.z);
                    REQUIRE(field->at(world(x)) ==
                            Approx(0.25 + 0.05 * x.x + 0.1 * x.y + 0.15 * x.z).epsilon(1e-6));
                }
            }
        }
        WHEN("it is read around the lone voxel") {
            THEN("it is the tent (1 − |dx|)(1 − |dy|)(1 − |dz|) times the voxel's value") {
                // The lone voxel's seven neighbours in each blend are inactive (zero), so only
                // its own weight, the product of the three 1 − |offset| factors, remains.
                rbtest::Rng rng(2);
                for (int n = 0; n < 200; ++n) {
                    const Vec3 d(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
                    CAPTURE(d.x, d.y, d.z);
                    const double tent =
                        (1 - std::abs(d.x)) * (1 - std::abs(d.y)) * (1 - std::abs(d.z));
                    REQUIRE(field->at(world(Vec3(10.0) + d)) ==
                            Approx(kLoneValue * tent).margin(1e-12));
                }
            }
        }
        WHEN("it is read beyond the active voxels") {
            THEN("it fades to zero one voxel out, and stays zero") {
                // Half a voxel out, the blend gives the edge voxel half its weight
                REQUIRE(field->at(world(Vec3(-0.5, 0, 0))) == Approx(0.5 * blockValue(0, 0, 0)));
                for (const Vec3& x : {Vec3(-1, 0, 0), Vec3(0, 4, 0), Vec3(2, 2, -1.5),
                                      Vec3(6, 6, 6), Vec3(11, 10, 10), Vec3(-1e9, 0, 0)}) {
                    CAPTURE(x.x, x.y, x.z);
                    REQUIRE(field->at(world(x)) == 0.0);
                }
            }
            THEN("its bounds are the active voxels' box grown by one voxel") {
                // Index box [-1, 11]³, mapped by world = (1, 2, 3) + 0.5 · index
                const rb::AABB box = field->bounds();
                REQUIRE(box.lo == Vec3(0.5, 1.5, 2.5));
                REQUIRE(box.hi == Vec3(6.5, 7.5, 8.5));
            }
        }
    }
}

SCENARIO("a density grid's optical depth along a line is integrated exactly, cell by cell",
         "[ch17]") {
    REQUIRE(rb::vdbSupported());
    GIVEN("the 4 × 4 × 4 block and the lone voxel, 0.5 apart") {
        rbtest::TempDir dir;
        const auto field = loadTestGrid(dir, plainMap());
        REQUIRE(field->integrable());
        WHEN("a line parallel to x passes the lone voxel at offsets (dy, dz) in voxels") {
            THEN("its depth is the tent's integral, value · (1 − |dy|)(1 − |dz|) · 0.5 / |d|") {
                // Source: along x the tent is (1 − |u|) over u in [−1, 1] (voxels), whose
                // integral is 1; a voxel is 0.5 world units, and t runs |d| world units per unit.
                for (const double speed : {1.0, 2.5}) {
                    for (const auto& [dy, dz] : {std::pair{0.0, 0.0}, {0.3, -0.6}, {-0.9, 0.45}}) {
                        CAPTURE(speed, dy, dz);
                        const Vec3 o = world(Vec3(4.0, 10.0 + dy, 10.0 + dz));
                        const double expected =
                            kLoneValue * (1 - std::abs(dy)) * (1 - std::abs(dz)) * kVoxel / speed;
                        REQUIRE(field->depth(o, Vec3(speed, 0, 0), 0.0, 20.0, nullptr, nullptr,
                                             0) == Approx(expected).epsilon(1e-12));
                    }
                }
            }
        }
    }
    GIVEN("the same grid turned 30° about y and 20° about x") {
        rbtest::TempDir dir;
        const auto field = loadTestGrid(dir, rotatedMap());
        WHEN("random lines cross the block, read at random points along them") {
            THEN("every reading is at()'s integral by a fine composite Simpson rule") {
                // Source: the exact integral of a piecewise cubic; composite Simpson with 40,000
                // panels errs only at the cells' kinks, by O(h²) each: below 1e-7 here.
                auto fine = [&](const Vec3& o, const Vec3& d, double a, double b) {
                    const int n = 40000;
                    const double h = (b - a) / n;
                    double sum = field->at(o + a * d) + field->at(o + b * d);
                    for (int i = 1; i < n; ++i)
                        sum += (i % 2 ? 4.0 : 2.0) * field->at(o + (a + i * h) * d);
                    return sum * h / 3.0;
                };
                rbtest::Rng rng(3);
                // Lines through the block's centre, so that every one meets density.
                const Vec3 centre = mapped(rotatedMap(), Vec3(1.5));
                for (int n = 0; n < 20; ++n) {
                    const Vec3 d = glm::normalize(
                        Vec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)));
                    const Vec3 o = centre - 3.0 * d;
                    std::vector<double> at = {rng.uniform(0, 6), rng.uniform(0, 6), 7.0};
                    std::sort(at.begin(), at.end());
                    std::vector<double> depthAt(at.size());
                    const double total = field->depth(o, d, 0.5, 6.0, at.data(), depthAt.data(), 3);
                    CAPTURE(n, d.x, d.y, d.z);
                    REQUIRE(total > 0.5);
                    REQUIRE(total == Approx(fine(o, d, 0.5, 6.0)).epsilon(1e-6).margin(1e-9));
                    for (int i = 0; i < 3; ++i) {
                        // A reading before the segment's start sees none of it, one beyond its
                        // end (t = 7) all of it.
                        const double expected =
                            at[i] <= 0.5 ? 0.0 : fine(o, d, 0.5, std::min(at[i], 6.0));
                        CAPTURE(i, at[i]);
                        REQUIRE(depthAt[i] == Approx(expected).epsilon(1e-6).margin(1e-9));
                    }
                }
            }
        }
    }
}

SCENARIO("through a density grid, ratio tracking estimates the exact transmittance",
         "[ch17][ex17.3]") {
    REQUIRE(rb::vdbSupported());
    GIVEN("a medium of σa = 0.1, σs = 0.4 per unit density over the turned grid") {
        rbtest::TempDir dir;
        rb::Medium m;
        m.sigmaA = rb::Colour(0.1);
        m.sigmaS = rb::Colour(0.4);
        m.density = loadTestGrid(dir, rotatedMap());
        const rb::TrackedMedium tracked(m, rb::Mat4(1.0), m.density->bounds(), 8);
        // A ray through the block's centre, which it passes at t = 1.5.
        const Vec3 u = glm::normalize(Vec3(1.0, 0.6, 0.4));
        const rb::Ray ray{mapped(rotatedMap(), Vec3(1.5)) - 1.5 * u, u};
        const double at[2] = {1.2, 1.6};
        rb::Colour exactAt[2];
        const rb::Colour exact = rb::exactTransmittance(tracked, ray, 0.0, 3.0, at, exactAt, 2);
        WHEN("ratio tracking reads the same ray 200,000 times") {
            // Three z-tests together at family-wise level 0.001.
            const double z = rbtest::zCritical(sidak(0.001, 3));
            for (int k = 0; k < 3; ++k) {
                const double expected = k < 2 ? exactAt[k].r : exact.r;
                const auto [mean, error] = meanAndError(200'000, [&](int i) {
                    rb::Sampler sampler(1, static_cast<std::uint64_t>(i), 7);
                    rb::Colour trAt[2];
                    const rb::Colour tr =
                        rb::ratioTrackReading(tracked, ray, 0.0, 3.0, at, trAt, 2, sampler);
                    return k < 2 ? trAt[k].r : tr.r;
                });
                THEN("its mean at reading " + std::to_string(k) + " is the exact value") {
                    // Source: ratio tracking is unbiased (Novák, Selle and Jarosz 2014, eq. 7);
                    // the exact value is e^(−σt τ) with τ integrated cell by cell.
                    INFO("mean " << mean << " ± " << error << ", exact " << expected
                                 << ", z = " << (mean - expected) / error);
                    CHECK(expected > 0.05);
                    CHECK(expected < 0.95);
                    CHECK(std::abs(mean - expected) < z * error);
                }
            }
        }
    }
}

SCENARIO("maxIn bounds the density over any box, and is exact around a lone voxel", "[ch17]") {
    for (const bool rotated : {false, true}) {
        const std::string grid =
            rotated ? "the test grid turned 30° about y and 20° about x" : "the test grid";
        GIVEN(grid) {
            rbtest::TempDir dir;
            const auto field = loadTestGrid(dir, rotated ? rotatedMap() : plainMap());
            WHEN("random boxes, from a sliver to the whole grid, are probed at random points") {
                THEN("maxIn is never below the density at any of them") {
                    rbtest::Rng rng(3);
                    const rb::AABB all = field->bounds();
                    int positive = 0;
                    for (int box = 0; box < 2000; ++box) {
                        Vec3 lo, hi;
                        const double size = std::pow(10.0, rng.uniform(-3, 1));
                        for (int a = 0; a < 3; ++a) {
                            const double centre = rng.uniform(all.lo[a], all.hi[a]);
                            const double half = 0.5 * size * rng.uniform();
                            lo[a] = centre - half;
                            hi[a] = centre + half;
                        }
                        const double bound = field->maxIn(lo, hi);
                        for (int n = 0; n < 20; ++n) {
                            const Vec3 p(rng.uniform(lo.x, hi.x), rng.uniform(lo.y, hi.y),
                                         rng.uniform(lo.z, hi.z));
                            const double density = field->at(p);
                            positive += density > 0.0;
                            CAPTURE(lo.x, lo.y, lo.z, hi.x, hi.y, hi.z, p.x, p.y, p.z);
                            REQUIRE(density <= bound);
                        }
                    }
                    // The probes must reach the smoke, or the test proves nothing
                    REQUIRE(positive > 1000);
                }
            }
            if (!rotated) {
                WHEN("the box holds the lone voxel's neighbourhood, ±0.5 voxel around its centre") {
                    THEN("maxIn is the voxel's value, the density at its centre") {
                        // Around the lone voxel the density is the tent, largest at the centre
                        REQUIRE(field->maxIn(world(Vec3(9.5)), world(Vec3(10.5))) == kLoneValue);
                    }
                }
            }
            WHEN("the box is far from every active voxel") {
                THEN("maxIn is zero") {
                    REQUIRE(field->maxIn(Vec3(100), Vec3(101)) == 0.0);
                    REQUIRE(field->maxIn(Vec3(-101), Vec3(-100)) == 0.0);
                }
            }
            WHEN("the box is all of space") {
                THEN("maxIn is the largest voxel, 0.25 + 0.05·3 + 0.1·3 + 0.15·3") {
                    const double inf = std::numeric_limits<double>::infinity();
                    REQUIRE(field->maxIn(Vec3(-inf), Vec3(inf)) == blockValue(3, 3, 3));
                }
            }
        }
    }
}

SCENARIO("broken VDB input is refused with a message naming the file", "[ch17]") {
    rbtest::TempDir dir;
    const std::string good = writeThreeGrids(dir);
    const std::string bytes = readAll(good);
    GIVEN("a file that does not exist") {
        const std::string path = (dir.path() / "missing.nvdb").string();
        THEN("the message says so") {
            REQUIRE_THAT(vdbError(path), Contains(path) && Contains("no such file"));
        }
    }
    GIVEN("a text file") {
        const std::string path = dir.write("garbage.nvdb", "this is not a voxel grid at all\n");
        THEN("it is not a NanoVDB file") {
            REQUIRE_THAT(vdbError(path), Contains(path) && Contains("not a NanoVDB file"));
        }
    }
    GIVEN("an OpenVDB file (its magic number, then anything)") {
        const std::string path =
            dir.write("smoke.vdb", std::string("\x20\x42\x44\x56\0\0\0\0", 8) + "rest");
        THEN("the message says to convert it") {
            REQUIRE_THAT(vdbError(path), Contains(path) && Contains("nanovdb_convert"));
        }
    }
    GIVEN("copies of a good file cut short at many lengths") {
        THEN("every one is refused, none crashes or loads") {
            for (std::size_t length :
                 {std::size_t(3), std::size_t(10), std::size_t(16), std::size_t(100),
                  std::size_t(700), bytes.size() / 2, bytes.size() - 1}) {
                const std::string path = dir.write("cut.nvdb", bytes.substr(0, length));
                CAPTURE(length);
                REQUIRE_THAT(vdbError(path), Contains(path));
            }
            const std::string path = dir.write("cut.nvdb", bytes.substr(0, bytes.size() - 1));
            REQUIRE_THAT(vdbError(path), Contains("truncated or corrupt"));
        }
    }
    GIVEN("a file whose first grid declares 1 TiB of bytes") {
        std::string huge = bytes;
        const std::uint64_t tebibyte = std::uint64_t(1) << 40;
        for (std::size_t field : {offsetof(nanovdb::io::MetaData, gridSize),
                                  offsetof(nanovdb::io::MetaData, fileSize)}) {
            huge.replace(sizeof(nanovdb::io::Header) + field, sizeof tebibyte,
                         reinterpret_cast<const char*>(&tebibyte), sizeof tebibyte);
        }
        const std::string path = dir.write("huge.nvdb", huge);
        THEN("the size is checked against the file's own, before any allocation") {
            REQUIRE_THAT(vdbError(path), Contains(path) && Contains("truncated or corrupt"));
        }
    }
    GIVEN("a file whose root points its first child far past the grid's end") {
        // The first grid's bytes start after the segment header and its three descriptions;
        // the root follows the grid and tree headers, its tiles follow the root's own data.
        std::string broken = bytes;
        std::size_t offset = sizeof(nanovdb::io::Header);
        for (const char* name : {"density", "temperature", "velocity"}) {
            offset += sizeof(nanovdb::io::MetaData) + std::strlen(name) + 1;
        }
        using Root = nanovdb::NanoGrid<float>::TreeType::RootType::DataType;
        offset += sizeof(nanovdb::GridData) + sizeof(nanovdb::NanoGrid<float>::TreeType::DataType) +
                  sizeof(Root) + offsetof(Root::Tile, child);
        const std::int64_t farAway = std::int64_t(1) << 40;
        broken.replace(offset, sizeof farAway, reinterpret_cast<const char*>(&farAway),
                       sizeof farAway);
        const std::string path = dir.write("broken.nvdb", broken);
        THEN("it is refused as corrupt before anything reads the node") {
            REQUIRE_THAT(vdbError(path), Contains(path) && Contains("corrupt"));
        }
    }
    GIVEN("a grid name the file does not hold") {
        THEN("the message lists the names and types it has") {
            REQUIRE_THAT(vdbError(good, "smoke"),
                         Contains(good) && Contains("'smoke'") && Contains("'density' (float)") &&
                             Contains("'temperature' (float)") && Contains("'velocity' (Vec3f)"));
        }
    }
    GIVEN("the name of a grid of vectors") {
        THEN("it is refused: a density needs a float grid") {
            REQUIRE_THAT(vdbError(good, "velocity"), Contains(good) && Contains("float grid"));
        }
    }
    GIVEN("a memory budget with 1000 bytes left") {
        rb::MemoryBudget budget;
        budget.limit = rb::residentBytes() + 1000;
        budget.origin = "a test budget";
        THEN("the grid is refused before it is read") {
            REQUIRE_THAT(vdbError(good, "density", &budget),
                         Contains(good) && Contains("density") && Contains("a test budget"));
        }
    }
    GIVEN("the good file") {
        THEN("each float grid loads") {
            REQUIRE(vdbError(good, "density") == "");
            REQUIRE(vdbError(good, "temperature") == "");
        }
    }
}

SCENARIO("the chapter's smoke plume loads, with densities in [0, 1]", "[ch17]") {
    GIVEN("scenes/assets/plume.nvdb") {
        const std::string path = rbtest::sourceDir() + "/scenes/assets/plume.nvdb";
        const auto plume = rb::loadVdbDensity(path, "density", nullptr);
        WHEN("its density is sampled on a 24 × 48 × 24 lattice over its bounds") {
            const rb::AABB box = plume->bounds();
            double largest = 0.0;
            int positive = 0;
            bool inRange = true;
            for (int i = 0; i < 24; ++i) {
                for (int j = 0; j < 48; ++j) {
                    for (int k = 0; k < 24; ++k) {
                        const Vec3 t((i + 0.5) / 24, (j + 0.5) / 48, (k + 0.5) / 24);
                        const double d = plume->at(box.lo + t * (box.hi - box.lo));
                        inRange = inRange && d >= 0.0 && d <= 1.0;
                        largest = std::max(largest, d);
                        positive += d > 0.0;
                    }
                }
            }
            THEN("it is a plume 1 wide and 2 tall on y = 0, non-empty, every density in [0, 1]") {
                REQUIRE(box.lo.y < 0.0);
                REQUIRE(box.hi.y <= 2.0 + 0.05);
                REQUIRE(box.hi.x - box.lo.x <= 1.0 + 0.1);
                REQUIRE(inRange);
                REQUIRE(positive > 1000);
                REQUIRE(largest > 0.5);
                REQUIRE(plume->maxIn(box.lo, box.hi) <= 1.0);
                REQUIRE(plume->maxIn(box.lo, box.hi) >= largest);
            }
        }
    }
}

#else

SCENARIO("without NanoVDB, loading a grid says how to get it", "[ch17]") {
    REQUIRE_FALSE(rb::vdbSupported());
    REQUIRE_THAT(vdbError("plume.nvdb"), Contains("plume.nvdb") && Contains("make deps"));
}

#endif

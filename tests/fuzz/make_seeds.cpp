/// \file
/// Writes the seed corpora of fuzz_journal, fuzz_stats, fuzz_compare and fuzz_vdb with the
/// project's own writers, each file a few hundred bytes: build the target fuzz_make_seeds, then
/// run it with tests/fuzz/corpus as its argument. Not a test; the output is committed.
#include <stb_image_write.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <random>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "app/block_stats.h"
#include "app/image_compare.h"
#include "mpi/journal.h"
#include "seed_identity.h"

#ifdef RB_HAVE_NANOVDB
#include <nanovdb/util/GridBuilder.h>
#include <nanovdb/util/GridChecksum.h>
#include <nanovdb/util/IO.h>
#endif

namespace fs = std::filesystem;

namespace {

/// A w × h image of uniform noise from `random`.
rb::golden::Image noise(int w, int h, std::mt19937& random) {
    rb::golden::Image image = rb::golden::Image::filled(w, h, 0.0f, 0.0f, 0.0f);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (float& v : image.rgb) v = unit(random);
    return image;
}

/// Journals for seed_identity.h: the header alone, two tiles, and two tiles with a torn third.
void journals(const fs::path& dir) {
    const std::vector<float> tile(4 * 4 * 3, 0.5f);
    {
        rb::JournalWriter(fs::path(dir / "header-only.journal").string(),
                          rbfuzz::journalIdentity());
    }
    for (const auto& [name, tiles] :
         {std::pair{"two-tiles.journal", 2}, {"torn-third.journal", 3}}) {
        rb::JournalWriter writer(fs::path(dir / name).string(), rbfuzz::journalIdentity());
        for (int k = 0; k < tiles; ++k) writer.append(3 - k, tile);
    }
    fs::resize_file(dir / "torn-third.journal", fs::file_size(dir / "torn-third.journal") - 5);
}

/// Statistics of four noise renders: 16 × 12 in blocks of 8, and 20 × 9 in blocks of 4.
void stats(const fs::path& dir, std::mt19937& random) {
    for (const auto& [w, h, block] : {std::tuple{16, 12, 8}, std::tuple{20, 9, 4}}) {
        std::vector<rb::golden::Image> renders;
        for (int i = 0; i < 4; ++i) renders.push_back(noise(w, h, random));
        rb::golden::save_block_stats(
            dir / ("noise-" + std::to_string(w) + "x" + std::to_string(h) + ".stats"),
            rb::golden::block_stats(renders, block));
    }
}

/// PNGs of 1, 3 and 4 channels, 8 bits, as stb writes them.
void pngs(const fs::path& dir, std::mt19937& random) {
    rb::golden::save_png(dir / "rgb-4x3.png", noise(4, 3, random));
    const unsigned char pixels[16] = {0,  64, 128, 255, 10, 20,  30,  40,
                                      50, 60, 70,  80,  90, 100, 110, 120};
    stbi_write_png(fs::path(dir / "grey-3x2.png").c_str(), 3, 2, 1, pixels, 3);
    stbi_write_png(fs::path(dir / "rgba-2x2.png").c_str(), 2, 2, 4, pixels, 8);
}

#ifdef RB_HAVE_NANOVDB
/// An empty float grid `name` (no active values): 0.5 units a voxel, origin at 0.
nanovdb::GridHandle<> emptyGrid(const std::string& name) {
    nanovdb::GridBuilder<float> builder(0.0f, nanovdb::GridClass::FogVolume);
    return builder.getHandle(0.5, nanovdb::Vec3d(0.0), name);
}

/// A grid "density" whose one active value is a root tile of 4096³ voxels of 0.5: the
/// smallest grid with active values, under 1 KB (a grid with one voxel holds a 256 KB node).
/// An empty grid ends with its root, so the tile is appended to its bytes.
nanovdb::GridHandle<> rootTileGrid() {
    using Grid = nanovdb::NanoGrid<float>;
    using Tile = Grid::TreeType::RootType::DataType::Tile;
    const nanovdb::GridHandle<> empty = emptyGrid("density");
    nanovdb::HostBuffer buffer = nanovdb::HostBuffer::create(empty.size() + sizeof(Tile));
    std::copy(empty.data(), empty.data() + empty.size(), buffer.data());
    auto& grid = *reinterpret_cast<Grid*>(buffer.data());
    grid.data()->mGridSize = buffer.size();
    auto& root = *grid.tree().root().data();
    root.mTableSize = 1;
    root.tile(0)->setValue(nanovdb::Coord(0), true, 0.5f);
    nanovdb::updateChecksum(grid, nanovdb::ChecksumMode::Partial);
    return nanovdb::GridHandle<>(std::move(buffer));
}

/// A grid with a root tile, an empty one, and both in one file after a float grid of another
/// name.
void vdbs(const fs::path& dir) {
    nanovdb::io::writeGrid(fs::path(dir / "root-tile.nvdb").string(), rootTileGrid());
    nanovdb::io::writeGrid(fs::path(dir / "empty.nvdb").string(), emptyGrid("density"));
    std::vector<nanovdb::GridHandle<>> two;
    two.push_back(emptyGrid("temperature"));
    two.push_back(rootTileGrid());
    nanovdb::io::writeGrids(fs::path(dir / "two-grids.nvdb").string(), two);
}
#endif

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s CORPUS_FOLDER (tests/fuzz/corpus)\n", argv[0]);
        return 2;
    }
    const fs::path corpus = argv[1];
    for (const char* target : {"journal", "stats", "compare", "vdb"})
        fs::create_directories(corpus / target);
    std::mt19937 random(1);
    journals(corpus / "journal");
    stats(corpus / "stats", random);
    pngs(corpus / "compare", random);
#ifdef RB_HAVE_NANOVDB
    vdbs(corpus / "vdb");
#endif
    return 0;
}

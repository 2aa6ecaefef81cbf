/// \file
/// Tests of the tile journal (src/mpi/journal.h), which an MPI render keeps beside its image.
///
/// The journal claims that it gives back exactly the tiles it was given, bit for bit, in the
/// order written; that a record cut short by a kill anywhere inside it, or damaged, is dropped
/// with everything after it while every earlier record survives; and that a journal written
/// for another render (another seed, size, scene or rt version) is refused with a message that
/// names what differs. The tests write journals into a temporary folder and cut them at every
/// byte of their last record.
#include "mpi/journal.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "core/error.h"

namespace {

namespace fs = std::filesystem;

/// A render's identity as rt builds it (main.cpp's renderIdentity), with one field changed.
rb::RenderIdentity identity(const std::string& output, const std::string& seed = "0") {
    return {output,
            {{"version", "0.16.0 (abc1234)"},
             {"scene", "showcase.lua (14598 bytes, hash 42)"},
             {"size", "64x48"},
             {"seed", seed},
             {"sampling", "features all, spp 1"}}};
}

/// A fresh folder for one scenario's files.
fs::path scratch(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("raybook-journal-test-" + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

/// Tile pixels with awkward floats: a NaN, infinity, negative zero and a denormal, which must
/// come back bit for bit.
std::vector<float> awkwardPixels(int count, float base) {
    std::vector<float> p(static_cast<std::size_t>(count));
    for (int i = 0; i < count; ++i) p[static_cast<std::size_t>(i)] = base + 0.001f * i;
    p[0] = std::numeric_limits<float>::quiet_NaN();
    p[1] = std::numeric_limits<float>::infinity();
    p[2] = -0.0f;
    p[3] = std::numeric_limits<float>::denorm_min();
    return p;
}

/// True when two float arrays hold the same bits.
bool sameBits(const std::vector<float>& a, const std::vector<float>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

}  // namespace

SCENARIO("a journal gives back every tile it was given, bit for bit, in order", "[mpi]") {
    GIVEN("a journal with three tiles appended") {
        const fs::path dir = scratch("roundtrip");
        const std::string path = rb::journalPath((dir / "out.png").string());
        const std::vector<float> a = awkwardPixels(768, 0.25f), b = awkwardPixels(96, 2.0f),
                                 c = awkwardPixels(768, -1.0f);
        {
            rb::JournalWriter journal(path, identity("out.png"));
            journal.append(7, a);
            journal.append(0, b);
            journal.append(12, c);
        }
        WHEN("it is read back for the same render") {
            const auto tiles = rb::readJournal(path, identity("out.png"));
            THEN("it holds the three tiles in the order written, with the same bits") {
                REQUIRE(tiles.size() == 3);
                CHECK(tiles[0].position == 7);
                CHECK(tiles[1].position == 0);
                CHECK(tiles[2].position == 12);
                CHECK(sameBits(tiles[0].pixels, a));
                CHECK(sameBits(tiles[1].pixels, b));
                CHECK(sameBits(tiles[2].pixels, c));
            }
        }
        WHEN("a resumed render starts a new journal from those tiles and adds one") {
            auto kept = rb::readJournal(path, identity("out.png"));
            {
                rb::JournalWriter journal(path, identity("out.png"), kept);
                journal.append(3, a);
            }
            THEN("the new journal holds the old tiles and the new one") {
                const auto tiles = rb::readJournal(path, identity("out.png"));
                REQUIRE(tiles.size() == 4);
                CHECK(tiles[3].position == 3);
                CHECK(sameBits(tiles[2].pixels, c));
            }
        }
        WHEN("the image is written and the journal discarded") {
            rb::JournalWriter journal(path, identity("out.png"), {});
            journal.discard();
            THEN("no file is left") {
                CHECK_FALSE(fs::exists(path));
            }
        }
    }
}

SCENARIO("a record cut short by a kill is dropped, and every earlier one survives", "[mpi]") {
    GIVEN("a journal of two tiles") {
        const fs::path dir = scratch("torn");
        const std::string path = rb::journalPath((dir / "out.png").string());
        const std::vector<float> a = awkwardPixels(48, 1.0f), b = awkwardPixels(48, 3.0f);
        {
            rb::JournalWriter journal(path, identity("out.png"));
            journal.append(1, a);
            journal.append(2, b);
        }
        const auto full = fs::file_size(path);
        // One record: "TILE", position, count, 48 floats, checksum.
        const std::uintmax_t record = 4 + 4 + 4 + 48 * 4 + 8;
        WHEN("the file is cut at every byte inside its last record") {
            int wrong = 0;
            for (std::uintmax_t size = full - record; size < full; ++size) {
                fs::copy_file(path, dir / "cut", fs::copy_options::overwrite_existing);
                fs::resize_file(dir / "cut", size);
                const auto tiles = rb::readJournal((dir / "cut").string(), identity("out.png"));
                if (tiles.size() != 1 || !sameBits(tiles[0].pixels, a)) ++wrong;
            }
            THEN("each cut gives back exactly the first tile") {
                CHECK(wrong == 0);
            }
        }
        WHEN("one byte of the last record's pixels is damaged") {
            std::fstream f(path, std::ios::in | std::ios::out | std::ios::binary);
            f.seekp(static_cast<std::streamoff>(full - 20));
            f.put('\x7f');
            f.close();
            THEN("its checksum drops it") {
                CHECK(rb::readJournal(path, identity("out.png")).size() == 1);
            }
        }
    }
}

SCENARIO("a journal written for another render is refused, naming what differs", "[mpi]") {
    GIVEN("a journal written for seed 0") {
        const fs::path dir = scratch("refused");
        const std::string path = rb::journalPath((dir / "out.png").string());
        {
            rb::JournalWriter journal(path, identity("out.png", "0"));
            journal.append(0, awkwardPixels(12, 0.0f));
        }
        THEN("a render with seed 5 is refused with both seeds in the message") {
            CHECK_THROWS_WITH(rb::readJournal(path, identity("out.png", "5")),
                              Catch::Contains("seed 0, this render has 5"));
        }
        THEN("a render of another size is refused, naming the size") {
            rb::RenderIdentity other = identity("out.png");
            other.fields[2].second = "64x64";
            CHECK_THROWS_WITH(rb::readJournal(path, other),
                              Catch::Contains("size 64x48, this render has 64x64"));
        }
        THEN("a file that is no journal is refused as such") {
            std::ofstream(dir / "junk") << "P6 not a journal\n";
            CHECK_THROWS_AS(rb::readJournal((dir / "junk").string(), identity("out.png")),
                            rb::InputError);
        }
    }
}

SCENARIO("a journal refuses a render whose scene reads a changed or another file", "[mpi]") {
    GIVEN("a journal of a scene that read a texture, by size and hash") {
        const fs::path dir = scratch("files");
        const std::string path = rb::journalPath((dir / "out.png").string());
        rb::RenderIdentity written = identity("out.png");
        written.fields.emplace_back("file assets/wood.png", "627 bytes, hash 00ff");
        {
            rb::JournalWriter journal(path, written);
            journal.append(0, awkwardPixels(12, 0.0f));
        }
        THEN("the same file's render reads it back") {
            CHECK(rb::readJournal(path, written).size() == 1);
        }
        THEN("a changed texture is refused, naming the file and both contents") {
            rb::RenderIdentity changed = written;
            changed.fields.back().second = "640 bytes, hash 0a0a";
            CHECK_THROWS_WITH(rb::readJournal(path, changed),
                              Catch::Contains("assets/wood.png changed since the journal") &&
                                  Catch::Contains("627 bytes, hash 00ff; now 640 bytes"));
        }
        THEN("a scene that reads another file is refused, naming it") {
            rb::RenderIdentity other = written;
            other.fields.back().first = "file assets/plume.nvdb";
            CHECK_THROWS_WITH(rb::readJournal(path, other),
                              Catch::Contains("assets/plume.nvdb was not read by the render"));
        }
    }
}

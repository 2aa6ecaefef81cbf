/// \file
/// Chapter 1 tests: the memory budget.
///
/// rt claims that a scene too big for the machine fails early with a clear message instead of
/// driving the machine into swap. That rests on three things these tests check: --max-memory
/// reads sizes as people write them (and refuses the rest), the estimates saturate instead of
/// overflowing, and a mesh is refused while it is read, as soon as what it needs passes what
/// the budget leaves free (never after). The whole path through ./rt, with a 50-million-face
/// OBJ, an oversized image, a full disk and a read-only folder, is tests/resources.sh.
#include <catch2/catch.hpp>
#include <limits>
#include <sstream>
#include <string>

#include "bvh/obj.h"
#include "core/error.h"
#include "core/memory_budget.h"

using Catch::Matchers::Contains;

namespace {

constexpr std::uint64_t kMiB = std::uint64_t(1) << 20;

/// OBJ text of `n` triangles that share three vertices.
std::string trianglesObj(int n) {
    std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    for (int i = 0; i < n; ++i) text += "f 1 2 3\n";
    return text;
}

/// Parse OBJ text `text` under a budget that leaves `free` bytes on top of what the process
/// holds when the parse starts (the text is in memory before the budget is measured).
rb::ObjData parseLeaving(const std::string& text, const std::string& name, std::uint64_t free) {
    std::istringstream in(text);
    rb::MemoryBudget budget;
    budget.limit = rb::residentBytes() + free;
    budget.origin = "a test budget";
    return rb::parseObj(in, name, budget);
}

}  // namespace

SCENARIO("--max-memory reads sizes in bytes and powers of 1024", "[ch01]") {
    GIVEN("sizes written the ways people write them") {
        THEN("the suffixes K, M, G and T multiply by 2^10, 2^20, 2^30 and 2^40, in any case") {
            CHECK(rb::memoryBudgetFromOption("1048576").limit == kMiB);
            CHECK(rb::memoryBudgetFromOption("2048K").limit == 2 * kMiB);
            CHECK(rb::memoryBudgetFromOption("512M").limit == 512 * kMiB);
            CHECK(rb::memoryBudgetFromOption("512MiB").limit == 512 * kMiB);
            CHECK(rb::memoryBudgetFromOption("4g").limit == 4096 * kMiB);
            CHECK(rb::memoryBudgetFromOption("1.5G").limit == 1536 * kMiB);
            CHECK(rb::memoryBudgetFromOption("1T").limit == (std::uint64_t(1) << 40));
        }
        THEN("the budget remembers the option, for its messages") {
            CHECK(rb::memoryBudgetFromOption("64M").origin == "--max-memory 64M");
        }
        THEN("words, unknown suffixes, negatives, NaN and less than 1 MiB are refused") {
            for (const char* bad : {"", "lots", "12Q", "-4G", "nan", "inf", "1000K", "0", "M"})
                CHECK_THROWS_WITH(rb::memoryBudgetFromOption(bad),
                                  Contains("--max-memory: expected a size of at least 1M"));
        }
    }
}

SCENARIO("the default budget is half of the machine's memory", "[ch01]") {
    GIVEN("the default budget") {
        const rb::MemoryBudget budget = rb::defaultMemoryBudget();
        THEN("it is more than this process holds and says where it came from") {
            CHECK(budget.limit > rb::residentBytes());
            CHECK_THAT(budget.origin, Contains("half of this machine's"));
        }
    }
}

SCENARIO("memory estimates saturate instead of wrapping around", "[ch01]") {
    GIVEN("a product that overflows 64 bits") {
        THEN("it is the largest value, and an ordinary one is exact") {
            CHECK(rb::saturatingProduct(std::uint64_t(1) << 40, std::uint64_t(1) << 30) ==
                  std::numeric_limits<std::uint64_t>::max());
            CHECK(rb::saturatingProduct(60000ULL * 60000ULL, rb::kImageBytesPerPixel) ==
                  86'400'000'000ULL);
            CHECK(rb::saturatingProduct(0, std::numeric_limits<std::uint64_t>::max()) == 0);
        }
    }
    GIVEN("an image of 60000 × 60000 pixels and a 1 GiB budget") {
        const rb::MemoryBudget budget = rb::memoryBudgetFromOption("1G");
        THEN("require() refuses it, naming the size needed and the limit") {
            CHECK_THROWS_WITH(budget.require(60000ULL * 60000ULL * rb::kImageBytesPerPixel,
                                             "scene.lua:9", "the image"),
                              Contains("scene.lua:9: the image needs about 80.5 GiB") &&
                                  Contains("of the memory limit of 1.0 GiB (--max-memory 1G)"));
        }
    }
}

SCENARIO("byte counts are printed for people", "[ch01]") {
    THEN("each unit is 1024 of the one before, with one decimal below 100") {
        CHECK(rb::formatBytes(512) == "512 B");
        CHECK(rb::formatBytes(1536) == "1.5 KiB");
        CHECK(rb::formatBytes(300 * kMiB) == "300 MiB");
        CHECK(rb::formatBytes(std::uint64_t(3) << 30) == "3.0 GiB");
    }
}

SCENARIO("a mesh that would not fit is refused while it is read", "[ch03]") {
    GIVEN("a budget that leaves 2 MiB free") {
        WHEN("an OBJ of 5,000 triangles is read (5000 × 272 B + 3 × 48 B = 1.3 MiB)") {
            THEN("it loads") {
                CHECK(parseLeaving(trianglesObj(5000), "small.obj", 2 * kMiB).triangles.size() ==
                      5000);
            }
        }
        WHEN("an OBJ of 100,000 triangles is read (26 MiB)") {
            THEN("the parse stops at the first check past 2 MiB: 8192 triangles, line 8195") {
                // Checks come at 4096 entries and each doubling; 8192 × 272 B = 2.1 MiB > 2 MiB.
                CHECK_THROWS_WITH(
                    parseLeaving(trianglesObj(100000), "big.obj", 2 * kMiB),
                    Contains("big.obj:8195: the mesh read so far (8192 triangles, 3 vertices)") &&
                        Contains("(a test budget)"));
            }
        }
        WHEN("an OBJ of 7,900 triangles, between two checks, is read") {
            THEN("the check at the end of the file still applies: 7900 × 272 B = 2.05 MiB") {
                CHECK_THROWS_WITH(parseLeaving(trianglesObj(7900), "end.obj", 2 * kMiB),
                                  Contains("end.obj:7903: the mesh read so far (7900 triangles"));
            }
        }
    }
    GIVEN("no budget") {
        std::istringstream in(trianglesObj(10000));
        THEN("any size loads") {
            CHECK(rb::parseObj(in, "free.obj").triangles.size() == 10000);
        }
    }
}

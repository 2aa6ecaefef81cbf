/// \file
/// Chapter 1 tests of `--preview`, the quick look before a long render.
///
/// The core claims that `--preview` renders a sixteenth of the pixels (a quarter of each side)
/// with one ray per pixel, no antialiasing and one sample of every distribution the built
/// chapters draw from (area lights, glossy lobes, the lens) and one photon pass, while any of
/// those settings given on the command line still wins. These tests parse command lines as rt
/// does; tests/preview.sh runs rt itself and checks the image's size, that two runs give the
/// same bytes, and the line that says it is a preview.
#include <catch2/catch.hpp>
#include <string>
#include <utility>
#include <vector>

#include "app/options.h"
#include "test_helpers.h"

SCENARIO("--preview renders a quarter of each side with one sample of everything",
         "[ch01][front-door][needs-ch16]") {
    // Parse `args` (after the program name) as the chapter-16 build's rt does.
    const auto parse = [](std::vector<const char*> args) {
        args.insert(args.begin(), "rt");
        return rb::parseCommandLine(static_cast<int>(args.size()), args.data(),
                                    rbtest::chapters(16).built());
    };
    GIVEN("rt --preview scene.lua in the chapter-16 build") {
        const rb::CommandLine cl = parse({"--preview", "scene.lua"});
        THEN("one ray per pixel, no antialiasing, one light, lobe and lens sample, one pass") {
            CHECK(cl.preview);
            CHECK(cl.samplesPerPixel == 1);
            CHECK(cl.featureOptions.at("aa") == "none");
            CHECK(cl.featureOptions.at("light-samples") == "1");
            CHECK(cl.featureOptions.at("glossy-samples") == "1");
            CHECK(cl.featureOptions.at("dof-samples") == "1");
            CHECK(cl.featureOptions.at("photon-passes") == "1");
            CHECK(rb::previewSettings(cl) ==
                  "--spp 1 --aa=none --light-samples=1 --glossy-samples=1 --dof-samples=1 "
                  "--photon-passes=1");
        }
    }
    GIVEN("--preview with settings of its own on the command line") {
        const rb::CommandLine cl =
            parse({"--spp", "4", "--preview", "--light-samples=3", "scene.lua"});
        THEN("those win, and the rest is the preview's") {
            CHECK(cl.samplesPerPixel == 4);
            CHECK(cl.featureOptions.at("light-samples") == "3");
            CHECK(cl.featureOptions.at("glossy-samples") == "1");
        }
    }
    GIVEN("the chapter-3 build, which has none of those chapters") {
        std::vector<const char*> args = {"rt", "--preview", "scene.lua"};
        const rb::CommandLine cl = rb::parseCommandLine(static_cast<int>(args.size()), args.data(),
                                                        rbtest::chapters(3).built());
        THEN("only the ray count is set: no option a chapter of the build does not read") {
            CHECK(cl.samplesPerPixel == 1);
            CHECK(cl.featureOptions.empty());
        }
    }
    WHEN("sizes are reduced") {
        THEN("each side is a quarter, rounded, and never below one pixel") {
            // Source: w' = round(w / 4) = floor((w + 2) / 4), at least 1.
            CHECK(rb::previewSize(256, 192) == std::pair<int, int>(64, 48));
            CHECK(rb::previewSize(250, 190) == std::pair<int, int>(63, 48));
            CHECK(rb::previewSize(3, 1) == std::pair<int, int>(1, 1));
        }
    }
}

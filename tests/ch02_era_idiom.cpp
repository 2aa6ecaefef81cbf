/// \file
/// Chapter 2 tests of the era's finer points: which calls are signs, how a scene without any
/// sign is decided from the way it places scaled objects, and when the era line is worth
/// printing.
///
/// Chapter 2 claims that rt renders a scene in the era it was written for without being told,
/// and stays quiet when there is nothing to say. A sign must be unambiguous: a form raybook
/// documents as its own (`gr.cone('c')`) says nothing. A scene with no sign still shows its
/// era in how it places a scaled object: a pre-2015 author, whose framework post-multiplied,
/// writes translate, then scale; a current author writes scale, then translate. Each test
/// writes a small scene, loads it the way `rt` does, and checks the era and where the shapes
/// land; the last one loads every scene of the project and checks that none changes era.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "scene/lua_scene.h"
#include "scene/scene_era.h"
#include "test_helpers.h"

using Catch::Contains;
using rb::Vec3;

namespace {

/// Load `lua` (as scene.lua in a fresh folder) with chapters 1 to `chapters`, the era detected.
rb::SceneLoadReport loadReport(const std::string& lua, int chapters,
                               std::vector<rb::LoadedRender>* renders = nullptr) {
    rbtest::TempDir dir;
    rb::SceneLoadReport report;
    auto loaded = rb::loadScene(dir.write("scene.lua", lua), rbtest::chapters(chapters),
                                rb::SceneLoadOptions{}, &report);
    if (renders) *renders = std::move(loaded);
    return report;
}

/// A box meant to span x -5..5, y -2..2, z -6..-5.5, placed the way `order` says.
std::string box(const std::string& name, bool translateFirst) {
    const std::string move = name + ":translate(-5, -2, -6)\n";
    const std::string size = name + ":scale(10, 4, 0.5)\n";
    return "local " + name + " = gr.cube('" + name + "')\n" +
           (translateFirst ? move + size : size + move) + "root:add_child(" + name + ")\n";
}

}  // namespace

SCENARIO("the era line is printed only when the scene renders pre-2015 or the order was guessed",
         "[ch02][era]") {
    const std::vector<rb::EraSign> legacy = {{rb::Era::Legacy, "unpack", "s.lua:3"}};
    const std::vector<rb::EraSign> modern = {
        {rb::Era::Modern, "gr.mesh with an .obj file", "s.lua:7"}};
    std::vector<rb::EraSign> both = legacy;
    both.push_back(modern[0]);
    GIVEN("a decision from one era's signs") {
        THEN("pre-2015 is shown, current is not, and either is still explained") {
            CHECK(rb::decideEra(rb::EraChoice::Detect, legacy, "s.lua:2").show);
            const rb::EraDecision d = rb::decideEra(rb::EraChoice::Detect, modern, "s.lua:2");
            CHECK_FALSE(d.show);
            CHECK_THAT(d.line, Contains("current") && Contains("s.lua:7"));
        }
    }
    GIVEN("a guess: conflicting signs, or none") {
        THEN("it is shown when the order matters, and only then") {
            CHECK(rb::decideEra(rb::EraChoice::Detect, both, "s.lua:2").show);
            CHECK_FALSE(rb::decideEra(rb::EraChoice::Detect, both, "").show);
            CHECK(rb::decideEra(rb::EraChoice::Detect, {}, "s.lua:2").show);
            const rb::EraDecision quiet = rb::decideEra(rb::EraChoice::Detect, {}, "");
            CHECK_FALSE(quiet.show);
            CHECK_THAT(quiet.line, Contains("does not matter"));
        }
    }
    GIVEN("a forced era") {
        THEN("--legacy is shown, --modern is not") {
            CHECK(rb::decideEra(rb::EraChoice::Legacy, {}, "").show);
            CHECK_FALSE(rb::decideEra(rb::EraChoice::Modern, legacy, "s.lua:2").show);
        }
    }
}

SCENARIO("a scene without signs is placed by its transform idiom", "[ch02][era][ex2.2]") {
    const std::string head = "root = gr.node('root')\n";
    GIVEN("a box written translate, then scale (the pre-2015 way), and a sphere only moved") {
        std::vector<rb::LoadedRender> renders;
        const rb::SceneLoadReport r =
            loadReport(head + box("wall", true) +
                           "local s = gr.sphere('s')\ns:translate(0, 3, 0)\nroot:add_child(s)\n" +
                           rbtest::renderLine(),
                       2, &renders);
        THEN("the scene renders pre-2015, said with the place of the idiom") {
            CHECK(r.era.era == rb::Era::Legacy);
            CHECK(r.era.show);
            CHECK_THAT(r.era.line, Contains("the pre-2015 way") && Contains("scene.lua:4"));
        }
        THEN("the box spans what its author meant") {
            // Source: post-multiplied, M = T(-5, -2, -6) · S(10, 4, 0.5) sends the unit cube's
            // corners (0,0,0) and (1,1,1) to (-5, -2, -6) and (5, 2, -5.5).
            const rb::AABB b = rbtest::boundsOf(renders[0], "wall");
            CHECK(rbtest::near(b.lo, Vec3(-5, -2, -6)));
            CHECK(rbtest::near(b.hi, Vec3(5, 2, -5.5)));
        }
    }
    GIVEN("the same box written scale, then translate (the current way)") {
        std::vector<rb::LoadedRender> renders;
        const rb::SceneLoadReport r =
            loadReport(head + box("wall", false) + rbtest::renderLine(), 2, &renders);
        THEN("the scene is current, without a line, and the box spans the same place") {
            // Source: pre-multiplied, M = T(-5, -2, -6) · S(10, 4, 0.5), as above.
            CHECK(r.era.era == rb::Era::Modern);
            CHECK_FALSE(r.era.show);
            CHECK_THAT(r.era.line, Contains("the current way") && Contains("scene.lua:4"));
            const rb::AABB b = rbtest::boundsOf(renders[0], "wall");
            CHECK(rbtest::near(b.lo, Vec3(-5, -2, -6)));
            CHECK(rbtest::near(b.hi, Vec3(5, 2, -5.5)));
        }
    }
    GIVEN("one box written each way") {
        const rb::SceneLoadReport r =
            loadReport(head + box("a", true) + box("b", false) + rbtest::renderLine(), 2);
        THEN("the idiom is not clear: current by default, and the guess is said") {
            CHECK(r.era.era == rb::Era::Modern);
            CHECK(r.era.show);
            CHECK_THAT(r.era.line,
                       Contains("no sign") && Contains("scene.lua:4") && Contains("scene.lua:8"));
        }
    }
    GIVEN("a beam written rotate, then stretch (the pre-2015 way), with no other transform") {
        std::vector<rb::LoadedRender> renders;
        const rb::SceneLoadReport r = loadReport(
            head +
                "local beam = gr.cube('beam')\nbeam:rotate('y', 90)\nbeam:scale(4, 1, 1)\n"
                "root:add_child(beam)\n" +
                rbtest::renderLine(),
            2, &renders);
        THEN("the scene renders pre-2015: stretched along x, then turned onto -z") {
            // Source: post-multiplied, M = R_y(90°) · S(4, 1, 1); R_y(90°) sends (x, y, z) to
            // (z, y, -x), so the stretched cube [0,4]x[0,1]x[0,1] lands on [0,1]x[0,1]x[-4,0].
            CHECK(r.era.era == rb::Era::Legacy);
            CHECK_THAT(r.era.line, Contains("the pre-2015 way") && Contains("scene.lua:4"));
            const rb::AABB b = rbtest::boundsOf(renders[0], "beam");
            CHECK(rbtest::near(b.lo, Vec3(0, 0, -4)));
            CHECK(rbtest::near(b.hi, Vec3(1, 1, 0)));
        }
    }
    GIVEN("a pane centred, stretched, turned and placed: translate, scale, rotate, translate") {
        // The current way (chapter 5's pane): the scale comes before the rotation. Its
        // translates come both before and after the scale, which alone would tell nothing.
        const rb::SceneLoadReport r =
            loadReport(head +
                           "local pane = gr.cube('pane')\npane:translate(-0.5, 0, -0.5)\n"
                           "pane:scale(1.8, 1.9, 0.3)\npane:rotate('y', 40)\n"
                           "pane:translate(-0.1, -1.05, -3.4)\nroot:add_child(pane)\n" +
                           rbtest::renderLine(),
                       2);
        THEN("the scene is current, from scale, then rotate, without a line") {
            CHECK(r.era.era == rb::Era::Modern);
            CHECK_FALSE(r.era.show);
            CHECK_THAT(r.era.line, Contains("the current way") && Contains("scene.lua:5"));
        }
    }
    GIVEN("a translate, a scale and a translate again, with no rotation") {
        const rb::SceneLoadReport r =
            loadReport(head +
                           "local s = gr.cube('s')\ns:translate(-0.5, 0, 0)\ns:scale(2, 1, 1)\n"
                           "s:translate(3, 0, 0)\nroot:add_child(s)\n" +
                           rbtest::renderLine(),
                       2);
        THEN("the idiom is not clear: current by default, and the guess is said") {
            CHECK(r.era.era == rb::Era::Modern);
            CHECK(r.era.show);
            CHECK_THAT(r.era.line, Contains("no sign"));
        }
    }
    GIVEN("a translate, then a scale that leaves the translated axis alone") {
        // Source: T(0, 3, 0) and S(2, 1, 2) commute (the scale is 1 along y), so the order
        // tells nothing about the era.
        const rb::SceneLoadReport r =
            loadReport(head +
                           "local s = gr.sphere('s')\ns:translate(0, 3, 0)\ns:scale(2, 1, 2)\n"
                           "root:add_child(s)\n" +
                           rbtest::renderLine(),
                       2);
        THEN("there is no vote: current, without a line") {
            CHECK(r.era.era == rb::Era::Modern);
            CHECK_FALSE(r.era.show);
        }
    }
}

SCENARIO("gr.cone('c'), raybook's own first form, does not switch a current scene's era",
         "[ch02][era][needs-ch15]") {
    GIVEN("a current scene with gr.cone('c') and a box written scale, then translate") {
        std::vector<rb::LoadedRender> renders;
        const rb::SceneLoadReport r =
            loadReport("root = gr.node('root')\nlocal c = gr.cone('c')\nroot:add_child(c)\n" +
                           box("wall", false) + rbtest::renderLine(),
                       15, &renders);
        THEN("the scene stays current, and the box stays where it was written") {
            // Source: pre-multiplied, M = T(-5, -2, -6) · S(10, 4, 0.5); post-multiplied it
            // would be S · T, sending the corner (0,0,0) to (-50, -8, -3).
            CHECK(r.era.era == rb::Era::Modern);
            CHECK_THAT(r.era.line, !Contains("gr.cone"));
            CHECK(rbtest::near(rbtest::boundsOf(renders[0], "wall").lo, Vec3(-5, -2, -6)));
        }
    }
}

SCENARIO("every scene of the project is rendered in the era it was written for",
         "[ch02][era][needs-ch18]") {
    namespace fs = std::filesystem;
    const fs::path scenes = fs::path(rbtest::sourceDir()) / "scenes";
    // The era each scene expects: its "-- rt-era:" line, else current. Seed 001's garage is
    // written in seed 001's dialect (gr.cyllinder), so it is pre-2015.
    const auto expected = [&](const fs::path& file, const std::string& text) {
        if (text.find("-- rt-era: legacy") != std::string::npos) return rb::Era::Legacy;
        if (text.find("-- rt-era: modern") != std::string::npos) return rb::Era::Modern;
        return file.filename() == "001-garage.lua" ? rb::Era::Legacy : rb::Era::Modern;
    };
    int loaded = 0;
    for (const char* folder : {"", "a4", "legacy", "seeds"})
        for (const auto& entry : fs::directory_iterator(scenes / folder)) {
            if (entry.path().extension() != ".lua") continue;
            std::ifstream in(entry.path());
            const std::string text((std::istreambuf_iterator<char>(in)),
                                   std::istreambuf_iterator<char>());
            // Helpers for require() are not scenes.
            if (text.find("-- rt-module:") != std::string::npos) continue;
            WHEN("rt loads " << entry.path().lexically_relative(scenes).string()) {
                rb::SceneLoadReport report;
                rb::loadScene(entry.path().string(), rbtest::chapters(18), rb::SceneLoadOptions{},
                              &report);
                INFO(report.era.line);
                CHECK(report.era.era == expected(entry.path(), text));
                // A current chapter scene renders without a word about its era.
                if (entry.path().filename().string().rfind("chapter", 0) == 0)
                    CHECK_FALSE(report.era.show);
            }
            ++loaded;
        }
    THEN("every folder held scenes") {
        CHECK(loaded > 30);
    }
}

/// \file
/// Chapter 2 tests of course compatibility: the framework's two eras, its tolerance of extra
/// arguments, `--lenient` and `--dialect`.
///
/// Chapter 2 claims that a TA can render a class's scenes as the course framework would,
/// without flags: a scene's own calls tell which framework it was written for (the pre-2015
/// one post-multiplied transforms), and rt runs it in that era and says why in one line; extra
/// trailing arguments, which the framework ignored, are warnings; under `--lenient` unknown
/// calls and methods are replaced by visible stand-ins and listed; and a dialect file, run
/// before the scene, maps a student's own calls onto raybook's. Each test writes a small
/// scene, loads it the way `rt` does, and checks the exact outcome.
#include <catch2/catch.hpp>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/world.h"
#include "scene/lua_scene.h"
#include "scene/scene_era.h"
#include "test_helpers.h"

using Catch::Contains;
using Catch::EndsWith;
using rb::Vec3;

namespace {

/// A scene and what loading it reported.
struct Loaded {
    std::vector<rb::LoadedRender> renders;
    rb::SceneLoadReport report;
};

/// Load `lua` (written to scene.lua in a fresh folder, with `files` beside it) as rt does.
Loaded load(const std::string& lua, rb::SceneLoadOptions options = {}, int chapters = 7,
            const std::vector<std::pair<std::string, std::string>>& files = {}) {
    rbtest::TempDir dir;
    for (const auto& [name, text] : files) {
        const std::string path = dir.write(name, text);
        if (name.size() > 4 && name.substr(name.size() - 4) == ".lua" && name != "scene.lua")
            options.dialects.push_back(path);
    }
    Loaded result;
    result.renders = rb::loadScene(dir.write("scene.lua", lua), rbtest::chapters(chapters), options,
                                   &result.report);
    return result;
}

/// A wall placed the pre-2015 way: translate, then scale (post-multiplied: scaled first).
const std::string kWall =
    "local wall = gr.cube('wall')\n"
    "wall:translate(-5, -2, -6)\n"
    "wall:scale(10, 4, 0.5)\n"
    "root:add_child(wall)\n";

}  // namespace

SCENARIO("the era is decided from the scene's signs and said in one line", "[ch02][era]") {
    const std::vector<rb::EraSign> legacy = {{rb::Era::Legacy, "unpack", "s.lua:3"}};
    const std::vector<rb::EraSign> modern = {
        {rb::Era::Modern, "gr.mesh with an .obj file", "s.lua:7"}};
    std::vector<rb::EraSign> both = legacy;
    both.push_back(modern[0]);
    GIVEN("only pre-2015 signs") {
        const rb::EraDecision d = rb::decideEra(rb::EraChoice::Detect, legacy, "");
        THEN("the era is pre-2015, and the line names the sign and its place") {
            CHECK(d.era == rb::Era::Legacy);
            CHECK_THAT(d.line, Contains("pre-2015") && Contains("unpack (s.lua:3)"));
        }
    }
    GIVEN("only current signs") {
        const rb::EraDecision d = rb::decideEra(rb::EraChoice::Detect, modern, "s.lua:2");
        THEN("the era is current") {
            CHECK(d.era == rb::Era::Modern);
            CHECK_THAT(d.line, Contains("current") && Contains(".obj file (s.lua:7)"));
        }
    }
    GIVEN("signs of both eras") {
        const rb::EraDecision d = rb::decideEra(rb::EraChoice::Detect, both, "");
        THEN("the era is current by default, and the line says the signs conflict") {
            CHECK(d.era == rb::Era::Modern);
            CHECK_THAT(d.line, Contains("conflict") && Contains("unpack") && Contains(".obj"));
        }
    }
    GIVEN("no signs") {
        THEN("the era is current, said only when the order of the transforms matters") {
            CHECK_FALSE(rb::decideEra(rb::EraChoice::Detect, {}, "").show);
            const rb::EraDecision d = rb::decideEra(rb::EraChoice::Detect, {}, "s.lua:9");
            CHECK(d.era == rb::Era::Modern);
            CHECK_THAT(d.line, Contains("no sign") && Contains("s.lua:9") && Contains("--legacy"));
        }
    }
    GIVEN("--legacy with current signs") {
        const rb::EraDecision d = rb::decideEra(rb::EraChoice::Legacy, modern, "");
        THEN("the flag wins and the line says so") {
            CHECK(d.era == rb::Era::Legacy);
            CHECK_THAT(d.line, Contains("forced by --legacy"));
        }
    }
}

SCENARIO("a seed-001 scene's translate-then-scale walls stand where its author put them",
         "[ch02][era][ex2.2][ex2.3][needs-ch04]") {
    GIVEN("seed 001's dialect (gr.phongMat) and a wall written translate, then scale") {
        const std::string lua =
            "root = gr.node('root')\n"
            "local white = gr.phongMat({0.8, 0.8, 0.8}, {0, 0, 0}, 1, 0, 0)\n" +
            kWall + "wall:set_material(white)\n" + rbtest::renderLine();
        WHEN("rt loads it without flags") {
            const Loaded l = load(lua);
            THEN("the scene is recognised as pre-2015 from gr.phongMat") {
                CHECK(l.report.era.era == rb::Era::Legacy);
                CHECK_THAT(l.report.era.line,
                           Contains("gr.phongMat (") && Contains("scene.lua:2)"));
            }
            THEN("the unit cube is scaled to 10 x 4 x 0.5, then moved to x -5..5, z -6..-5.5") {
                // Source: post-multiplication gives M = T(-5, -2, -6) · S(10, 4, 0.5), so the
                // cube's corner (1,1,1) lands at (-5 + 10, -2 + 4, -6 + 0.5).
                const rb::AABB b = rbtest::boundsOf(l.renders[0], "wall");
                CHECK(rbtest::near(b.lo, Vec3(-5, -2, -6)));
                CHECK(rbtest::near(b.hi, Vec3(5, 2, -5.5)));
            }
            THEN("the wall fills the middle of the rendered picture") {
                // The camera at (0, 0, 10) looks down -z through the wall's middle (0, 0, -5.5),
                // which faces the light beside the eye: the centre pixel is lit.
                auto renders = l.renders;
                const auto world = rb::buildWorld(std::move(renders[0]), rbtest::chapters(7));
                CHECK(rbtest::renderSmall(*world, 32, 24).get(16, 12).r > 0.1);
            }
        }
        WHEN("the current order is forced with --modern") {
            rb::SceneLoadOptions modern;
            modern.era = rb::EraChoice::Modern;
            const Loaded l = load(lua, modern);
            THEN("the wall is scaled after it moved: far to the left, out of the picture") {
                // Source: M = S(10, 4, 0.5) · T(-5, -2, -6) sends the corner (0,0,0) to
                // (-50, -8, -3); nothing is left in the middle of the picture.
                const rb::AABB b = rbtest::boundsOf(l.renders[0], "wall");
                CHECK(rbtest::near(b.lo, Vec3(-50, -8, -3)));
                auto renders = l.renders;
                const auto world = rb::buildWorld(std::move(renders[0]), rbtest::chapters(7));
                CHECK(rbtest::renderSmall(*world, 32, 24).get(16, 12).r == 0.0);
            }
        }
    }
}

SCENARIO("Lua 5.1's unpack and string.gfind mark a scene as pre-2015", "[ch02][era][ex2.2]") {
    GIVEN("a scene that places its wall with unpack, and no other sign") {
        const std::string lua = "root = gr.node('root')\nlocal p = {-5, 0, -6}\n" +
                                std::string(
                                    "local wall = gr.cube('wall')\n"
                                    "wall:translate(unpack(p))\n"
                                    "wall:scale(10, 4, 0.5)\n"
                                    "root:add_child(wall)\n") +
                                rbtest::renderLine();
        const Loaded l = load(lua);
        THEN("it runs as pre-2015, and unpack still returns every value") {
            CHECK(l.report.era.era == rb::Era::Legacy);
            CHECK_THAT(l.report.era.line, Contains("unpack (") && Contains("scene.lua:4)"));
            CHECK(rbtest::near(rbtest::boundsOf(l.renders[0], "wall").lo, Vec3(-5, 0, -6)));
        }
    }
    GIVEN("a scene that iterates words with string.gfind") {
        const Loaded l = load(
            "local n = 0\nfor w in string.gfind('a b c', '%a') do n = n + 1 end\n"
            "assert(n == 3)\nroot = gr.node('root')\n" +
            rbtest::renderLine());
        THEN("it is pre-2015 too") {
            CHECK(l.report.era.era == rb::Era::Legacy);
        }
    }
}

SCENARIO("the loader notes where the order of transforms first matters", "[ch02][era][ex2.2]") {
    GIVEN("one node moved twice, another rotated about one axis twice: calls that commute") {
        const Loaded l = load(
            "root = gr.node('root')\nlocal s = gr.sphere('s')\n"
            "s:translate(1, 0, 0)\ns:translate(0, 2, 0)\nroot:add_child(s)\n"
            "local t = gr.sphere('t')\n"
            "t:rotate('y', 10)\nt:rotate('y', 20)\nroot:add_child(t)\n" +
            rbtest::renderLine());
        THEN("the era needs no word") {
            CHECK_FALSE(l.report.era.show);
        }
    }
    GIVEN("a node scaled, then moved") {
        const Loaded l = load(
            "root = gr.node('root')\nlocal s = gr.sphere('s')\n"
            "s:scale(2, 2, 2)\ns:translate(1, 0, 0)\nroot:add_child(s)\n" +
            rbtest::renderLine());
        THEN("the line says the order matters at the translate") {
            CHECK_THAT(l.report.era.line, Contains("scene.lua:4"));
        }
    }
}

SCENARIO("extra trailing arguments are what the course framework ignores: a warning",
         "[ch02][tolerance][ex2.2][needs-ch04]") {
    GIVEN("gr.sphere with two extra arguments, twice") {
        const Loaded l = load(
            "root = gr.node('root')\nroot:add_child(gr.sphere('s', 1, 2))\n"
            "root:add_child(gr.sphere('t', 1, 2))\n" +
            rbtest::renderLine());
        THEN("both spheres exist, and one warning names the call, its line and the count") {
            CHECK(l.renders[0].instances.size() == 2);
            REQUIRE(l.report.warnings.size() == 1);
            CHECK_THAT(l.report.warnings[0], Contains("scene.lua:2: gr.sphere: ignored 2 extra") &&
                                                 Contains("(2 times)"));
        }
    }
    GIVEN("gr.sphere whose name, which it reads, is a number") {
        THEN("that is still an error") {
            CHECK_THAT(rbtest::loadError("gr.sphere(3)\n"), Contains("must be a string"));
        }
    }
    GIVEN("gr.material(kd, ks, shininess, 0.4) in a chapter-4 build") {
        const Loaded l = load(
            "root = gr.node('root')\nlocal s = gr.sphere('s')\n"
            "s:set_material(gr.material({1,0,0}, {1,1,1}, 20, 0.4))\n"
            "root:add_child(s)\n" +
                rbtest::renderLine(),
            {}, 4);
        THEN("the fourth argument is the reflectivity, and a warning says so") {
            REQUIRE(l.renders[0].instances[0].material != nullptr);
            CHECK(l.renders[0].instances[0].material->params.at("reflect") == 0.4);
            REQUIRE(l.report.warnings.size() == 1);
            CHECK_THAT(l.report.warnings[0], Contains("reflectivity"));
        }
    }
}

SCENARIO("--lenient renders what raybook understands and lists what it ignored",
         "[ch02][lenient][ex2.2]") {
    const std::string lua =
        "root = gr.node('root')\n"
        "local m = gr.shiny_material({1,0,0}, 3)\n"
        "local p = gr.torus('donut', 2, 0.5)\n"
        "p:set_material(m)\n"
        "p:wobble(3)\n"
        "p:wobble(4)\n"
        "root:add_child(p)\n"
        "local s = gr.sphere('s')\ns:set_material(m)\nroot:add_child(s)\n" +
        rbtest::renderLine();
    GIVEN("a scene with an unknown material call, primitive and method") {
        WHEN("it is loaded without --lenient") {
            THEN("the first unknown call is an error naming it") {
                CHECK_THAT(rbtest::loadError(lua, rbtest::chapters(7)),
                           Contains("gr.shiny_material is not a raybook call"));
            }
        }
        WHEN("it is loaded with --lenient") {
            rb::SceneLoadOptions options;
            options.lenient = true;
            const Loaded l = load(lua, options);
            THEN("the torus is a sphere of its outer radius, and both wear the material's red") {
                REQUIRE(l.renders[0].instances.size() == 2);
                for (const rb::Instance& i : l.renders[0].instances) {
                    REQUIRE(i.material != nullptr);
                    CHECK(rbtest::near(i.material->kd, Vec3(1, 0, 0)));
                }
                CHECK(rbtest::near(rbtest::boundsOf(l.renders[0], "donut").hi, Vec3(2.5)));
            }
            THEN("a warning names each stand-in") {
                REQUIRE(l.report.warnings.size() == 2);
                CHECK_THAT(l.report.warnings[0],
                           Contains("scene.lua:2: gr.shiny_material: --lenient stands in a "
                                    "diffuse material whose kd is argument 1 {1, 0, 0}"));
                CHECK_THAT(l.report.warnings[1],
                           Contains("scene.lua:3: gr.torus: --lenient stands in a sphere of its "
                                    "outer radius 2.5"));
            }
            THEN("the ignored list names each unknown once, with its count and first line") {
                REQUIRE(l.report.ignored.size() == 3);
                CHECK_THAT(l.report.ignored[0],
                           Contains("gr.shiny_material") && Contains("scene.lua:2"));
                CHECK_THAT(l.report.ignored[1], Contains("gr.torus") && Contains("scene.lua:3"));
                CHECK_THAT(l.report.ignored[2], Contains("node:wobble") &&
                                                    Contains("scene.lua:5") &&
                                                    Contains("(2 times)"));
            }
        }
    }
}

SCENARIO("--lenient reads a known call without the arguments it cannot read",
         "[ch02][lenient][ex2.2]") {
    rb::SceneLoadOptions lenient;
    lenient.lenient = true;
    GIVEN("gr.render with another course's trailing arguments: a quality name and a table") {
        const std::string lua =
            "root = gr.node('root')\nroot:add_child(gr.sphere('s'))\n"
            "gr.render(root, 'out.png', 8, 8, {0, 0, 10}, {0, 0, -1}, {0, 1, 0}, 50,"
            " {0.1, 0.1, 0.1}, {gr.light({0, 0, 10}, {1, 1, 1}, {1, 0, 0})}, 'high', {4})\n";
        WHEN("it is loaded without --lenient") {
            THEN("argument 11 is an error, as before") {
                CHECK_THAT(rbtest::loadError(lua, rbtest::chapters(7)),
                           Contains("scene.lua:3: gr.render: argument 11 (aa) must be a number, "
                                    "got string"));
            }
        }
        WHEN("it is loaded with --lenient") {
            const Loaded l = load(lua, lenient);
            THEN(
                "it renders from its first ten arguments, and its extras are no sign of seed 001") {
                REQUIRE(l.renders.size() == 1);
                CHECK(l.renders[0].instances.size() == 1);
                CHECK(l.renders[0].job.options.count("aa") == 0);
                CHECK(l.report.era.era == rb::Era::Modern);
                CHECK_THAT(l.report.era.line, !Contains("seed 001"));
            }
            THEN("one line lists the call: what it could not read, what it did, and where") {
                CHECK(l.report.ignored.empty());
                REQUIRE(l.report.unreadable.size() == 1);
                CHECK_THAT(l.report.unreadable[0],
                           Contains("gr.render (arguments raybook cannot read: argument 11 (aa) "
                                    "must be a number, got string; read with its first 10 "
                                    "arguments), first at ") &&
                               Contains("scene.lua:3"));
            }
        }
    }
}

SCENARIO("--lenient puts a stand-in where a known call cannot be read at all",
         "[ch02][lenient][ex2.2]") {
    rb::SceneLoadOptions lenient;
    lenient.lenient = true;
    GIVEN("two material calls with a table for the shininess, on lines 1 and 2") {
        const std::string lua =
            "local a = gr.material({0.1, 0.8, 0.1}, {0.2, 0.2, 0.2}, {25})\n"
            "local b = gr.material({0.1, 0.1, 0.8}, {0.2, 0.2, 0.2}, {40})\n"
            "root = gr.node('root')\n"
            "local s = gr.sphere('s')\ns:set_material(a)\nroot:add_child(s)\n"
            "local t = gr.sphere('t')\nt:set_material(b)\nroot:add_child(t)\n" +
            rbtest::renderLine();
        const Loaded l = load(lua, lenient);
        THEN("each table is read as its number: the spheres keep their colours and exponents") {
            REQUIRE(l.renders.at(0).instances.size() == 2);
            const rb::Material* a = l.renders[0].instances[0].material;
            const rb::Material* b = l.renders[0].instances[1].material;
            REQUIRE((a && b));
            CHECK(rbtest::near(a->kd, Vec3(0.1, 0.8, 0.1)));
            CHECK(a->shininess == 25.0);
            CHECK(rbtest::near(b->kd, Vec3(0.1, 0.1, 0.8)));
            CHECK(b->shininess == 40.0);
        }
        THEN("one warning names the guess, with the first line and the count; nothing is listed") {
            CHECK(l.report.unreadable.empty());
            REQUIRE(l.report.warnings.size() == 1);
            CHECK_THAT(l.report.warnings[0],
                       Contains("scene.lua:1: gr.material: argument 3 (shininess): --lenient "
                                "read the table {25} as the number 25 (a table where a number "
                                "belongs) (2 times)"));
        }
    }
    GIVEN("a material whose second argument cannot be read, followed by a fourth") {
        // Read again without arguments 2 to 4, the call is one argument short: a stand-in.
        const Loaded l =
            load(rbtest::oneMaterialScene("gr.material({1, 0, 0}, {1, 1}, 25, 0.5)"), lenient, 4);
        THEN("the call is listed once, by what its first reading found; kd is its first colour") {
            CHECK(rbtest::near(l.renders.at(0).instances.at(0).material->kd, Vec3(1, 0, 0)));
            REQUIRE(l.report.unreadable.size() == 1);
            CHECK_THAT(l.report.unreadable[0],
                       Contains("argument 2 (ks) must be a table of 3 numbers, got a table of 2; "
                                "a stand-in took its place)") &&
                           !Contains("times"));
        }
    }
    GIVEN("node:rotate(30), a one-argument form of node:rotate(axis, degrees)") {
        const std::string lua =
            "root = gr.node('root')\nlocal s = gr.sphere('s')\ns:translate(3, 0, 0)\n"
            "s:rotate(30)\nroot:add_child(s)\n" +
            rbtest::renderLine();
        THEN("without --lenient it is an error, as before") {
            CHECK_THAT(rbtest::loadError(lua, rbtest::chapters(7)),
                       Contains("scene.lua:4: node:rotate expects 2 arguments (axis, degrees), "
                                "got 1"));
        }
        THEN("with --lenient the call is ignored: the sphere stays where it was put") {
            const Loaded l = load(lua, lenient);
            CHECK(rbtest::near(rbtest::boundsOf(l.renders.at(0), "s").lo, Vec3(2, -1, -1)));
            REQUIRE(l.report.unreadable.size() == 1);
            CHECK_THAT(l.report.unreadable[0],
                       Contains("node:rotate (arguments raybook cannot read: expects 2 arguments "
                                "(axis, degrees), got 1; the call was ignored), first at ") &&
                           Contains("scene.lua:4"));
        }
    }
    GIVEN("gr.light with a position alone") {
        const Loaded l = load(
            "root = gr.node('root')\nroot:add_child(gr.sphere('s'))\n"
            "local spot = gr.light({0, 5, 5})\n"
            "gr.render(root, 'out.png', 8, 8, {0, 0, 10}, {0, 0, -1}, {0, 1, 0}, 50,"
            " {0.1, 0.1, 0.1}, {gr.light({0, 0, 10}, {1, 1, 1}, {1, 0, 0}), spot})\n",
            lenient);
        THEN("the light is a white point light at its position, beside the scene's own") {
            const auto& lights = l.renders.at(0).job.lights;
            REQUIRE(lights.size() == 2);
            CHECK(rbtest::near(lights[0].colour, Vec3(1.0)));
            CHECK(rbtest::near(lights[1].position, Vec3(0, 5, 5)));
            CHECK(rbtest::near(lights[1].colour, Vec3(1.0)));
            REQUIRE(l.report.unreadable.size() == 1);
            CHECK_THAT(l.report.unreadable[0], Contains("gr.light (") && Contains("scene.lua:3"));
        }
    }
}

SCENARIO("--lenient reads a light whose extra arguments mean something else as a point light",
         "[ch02][lenient][ex2.2][needs-ch06]") {
    rb::SceneLoadOptions lenient;
    lenient.lenient = true;
    // Another course's spot light: position, colour, falloff, 'spot', direction, angle.
    const std::string lua =
        "root = gr.node('root')\nroot:add_child(gr.sphere('s'))\n"
        "local spot = gr.light({0, 5, 5}, {0.9, 0.8, 0.7}, {1, 0, 0}, 'spot', {0, -1, 0}, 30)\n"
        "gr.render(root, 'out.png', 8, 8, {0, 0, 10}, {0, 0, -1}, {0, 1, 0}, 50,"
        " {0.1, 0.1, 0.1}, {spot})\n";
    for (const int chapter : {1, 6}) {
        GIVEN("a chapter-" + std::to_string(chapter) + " build (six arguments are seed 001's " +
              (chapter < 6 ? "area light, which it lacks)" : "rectangular light)")) {
            THEN("without --lenient it is an error, as before") {
                CHECK_THAT(rbtest::loadError(lua, rbtest::chapters(chapter)),
                           Contains("scene.lua:3: gr.light: "));
            }
            const Loaded l = load(lua, lenient, chapter);
            THEN("with --lenient it is the point light of its first three arguments") {
                const auto& lights = l.renders.at(0).job.lights;
                REQUIRE(lights.size() == 1);
                CHECK(rbtest::near(lights[0].position, Vec3(0, 5, 5)));
                CHECK(rbtest::near(lights[0].colour, Vec3(0.9, 0.8, 0.7)));
                CHECK(lights[0].shape == nullptr);
                CHECK(l.report.era.era == rb::Era::Modern);
                REQUIRE(l.report.unreadable.size() == 1);
                CHECK_THAT(l.report.unreadable[0],
                           Contains("gr.light (arguments raybook cannot read: ") &&
                               Contains("read with its first 3 arguments), first at ") &&
                               Contains("scene.lua:3"));
            }
        }
    }
}

SCENARIO("--lenient ignores a texture call it cannot read", "[ch02][lenient][needs-ch10]") {
    rb::SceneLoadOptions lenient;
    lenient.lenient = true;
    GIVEN("mat:set_texture('diffuse', 'wood.png'), a slot raybook does not have") {
        const std::string lua = rbtest::oneMaterialScene("gr.material({1, 0, 0}, {0, 0, 0}, 1)",
                                                         "m:set_texture('diffuse', 'wood.png')\n");
        THEN("without --lenient it is an error, as before") {
            CHECK_THAT(rbtest::loadError(lua, rbtest::chapters(10)),
                       Contains("scene.lua:6: material:set_texture: slot 'diffuse' must be 'kd' "
                                "or 'ks'"));
        }
        THEN("with --lenient the material keeps its colour and has no texture") {
            const Loaded l = load(lua, lenient, 10);
            const rb::Material* m = l.renders.at(0).instances.at(0).material;
            CHECK(rbtest::near(m->kd, Vec3(1, 0, 0)));
            CHECK(m->textures.empty());
            REQUIRE(l.report.unreadable.size() == 1);
            CHECK_THAT(l.report.unreadable[0],
                       Contains("material:set_texture (arguments raybook cannot read: slot "
                                "'diffuse' must be 'kd' or 'ks'; the call was ignored)"));
        }
    }
}

SCENARIO("a dialect file maps a student's own calls onto raybook's before the scene runs",
         "[ch02][dialect][ex2.2][needs-ch04]") {
    GIVEN(
        "a dialect defining gr.mirror(kd, r) and a node method :lift(h), and a scene using both") {
        const std::string dialect =
            "function gr.mirror(kd, r)\n"
            "  return gr.material{kd = kd, ks = {0.5, 0.5, 0.5}, shininess = 50, reflect = r}\n"
            "end\n"
            "function gr.methods.node.lift(self, h) self:translate(0, h, 0) end\n";
        const std::string lua =
            "root = gr.node('root')\nlocal s = gr.sphere('s')\n"
            "s:set_material(gr.mirror({0.2, 0.2, 0.2}, 0.7))\n"
            "s:lift(3)\nroot:add_child(s)\n" +
            rbtest::renderLine();
        const Loaded l = load(lua, {}, 7, {{"student.lua", dialect}});
        THEN("the sphere is a mirror of reflectivity 0.7, lifted by 3") {
            const rb::Instance& i = l.renders[0].instances.at(0);
            CHECK(i.material->params.at("reflect") == 0.7);
            CHECK(rbtest::near(i.worldBounds.lo, Vec3(-1, 2, -1)));
        }
    }
    GIVEN("a dialect file with an error on its line 2") {
        THEN("the message names the dialect file and line") {
            CHECK_THROWS_WITH(
                load(rbtest::renderLine(), {}, 7, {{"bad.lua", "local x = 1\nx()\n"}}),
                Contains("bad.lua:2:"));
        }
    }
}

SCENARIO("--lenient stands in other courses' lights as point lights at their position",
         "[ch02][lenient][ex2.2]") {
    rb::SceneLoadOptions lenient;
    lenient.lenient = true;
    GIVEN("a scene lit only by gr.spot_light and gr.point_light, which raybook does not know") {
        const std::string lua =
            "root = gr.node('root')\nroot:add_child(gr.sphere('s'))\n"
            "local a = gr.spot_light({0, 5, 5}, {0.9, 0.8, 0.7}, {1, 0, 0}, {0, -1, 0}, 30)\n"
            "local b = gr.point_light{position = {1, 2, 3}, colour = {0.2, 0.3, 0.4}}\n"
            "gr.render(root, 'out.png', 8, 8, {0, 0, 10}, {0, 0, -1}, {0, 1, 0}, 50,"
            " {0.1, 0.1, 0.1}, {a, b})\n";
        const Loaded l = load(lua, lenient);
        THEN("each is a point light at its first triple, of the colour of the next") {
            const auto& lights = l.renders.at(0).job.lights;
            REQUIRE(lights.size() == 2);
            CHECK(rbtest::near(lights[0].position, Vec3(0, 5, 5)));
            CHECK(rbtest::near(lights[0].colour, Vec3(0.9, 0.8, 0.7)));
            CHECK(rbtest::near(lights[0].falloff, Vec3(1, 0, 0)));
            CHECK(rbtest::near(lights[1].position, Vec3(1, 2, 3)));
            CHECK(rbtest::near(lights[1].colour, Vec3(0.2, 0.3, 0.4)));
        }
        THEN("one warning line says that the render is lit by stand-ins alone") {
            CHECK_THAT(l.report.warnings.back(),
                       Contains("scene.lua:5: gr.render: every light is a --lenient stand-in "
                                "(point lights in place of gr.spot_light, gr.point_light)"));
        }
    }
    GIVEN("the same render with one of raybook's own lights beside a stand-in") {
        const Loaded l = load(
            "root = gr.node('root')\nroot:add_child(gr.sphere('s'))\n"
            "local a = gr.spot_light({0, 5, 5}, {0.9, 0.8, 0.7})\n"
            "gr.render(root, 'out.png', 8, 8, {0, 0, 10}, {0, 0, -1}, {0, 1, 0}, 50,"
            " {0.1, 0.1, 0.1}, {a, gr.light({0, 0, 10}, {1, 1, 1}, {1, 0, 0})})\n",
            lenient);
        THEN("no line says the lighting is a guess") {
            for (const std::string& w : l.report.warnings) CHECK_THAT(w, !Contains("every light"));
        }
    }
}

SCENARIO("--lenient builds other courses' primitives from raybook's own shapes",
         "[ch02][lenient][ex2.2][needs-ch15]") {
    rb::SceneLoadOptions lenient;
    lenient.lenient = true;
    GIVEN("a plane, a triangle, a quad, a disc, a torus and a tube") {
        const std::string lua =
            "root = gr.node('root')\n"
            "root:add_child(gr.plane('plane'))\n"
            "root:add_child(gr.triangle('tri', {0, 0, 0}, {1, 0, 0}, {0, 2, 0}))\n"
            "root:add_child(gr.quad('quad', {{0, 0, 1}, {3, 0, 1}, {3, 1, 1}, {0, 1, 1}}))\n"
            "root:add_child(gr.disk('disc'))\n"
            "root:add_child(gr.torus('torus', 2, 0.5))\n"
            "root:add_child(gr.tube('tube'))\n" +
            rbtest::renderLine();
        WHEN("it is loaded in a chapter-15 build") {
            const Loaded l = load(lua, lenient, 15);
            const rb::LoadedRender& r = l.renders.at(0);
            THEN("each is the nearest shape raybook has, where its author put it") {
                REQUIRE(r.instances.size() == 6);
                CHECK(rbtest::boundsOf(r, "plane").lo.x <= -1000.0);
                CHECK(std::abs(rbtest::boundsOf(r, "plane").hi.y) < 1e-9);
                CHECK(rbtest::near(rbtest::boundsOf(r, "tri").hi, Vec3(1, 2, 0)));
                CHECK(rbtest::near(rbtest::boundsOf(r, "quad").lo, Vec3(0, 0, 1)));
                CHECK(rbtest::near(rbtest::boundsOf(r, "quad").hi, Vec3(3, 1, 1)));
                CHECK(rbtest::boundsOf(r, "disc").hi.y < 0.01);
                CHECK(rbtest::near(rbtest::boundsOf(r, "torus").hi, Vec3(2.5)));
                CHECK(rbtest::near(rbtest::boundsOf(r, "tube").lo, Vec3(-1)));
            }
            THEN("a warning names each stand-in, and the table mesh is no sign of an era") {
                REQUIRE(l.report.warnings.size() == 6);
                CHECK_THAT(l.report.warnings[1],
                           Contains("scene.lua:3: gr.triangle: --lenient stands in a mesh of "
                                    "its 3 vertices"));
                CHECK_THAT(l.report.warnings[3], Contains("gr.disk: --lenient stands in a "
                                                          "cylinder of radius 1"));
                CHECK(l.report.era.era == rb::Era::Modern);
                CHECK_THAT(l.report.era.line, !Contains("gr.mesh"));
            }
        }
        WHEN("it is loaded in a chapter-7 build, which has no cylinder") {
            const Loaded l = load(lua, lenient, 7);
            THEN("the disc is a flattened sphere and the tube a sphere") {
                CHECK(rbtest::boundsOf(l.renders.at(0), "disc").hi.y < 0.01);
                CHECK_THAT(l.report.warnings[3], Contains("a sphere of radius 1 flattened"));
                CHECK_THAT(l.report.warnings[5], Contains("a unit sphere (this build has no "
                                                          "cylinder)"));
            }
        }
    }
}

SCENARIO("a long gr.render call alone is no sign of the pre-2015 era", "[ch02][era][ex2.2]") {
    // A wall scaled, then moved: the current way (post-multiplied, it would be moved first).
    const std::string wall =
        "root = gr.node('root')\nlocal wall = gr.cube('wall')\nwall:scale(10, 4, 0.5)\n"
        "wall:translate(-5, -2, -6)\nroot:add_child(wall)\n";
    const std::string ten =
        "gr.render(root, 'out.png', 8, 8, {0, 0, 10}, {0, 0, -1}, {0, 1, 0}, 50, {0.1, 0.1, 0.1},"
        " {gr.light({0, 0, 10}, {1, 1, 1}, {1, 0, 0})}";
    GIVEN("a render with two more numbers (aa = 1, ss = 2), which seed 001 also wrote") {
        const Loaded l = load(wall + ten + ", 1, 2)\n", {}, 8);
        THEN("the transforms' idiom decides: current, and the wall stands where it was put") {
            CHECK(l.report.era.era == rb::Era::Modern);
            CHECK_THAT(l.report.era.line, !Contains("gr.render"));
            CHECK(rbtest::near(rbtest::boundsOf(l.renders.at(0), "wall").lo, Vec3(-5, -2, -6)));
        }
    }
    GIVEN("seed 001's whole form, ending in its {aperture, focalLength, dof} triple") {
        const Loaded l = load(wall + ten + ", 0, 0, 0, {0, 10, 0})\n", {}, 13);
        THEN("it is still a sign of seed 001's era") {
            CHECK(l.report.era.era == rb::Era::Legacy);
            CHECK_THAT(l.report.era.line, Contains("seed 001's gr.render with 14 arguments"));
        }
    }
    GIVEN("a render with sixteen values under --lenient: samples, depth, aperture, ...") {
        rb::SceneLoadOptions lenient;
        lenient.lenient = true;
        const Loaded l = load(wall + ten + ", 16, 5, 0.1, 2.8, 1, 64)\n", lenient, 13);
        THEN("it renders from its first ten, current, its extras listed and never an error") {
            REQUIRE(l.renders.size() == 1);
            CHECK(l.renders[0].job.options.count("aa") == 0);
            CHECK(l.report.era.era == rb::Era::Modern);
            REQUIRE(l.report.unreadable.size() == 1);
            CHECK_THAT(l.report.unreadable[0], Contains("read with its first 10 arguments"));
        }
        THEN("the render names the scene's line, not the C function that read it again") {
            CHECK_THAT(l.renders[0].job.where, EndsWith("scene.lua:6") && !Contains("[C]"));
        }
    }
}

SCENARIO("an error names the scene's line once, wherever the script raised it",
         "[ch02][errors][ex2.2]") {
    GIVEN("error() with a table") {
        THEN("the message says so, at the line") {
            CHECK_THAT(rbtest::loadError("local x = 1\nerror({code = 1})\n"),
                       Contains("scene.lua:2: the script raised an error whose value is a "
                                "table, not a message"));
        }
    }
    GIVEN("a call made through pcall, its message raised again with error(message, 0)") {
        THEN("the message names the line of the pcall, not [C]") {
            const std::string e =
                rbtest::loadError("local ok, e = pcall(gr.sphere, 5)\nerror(e, 0)\n");
            CHECK_THAT(e, Contains("scene.lua:1: gr.sphere: argument 1 (name) must be a string"));
            CHECK_THAT(e, !Contains("[C]"));
        }
    }
    GIVEN("the same message raised again with error(message) on the line that made it") {
        THEN("the line is named once") {
            const std::string e = rbtest::loadError(
                "local ok, e = pcall(gr.sphere, 5) if not ok then error(e) end\n");
            CHECK_THAT(e, Contains("scene.lua:1: gr.sphere: argument 1"));
            CHECK_THAT(e, !Contains("scene.lua:1: scene.lua:1:"));
        }
    }
    GIVEN("a bad call inside table.sort's comparison") {
        THEN("the message names the comparison's line") {
            CHECK_THAT(rbtest::loadError("table.sort({3, 1, 2}, function(a, b)\n"
                                         "  return gr.nh_sphere('s', {0, 0}, 1)\nend)\n"),
                       Contains("scene.lua:2: gr.nh_sphere: argument 2 (centre)"));
        }
    }
}

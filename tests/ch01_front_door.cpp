/// \file
/// Chapter 1 tests of the front door: what a student meets before any picture.
///
/// The core claims that a scene's files are found where a student keeps them (the working
/// directory, then the scene's folder, then each `--assets` folder, and a missing file's error
/// names every place it looked); that `--features=-glossy` means "everything built, minus
/// glossy"; that messages tell a student to build a chapter only when it is written; that rt
/// writes PNG only and refuses to put PNG data under another format's name; that `--help`
/// shows every option's default; and that a render that can only disappoint says why: no
/// shapes, nothing in view, or a scene argument that no chapter in use reads. Each test builds
/// the situation by hand and checks the exact outcome.
#include <unistd.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <string>
#include <vector>

#include "app/options.h"
#include "app/render_warnings.h"
#include "app/version.h"
#include "core/camera.h"
#include "core/error.h"
#include "core/image.h"
#include "core/sphere.h"
#include "scene/lua_scene.h"
#include "test_helpers.h"

using Catch::Contains;
using rb::Vec3;

namespace {

namespace fs = std::filesystem;

/// Runs the enclosing scope in another working directory and goes back at its end.
class WorkingDirectory {
  public:
    explicit WorkingDirectory(const fs::path& dir) : previous_(fs::current_path()) {
        fs::current_path(dir);
    }
    ~WorkingDirectory() { fs::current_path(previous_); }
    WorkingDirectory(const WorkingDirectory&) = delete;
    WorkingDirectory& operator=(const WorkingDirectory&) = delete;

  private:
    fs::path previous_;
};

/// The message of the InputError that `f` throws, or "" if it throws none.
template <class F>
std::string errorOf(F f) {
    try {
        f();
    } catch (const rb::InputError& e) {
        return e.what();
    }
    return "";
}

/// Parse a command line given as words (argv[0] is added).
rb::CommandLine parse(std::vector<const char*> words) {
    words.insert(words.begin(), "rt");
    return rb::parseCommandLine(static_cast<int>(words.size()), words.data(),
                                rbtest::chapters(7).built());
}

/// A render request whose only content is `instances`, seen by the A4 default camera at
/// the origin looking down −z, and its extra seed-001 options.
rb::RenderJob jobAt(const std::string& output = "out.png") {
    rb::RenderJob job;
    job.output = output;
    job.width = 40;
    job.height = 30;
    job.where = "scene.lua:9";
    job.camera.eye = Vec3(0.0, 0.0, 0.0);
    job.camera.view = Vec3(0.0, 0.0, -1.0);
    job.camera.fovyDegrees = 50.0;
    return job;
}

/// A unit sphere instance centred at `centre`.
rb::Instance sphereAt(const rb::Shape& sphere, const Vec3& centre) {
    return rbtest::makeInstance(sphere, glm::translate(rb::Mat4(1.0), centre));
}

}  // namespace

SCENARIO(
    "a file the scene names is found in the working directory, then the scene's folder, "
    "then each --assets folder",
    "[ch01][front-door]") {
    GIVEN(
        "a working directory, a scene folder and an assets folder, each holding its own "
        "cow.obj, and a scene that names 'cow.obj'") {
        rbtest::TempDir dir;
        for (const char* folder : {"work", "scene", "assets", "more"})
            fs::create_directory(dir.path() / folder);
        const std::string inWork = dir.write("work/cow.obj", "v 0 0 0\n");
        const std::string inScene = dir.write("scene/cow.obj", "v 0 0 0\n");
        const std::string inAssets = dir.write("assets/cow.obj", "v 0 0 0\n");
        rb::SceneBuilder builder;
        builder.sceneDir = (dir.path() / "scene").string();
        builder.options.assetDirs = {(dir.path() / "more").string(),
                                     (dir.path() / "assets").string()};
        WorkingDirectory cd(dir.path() / "work");

        WHEN("all three hold it") {
            THEN("the working directory's copy is used") {
                CHECK(fs::equivalent(rb::findSceneFile(builder, "cow.obj", "gr.mesh"), inWork));
            }
        }
        WHEN("the working directory does not") {
            fs::remove(inWork);
            THEN("the scene folder's copy is used") {
                CHECK(fs::equivalent(rb::findSceneFile(builder, "cow.obj", "gr.mesh"), inScene));
            }
        }
        WHEN("only an --assets folder holds it, the second one named") {
            fs::remove(inWork);
            fs::remove(inScene);
            THEN("the --assets folders are searched in the order given, and it is found") {
                CHECK(fs::equivalent(rb::findSceneFile(builder, "cow.obj", "gr.mesh"), inAssets));
            }
        }
        WHEN("no place holds it") {
            fs::remove(inWork);
            fs::remove(inScene);
            fs::remove(inAssets);
            const std::string message =
                errorOf([&] { rb::findSceneFile(builder, "cow.obj", "gr.mesh"); });
            THEN("the error names the call, the file and all four places, in search order") {
                const auto at = [&](const char* folder) {
                    return message.find((dir.path() / folder / "cow.obj").string());
                };
                CHECK_THAT(message, Contains("gr.mesh: cannot find 'cow.obj'"));
                REQUIRE(at("work") != std::string::npos);
                REQUIRE(at("scene") != std::string::npos);
                REQUIRE(at("more") != std::string::npos);
                REQUIRE(at("assets") != std::string::npos);
                CHECK(at("work") < at("scene"));
                CHECK(at("scene") < at("more"));
                CHECK(at("more") < at("assets"));
            }
        }
    }
    GIVEN("a scene whose folder is the working directory") {
        rbtest::TempDir dir;
        rb::SceneBuilder builder;
        builder.sceneDir = dir.path().string();
        WorkingDirectory cd(dir.path());
        THEN("that folder is searched once, not twice") {
            CHECK(rb::sceneFileCandidates(builder, "cow.obj").size() == 1);
        }
    }
}

SCENARIO(
    "a scene in its own folder loads its mesh and its require()d helper from there, "
    "wherever it is run from",
    "[ch01][front-door][needs-ch03]") {
    GIVEN("a folder holding scene.lua, tri.obj and helper.lua, and another working directory") {
        rbtest::TempDir dir;
        fs::create_directory(dir.path() / "Assets");
        fs::create_directory(dir.path() / "elsewhere");
        dir.write("Assets/tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        dir.write("Assets/helper.lua", "return {name = 'tri'}\n");
        const std::string scene = dir.write("Assets/scene.lua",
                                            "local h = require('helper')\nroot = gr.node('root')\n"
                                            "root:add_child(gr.mesh(h.name, 'tri.obj'))\n" +
                                                rbtest::renderLine());
        WHEN("rt runs it from the other folder") {
            WorkingDirectory cd(dir.path() / "elsewhere");
            const auto renders = rb::loadScene(scene, rbtest::chapters(3), {});
            THEN("the mesh is found beside the scene and becomes one instance") {
                REQUIRE(renders.size() == 1);
                CHECK(renders[0].instances.size() == 1);
            }
        }
    }
}

SCENARIO("a helper that raises an error while require() loads it stops the scene with that error",
         "[ch01][front-door]") {
    GIVEN("a scene that requires a helper whose first line raises an error") {
        rbtest::TempDir dir;
        dir.write("a_helper_with_a_long_name.lua", "error('this helper refuses to load')\n");
        const std::string scene =
            dir.write("scene.lua", "require('a_helper_with_a_long_name')\n" + rbtest::renderLine());
        WHEN("the scene loads") {
            std::string message;
            try {
                rb::loadScene(scene, rbtest::coreFeatures(), {});
            } catch (const rb::InputError& e) {
                message = e.what();
            }
            // Under make test-sanitize this test also checks that require lets go of the
            // helper's path when the error passes through it: rt once leaked that string
            // (LeakSanitizer reported it at exit).
            THEN("the helper's own error, with its file and line, is what the student sees") {
                CHECK_THAT(message, Contains("a_helper_with_a_long_name.lua:1:") &&
                                        Contains("this helper refuses to load"));
            }
        }
    }
}

SCENARIO("--features=-glossy on its own means everything built except glossy",
         "[ch01][front-door][needs-ch07]") {
    GIVEN("the chapter-7 build") {
        WHEN("the list starts by switching one feature off") {
            const rb::FeatureSet set = rbtest::chapters(7, "-glossy");
            THEN("every other chapter stays on, exactly as with all,-glossy") {
                const rb::FeatureSet reference = rbtest::chapters(7, "all,-glossy");
                CHECK_FALSE(set.enabled("glossy"));
                REQUIRE(set.on().size() == 6);
                for (size_t i = 0; i < set.on().size(); ++i)
                    CHECK(std::string(set.on()[i].name) == reference.on()[i].name);
            }
        }
        WHEN("the list names one feature to switch on") {
            const rb::FeatureSet set = rbtest::chapters(7, "reflection");
            THEN("only the core and that feature are on") {
                CHECK(set.enabled("reflection"));
                CHECK_FALSE(set.enabled("refraction"));
                CHECK(set.on().size() == 4);
            }
        }
    }
}

SCENARIO("a message tells a student to build a chapter only when that chapter is written",
         "[ch01][front-door][needs-ch04]") {
    GIVEN("the newest chapter written in this tree") {
        const int newest = rb::newestChapter();
        THEN("a written chapter's advice names its make target") {
            CHECK(rb::chapterAdvice(newest) ==
                  "build it with make chapter" + std::to_string(newest) + " or later");
        }
        THEN("a later chapter's advice says it is planned, and names no target") {
            const std::string advice = rb::chapterAdvice(newest + 1);
            CHECK_THAT(advice, Contains("planned"));
            CHECK_THAT(advice, !Contains("make"));
        }
    }
    GIVEN("--features naming media (chapter 17, written) in a chapter-3 build") {
        std::string message;
        try {
            rbtest::chapters(3, "all,media");
        } catch (const rb::InputError& e) {
            message = e.what();
        }
        THEN("the error names chapter 17 and the make target that builds it") {
            CHECK_THAT(message, Contains("chapter 17"));
            CHECK_THAT(message, Contains("make chapter17"));
        }
    }
    GIVEN("--features naming photon_map (chapter 16, written) in a chapter-3 build") {
        std::string message;
        try {
            rbtest::chapters(3, "all,photon_map");
        } catch (const rb::InputError& e) {
            message = e.what();
        }
        THEN("the error says how to build chapter 16") {
            CHECK_THAT(message, Contains("make chapter16"));
        }
    }
    GIVEN("a chapter-3 build and a scene calling gr.phongMat (chapter 4, written)") {
        const std::string message = rbtest::loadError("gr.phongMat({1,1,1},{0,0,0},1,0.5,0)\n");
        THEN("the error says how to build chapter 4") {
            CHECK_THAT(message, Contains("make chapter4"));
        }
    }
}

SCENARIO("a scene that reaches for os or io learns that the sandbox left them out",
         "[ch01][front-door]") {
    GIVEN("a scene that calls os.time()") {
        const std::string message = rbtest::loadError("local t = os.time()\n");
        THEN("the error names the line, the sandbox and --unsafe-lua") {
            CHECK_THAT(message, Contains("scene.lua:1:"));
            CHECK_THAT(message, Contains("sandbox"));
            CHECK_THAT(message, Contains("--unsafe-lua"));
        }
    }
    GIVEN("a scene that reads a global nobody defined") {
        THEN("it is nil, as in plain Lua") {
            CHECK(rbtest::loadError("assert(undefined_name == nil)\nroot = gr.node('root')\n" +
                                    rbtest::renderLine()) == "");
        }
    }
}

SCENARIO("rt writes PNG images only, and never under another format's name", "[ch01][front-door]") {
    GIVEN("output names") {
        THEN(".png in any case is accepted") {
            CHECK(rb::hasPngExtension("out.png"));
            CHECK(rb::hasPngExtension("dir.v2/OUT.PNG"));
        }
        THEN("other extensions, or none, are not") {
            CHECK_FALSE(rb::hasPngExtension("out.jpg"));
            CHECK_FALSE(rb::hasPngExtension("png"));
            CHECK_FALSE(rb::hasPngExtension("out.png.bak"));
        }
    }
    WHEN("the command line asks for --output x.jpg") {
        const std::string message = errorOf([] { parse({"--output", "x.jpg", "scene.lua"}); });
        THEN("it is refused before any work, naming the option and the rule") {
            CHECK_THAT(message, Contains("--output"));
            CHECK_THAT(message, Contains("x.jpg"));
            CHECK_THAT(message, Contains(".png"));
        }
    }
}

SCENARIO("--help shows the default of every option that has one, and --assets may repeat",
         "[ch01][front-door]") {
    GIVEN("the chapter-7 build's help text") {
        const std::string help = rb::usage(rbtest::chapters(7).built());
        THEN("each core option with a value shows its default") {
            for (const char* option : {"--features", "--threads", "--seed", "--spp", "--max-depth",
                                       "--size", "--output"}) {
                const size_t at = help.find(option);
                REQUIRE(at != std::string::npos);
                const size_t next = help.find("\n  --", at + 1);
                INFO(option);
                CHECK(help.substr(at, next - at).find("default:") != std::string::npos);
            }
        }
        THEN("each chapter option shows its default") {
            const rb::FeatureSet seven = rbtest::chapters(7);
            for (const rb::Feature& f : seven.built())
                for (const rb::FeatureOption& o : f.options) {
                    INFO(o.name);
                    CHECK(o.defaultValue != nullptr);
                    CHECK_THAT(help, Contains(std::string("default: ") + o.defaultValue));
                }
        }
    }
    WHEN("--assets is given twice") {
        const rb::CommandLine cl = parse({"--assets", "a", "--assets=b", "scene.lua"});
        THEN("both folders are kept, in order") {
            CHECK(cl.assetDirs == std::vector<std::string>{"a", "b"});
        }
    }
}

SCENARIO("--version names the version, the commit and the chapters built",
         "[ch01][front-door][needs-ch03]") {
    GIVEN("the features of chapters 1-3") {
        const std::string text = rb::versionText(rbtest::chapters(3).built());
        THEN("the first line has the version and commit, the second chapters 1-3 by name") {
            CHECK_THAT(text, Contains(std::string("raybook ") + rb::versionNumber() + " (commit " +
                                      rb::gitCommit() + ")\n"));
            CHECK_THAT(text, Contains("chapters 1-3: raycast, phong, bvh\n"));
        }
        THEN("chapter 1 alone is named as one chapter") {
            CHECK_THAT(rb::versionText(rbtest::chapters(1).built()),
                       Contains("\nchapter 1: raycast\n"));
        }
    }
}

SCENARIO("the camera knows which boxes no camera ray can reach", "[ch01][front-door]") {
    GIVEN("a camera at the origin looking down -z with fovy 90 on a square image") {
        rb::CameraSpec spec;
        spec.fovyDegrees = 90.0;  // half-height tan(45°) = 1: the edges are the planes |x| = -z
        const rb::PinholeCamera camera(spec, 100, 100);
        const auto box = [](Vec3 lo, Vec3 hi) {
            rb::AABB b;
            b.extend(lo);
            b.extend(hi);
            return b;
        };
        THEN("a box ahead is shown, one behind the eye is not") {
            CHECK(camera.mayShow(box({-1, -1, -6}, {1, 1, -4})));
            CHECK_FALSE(camera.mayShow(box({-1, -1, 4}, {1, 1, 6})));
        }
        THEN("a box just beyond the right edge (x > -z) is not, one straddling it is") {
            CHECK_FALSE(camera.mayShow(box({5.1, -1, -5}, {6, 1, -5})));
            CHECK(camera.mayShow(box({4.9, -1, -5}, {6, 1, -5})));
        }
        THEN("a box around the eye is shown") {
            CHECK(camera.mayShow(box({-1, -1, -1}, {1, 1, 1})));
        }
    }
}

SCENARIO("a render that can only disappoint says why, and is still made",
         "[ch01][front-door][needs-ch07]") {
    const rb::Sphere sphere;
    const rb::PinholeCamera camera(jobAt().camera, 40, 30);
    GIVEN("a render with no shapes at all") {
        const auto warnings =
            rb::renderWarnings(jobAt(), {}, camera, rbtest::chapters(7), "out.png");
        THEN("one warning, naming the gr.render line, asks whether add_child was forgotten") {
            REQUIRE(warnings.size() == 1);
            CHECK_THAT(warnings[0], Contains("scene.lua:9"));
            CHECK_THAT(warnings[0], Contains("did you add_child?"));
        }
    }
    GIVEN("a sphere behind the camera") {
        const std::vector<rb::Instance> behind = {sphereAt(sphere, Vec3(0, 0, 5))};
        const auto warnings =
            rb::renderWarnings(jobAt(), behind, camera, rbtest::chapters(7), "out.png");
        THEN("one warning says no shape is in front of the camera") {
            REQUIRE(warnings.size() == 1);
            CHECK_THAT(warnings[0], Contains("no shape is in front of the camera"));
        }
    }
    GIVEN("a sphere in front of the camera") {
        const std::vector<rb::Instance> ahead = {sphereAt(sphere, Vec3(0, 0, -5))};
        THEN("there is nothing to say") {
            CHECK(
                rb::renderWarnings(jobAt(), ahead, camera, rbtest::chapters(7), "out.png").empty());
        }
        WHEN("seed 001's gr.render asks for antialiasing (aa = 1), which chapter 8 reads") {
            rb::RenderJob job = jobAt();
            job.options["aa"] = 1.0;
            const auto warnings =
                rb::renderWarnings(job, ahead, camera, rbtest::chapters(7), "out.png");
            THEN("one warning names the argument and chapter 8, which this build lacks") {
                REQUIRE(warnings.size() == 1);
                CHECK_THAT(warnings[0], Contains("aa argument"));
                CHECK_THAT(warnings[0], Contains("chapter 8"));
            }
        }
        WHEN("it asks for ss = 0 (hard shadows), which needs no chapter") {
            rb::RenderJob job = jobAt();
            job.options["ss"] = 0.0;
            THEN("there is nothing to say") {
                CHECK(
                    rb::renderWarnings(job, ahead, camera, rbtest::chapters(5), "out.png").empty());
            }
        }
        WHEN(
            "it asks for dist = 3 glossy samples in a chapter-7 build run with "
            "--features=-glossy") {
            rb::RenderJob job = jobAt();
            job.options["dist"] = 3.0;
            const auto warnings =
                rb::renderWarnings(job, ahead, camera, rbtest::chapters(7, "-glossy"), "out.png");
            THEN("the warning says --features switched chapter 7 off") {
                REQUIRE(warnings.size() == 1);
                CHECK_THAT(warnings[0], Contains("chapter 7"));
                CHECK_THAT(warnings[0], Contains("--features"));
            }
        }
        WHEN("the scene names its output 'picture.ppm'") {
            const auto warnings = rb::renderWarnings(jobAt("picture.ppm"), ahead, camera,
                                                     rbtest::chapters(7), "picture.ppm");
            THEN("a warning says the file holds PNG data") {
                REQUIRE(warnings.size() == 1);
                CHECK_THAT(warnings[0], Contains("picture.ppm"));
                CHECK_THAT(warnings[0], Contains("PNG"));
            }
        }
    }
}

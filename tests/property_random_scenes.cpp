/// \file
/// Property tests: random small scenes, in every chapter.
///
/// The chapter tests check each method against a closed form on scenes chosen by hand; these
/// check two properties on scenes nobody chose. A generator writes Lua scenes with random
/// shapes, hierarchies, transforms, materials, lights and cameras, each value drawn from the
/// range the scene language accepts (the reference page lists them), using only the calls of
/// the chapter at hand. Every such scene, rendered by that chapter's features, must give
///   1. pixels that are finite and non-negative before any clamping (radiance is never negative,
///      and nothing in the range of legal scenes may produce NaN or Inf), and
///   2. the same bits with one thread and with two (the random stream depends on the pixel and
///      the sample, never on the thread).
/// From chapter 9 on the scenes also draw smooth meshes, textures (checkers and a small image,
/// in every mapping), bumps (every pattern, strengths up to ones that would flip the normal),
/// tone maps (the clamped, global and local operators: checked after the post-process too,
/// which must give finite pixels in [0, 1]), lenses, CSG trees over every shape kind (nested,
/// transformed, with materials of their own) and open, capped and frustum cylinders and cones.
/// The scenes are seeded (RB_PROPERTY_SEED changes the seed), so a failure names a scene that
/// can be rerun: the test prints its Lua text.
#include <catch2/catch.hpp>
#include <set>
#include <sstream>
#include <string>

#include "core/post_process.h"
#include "test_helpers.h"

namespace {

using rbtest::Rng;

/// True when no channel of the image exceeds 1 (a display image).
bool allAtMostOne(const rb::Image& image) {
    for (float c : image.data())
        if (!(c <= 1.0f)) return false;
    return true;
}

/// Lua text for random values, drawn from an Rng.
class SceneWriter {
  public:
    SceneWriter(std::uint64_t seed, int chapter) : rng_(seed), chapter_(chapter) {}

    /// A whole scene: objects under a random hierarchy, lights, options and one gr.render.
    std::string scene(int width, int height) {
        std::ostringstream lua;
        lua.precision(17);  // the text carries every bit of the drawn values
        lua << "local root = gr.node('root')\n";
        const int groups = 1 + count(3);
        for (int g = 0; g < groups; ++g) {
            lua << "local g" << g << " = gr.node('g" << g << "')\n";
            lua << transforms("g" + std::to_string(g));
            lua << (g == 0 || rng_.uniform() < 0.5 ? "root" : "g" + std::to_string(g - 1))
                << ":add_child(g" << g << ")\n";
            const int objects = 1 + count(3);
            for (int k = 0; k < objects; ++k) {
                const std::string name = "o" + std::to_string(g) + "_" + std::to_string(k);
                lua << object(name);
                lua << "g" << g << ":add_child(" << name << ")\n";
            }
        }
        lua << options();
        lua << "gr.render(root, 'out.png', " << width << ", " << height << ", "
            << triple(direction() * rng_.uniform(4.0, 12.0)) << ", " << triple(direction()) << ", "
            << triple(direction()) << ", " << rng_.uniform(5.0, 150.0) << ", " << colour(0.0, 0.4)
            << ", {" << lights() << "})\n";
        return lua.str();
    }

  private:
    /// A whole number in [0, n].
    int count(int n) { return static_cast<int>(rng_.uniform() * (n + 1)); }
    /// One of `n` choices, 0-based.
    int choose(int n) { return std::min(n - 1, static_cast<int>(rng_.uniform() * n)); }

    /// A unit direction (never parallel to another drawn one except by a measure-zero chance).
    rb::Vec3 direction() { return rng_.unitVector(); }

    static std::string triple(const rb::Vec3& v) {
        std::ostringstream s;
        s.precision(17);
        s << "{" << v.x << ", " << v.y << ", " << v.z << "}";
        return s.str();
    }
    std::string colour(double lo, double hi) {
        return triple({rng_.uniform(lo, hi), rng_.uniform(lo, hi), rng_.uniform(lo, hi)});
    }

    /// Lua that makes node `name`: a shape, or from chapter 14 sometimes a CSG tree, with
    /// random transforms and a material.
    std::string object(const std::string& name, int depth = 0) {
        std::ostringstream s;
        if (chapter_ >= 14 && depth < 2 && rng_.uniform() < (depth == 0 ? 0.3 : 0.25)) {
            // op(A, B): any objects, themselves CSG trees at times; the operands are not added
            // to the graph, and may or may not carry materials of their own.
            static const char* const kOps[] = {"gr.union", "gr.intersection", "gr.difference"};
            const std::string a = name + "a", b = name + "b";
            s << object(a, depth + 1) << object(b, depth + 1);
            s << "local " << name << " = " << kOps[choose(3)] << "(" << a << ", " << b << ")\n";
        } else {
            s << "local " << name << " = " << shape(name) << "\n";
        }
        s << transforms(name);
        if (depth == 0 || rng_.uniform() < 0.7) s << material(name);
        return s.str();
    }

    /// A shape: sphere, cube, nh_sphere, nh_box, from chapter 3 a mesh, from 9 a smooth mesh,
    /// from 15 a cylinder or cone (capped or open, pointed or a frustum).
    std::string shape(const std::string& name) {
        std::ostringstream s;
        s.precision(17);
        const int kinds = chapter_ >= 15 ? 8 : chapter_ >= 9 ? 6 : chapter_ >= 3 ? 5 : 4;
        switch (choose(kinds)) {
            case 0:
                s << "gr.sphere('" << name << "')";
                break;
            case 1:
                s << "gr.cube('" << name << "')";
                break;
            case 2:
                s << "gr.nh_sphere('" << name << "', " << triple(direction() * rng_.uniform(0, 2))
                  << ", " << rng_.uniform(0.01, 2.0) << ")";
                break;
            case 3:
                s << "gr.nh_box('" << name << "', " << triple(direction() * rng_.uniform(0, 2))
                  << ", " << rng_.uniform(0.01, 2.0) << ")";
                break;
            case 4:
                s << "gr.mesh('" << name << "', '" << rbtest::sourceDir() << "/scenes/a4/"
                  << (rng_.uniform() < 0.5 ? "dodeca.obj" : "cubeSq.obj") << "')";
                break;
            case 5: {
                static const char* const kMeshes[] = {"a4/dodeca.obj", "a4/cubeSq.obj",
                                                      "assets/icosphere80.obj"};
                s << "gr.smooth_mesh('" << name << "', '" << rbtest::sourceDir() << "/scenes/"
                  << kMeshes[choose(3)] << "', {normals = '"
                  << (rng_.uniform() < 0.5 ? "file" : "computed")
                  << "', crease = " << rng_.uniform(0, 180)
                  << ", terminator = " << (rng_.uniform() < 0.5 ? "true" : "false") << "})";
                break;
            }
            case 6:
                s << "gr.cylinder{name = '" << name
                  << "', open = " << (rng_.uniform() < 0.5 ? "true" : "false") << "}";
                break;
            default:
                s << "gr.cone{name = '" << name
                  << "', open = " << (rng_.uniform() < 0.5 ? "true" : "false");
                if (rng_.uniform() < 0.5) s << ", top_radius = " << rng_.uniform(0.001, 1.0);
                s << "}";
        }
        return s.str();
    }

    /// Zero to three random transforms of node `name`: translate, rotate, or a scale that may
    /// mirror and may be far from uniform (never singular: |factor| >= 0.05).
    std::string transforms(const std::string& name) {
        std::ostringstream s;
        s.precision(17);
        const int n = count(3);
        for (int i = 0; i < n; ++i) {
            switch (choose(3)) {
                case 0:
                    s << name << ":translate(" << rng_.uniform(-3, 3) << ", " << rng_.uniform(-3, 3)
                      << ", " << rng_.uniform(-3, 3) << ")\n";
                    break;
                case 1:
                    s << name << ":rotate('"
                      << "xyz"[choose(3)] << "', " << rng_.uniform(-360, 360) << ")\n";
                    break;
                default: {
                    auto factor = [&] {
                        const double f = rng_.uniform(0.05, 3.0);
                        return rng_.uniform() < 0.15 ? -f : f;
                    };
                    s << name << ":scale(" << factor() << ", " << factor() << ", " << factor()
                      << ")\n";
                }
            }
        }
        return s.str();
    }

    /// Lua that gives node `node` a material with the fields of chapters 1..chapter_, each in
    /// its legal range, and from chapters 10 and 11 textures and bumps.
    std::string material(const std::string& node) {
        std::ostringstream s;
        s.precision(17);
        const std::string m = node + "m";
        s << "local " << m << " = gr.material{kd = " << colour(0, 1) << ", ks = " << colour(0, 1)
          << ", shininess = " << rng_.uniform(0.5, 500.0);
        if (chapter_ >= 4 && rng_.uniform() < 0.5) s << ", reflect = " << rng_.uniform(0, 1);
        if (chapter_ >= 5 && rng_.uniform() < 0.5)
            s << ", transparency = " << rng_.uniform(0, 1) << ", ior = " << rng_.uniform(0.2, 4.0)
              << ", schlick = " << (rng_.uniform() < 0.5 ? "true" : "false");
        if (chapter_ >= 7 && rng_.uniform() < 0.5) s << ", glossiness = " << rng_.uniform(0, 2);
        s << "}\n";
        if (chapter_ >= 10 && rng_.uniform() < 0.5)
            s << m << ":set_texture(" << (rng_.uniform() < 0.5 ? "'kd', " : "'ks', ") << texture()
              << ")\n";
        if (chapter_ >= 11 && rng_.uniform() < 0.5) s << m << ":set_bump" << bump() << "\n";
        s << node << ":set_material(" << m << ")\n";
        return s.str();
    }

    /// A texture (chapter 10): a checker or the small globe image, in any mapping, scaled and
    /// offset, wrapped or clamped, filtered or not.
    std::string texture() {
        std::ostringstream s;
        s.precision(17);
        static const char* const kMappings[] = {"surface", "planar", "spherical", "cylindrical"};
        s << "gr.texture{";
        if (rng_.uniform() < 0.5)
            s << "checker = {" << colour(0, 1) << ", " << colour(0, 1) << "}";
        else
            s << "image = '" << rbtest::sourceDir()
              << "/scenes/assets/textures/globe.png', wrap = '"
              << (rng_.uniform() < 0.5 ? "repeat" : "clamp") << "', filter = '"
              << (rng_.uniform() < 0.5 ? "bilinear" : "nearest") << "'";
        auto nonZero = [&] { return (rng_.uniform() < 0.2 ? -1 : 1) * rng_.uniform(0.05, 20); };
        s << ", mapping = '" << kMappings[choose(4)] << "', scale = {" << nonZero() << ", "
          << nonZero() << "}, offset = {" << rng_.uniform(-5, 5) << ", " << rng_.uniform(-5, 5)
          << "}}";
        return s.str();
    }

    /// A bump (chapter 11) of every pattern, with strengths from none to far past flipping.
    std::string bump() {
        std::ostringstream s;
        s.precision(17);
        const double strength =
            (rng_.uniform() < 0.5 ? -1 : 1) *
            (rng_.uniform() < 0.2 ? rng_.uniform(0, 1000) : rng_.uniform(0, 0.2));
        s << "{strength = " << strength << ", ";
        switch (choose(4)) {
            case 0:
                s << "pattern = 'ripples', wavelength = " << rng_.uniform(0.01, 2)
                  << ", centre = " << triple(direction() * rng_.uniform(0, 2));
                break;
            case 1:
                s << "pattern = 'noise', scale = " << rng_.uniform(0.01, 2)
                  << ", octaves = " << 1 + count(7) << ", seed = " << count(100);
                break;
            case 2:
                s << "pattern = 'ramp', slope = " << triple(direction() * rng_.uniform(0, 3));
                break;
            default:
                s << "pattern = 'image', file = '" << rbtest::sourceDir()
                  << "/scenes/assets/tiles-height.png', mapping = '"
                  << (rng_.uniform() < 0.5 ? "surface" : "planar") << "'";
        }
        s << "}";
        return s.str();
    }

    /// Non-negative falloff coefficients, not all zero.
    std::string falloff() {
        return triple({rng_.uniform(0.05, 1.0), rng_.uniform(0, 0.5), rng_.uniform(0, 0.2)});
    }

    /// One to three lights: point lights, and from chapter 6 area and ball lights.
    std::string lights() {
        std::ostringstream s;
        s.precision(17);
        const int n = 1 + count(2);
        for (int i = 0; i < n; ++i) {
            if (i > 0) s << ", ";
            const rb::Vec3 position = direction() * rng_.uniform(0.0, 8.0);
            const int kind = chapter_ >= 6 ? choose(3) : 0;
            if (kind == 0) {
                s << "gr.light(" << triple(position) << ", " << colour(0, 1) << ", " << falloff()
                  << ")";
            } else if (kind == 1) {
                const rb::Vec3 normal = direction();
                rb::Vec3 left = direction();
                if (std::abs(glm::dot(normal, left)) > 0.99) left = glm::cross(normal, {1, 0, 0});
                s << "gr.area_light{position = " << triple(position)
                  << ", colour = " << colour(0, 1) << ", falloff = " << falloff() << ", size = {"
                  << rng_.uniform(0, 3) << ", " << rng_.uniform(0, 3)
                  << "}, normal = " << triple(normal) << ", left = " << triple(left)
                  << ", samples = " << 1 + count(2) << "}";
            } else {
                s << "gr.ball_light{position = " << triple(position)
                  << ", colour = " << colour(0, 1) << ", falloff = " << falloff()
                  << ", radius = " << rng_.uniform(0, 1.5) << ", samples = " << 1 + count(2) << "}";
            }
        }
        return s.str();
    }

    /// Scene-wide options and the pixel sampler of the chapter, kept small so that a scene renders
    /// in milliseconds.
    std::string options() {
        std::ostringstream s;
        // From chapter 9 on, at most 4 bounces: glossy lobes branch at every one, and the
        // scenes of chapters 4 to 8 already reach depth 6.
        if (chapter_ >= 4) s << "gr.option('max_depth', " << count(chapter_ >= 9 ? 4 : 6) << ")\n";
        if (chapter_ >= 7) {
            s << "gr.option('glossy_samples', " << count(4) << ")\n";
            s << "gr.option('glossy_sampler', " << count(1) << ")\n";
        }
        if (chapter_ >= 8) {
            // A pixel sampler: none, random, uniform, jittered (n² samples) or adaptive.
            static const char* const kSamplers[] = {"none", "random", "uniform", "jittered",
                                                    "adaptive"};
            const char* sampler = kSamplers[choose(5)];
            const int n = 1 + count(2);
            s << "gr.antialias{sampler = '" << sampler << "', samples = " << n * n
              << ", threshold = " << rng_.uniform(0.0, 0.5) << ", depth = " << count(3) << "}\n";
        }
        if (chapter_ >= 12 && rng_.uniform() < 0.6) {
            // A tone map: the course's clamp, Reinhard's global curve or his local operator.
            static const char* const kOperators[] = {"none", "global", "local"};
            s << "gr.tone_map{operator = '" << kOperators[choose(3)]
              << "', key = " << rng_.uniform(0.01, 1.0) << ", exposure = " << rng_.uniform(-5, 5)
              << ", srgb = " << (rng_.uniform() < 0.5 ? "true" : "false") << "}\n";
        }
        if (chapter_ >= 13 && rng_.uniform() < 0.6)
            s << "gr.lens{aperture = " << rng_.uniform(0, 1)
              << ", focus = " << rng_.uniform(0.5, 20) << ", samples = " << 1 + count(3)
              << ", shape = '" << (rng_.uniform() < 0.5 ? "disk" : "square") << "'}\n";
        return s.str();
    }

    Rng rng_;
    int chapter_;
};

/// Scenes per chapter: enough to reach the rarer combinations (mirror inside glass under a ball
/// light) many times, few enough to stay within a few seconds for all chapters. The sanitizer
/// tree renders a tenth of them (rbtest::samples); make soak renders thousands there.
constexpr int kScenesPerChapter = rbtest::samples(40);

}  // namespace

SCENARIO(
    "random legal scenes of every chapter render finite, non-negative and the same bits on "
    "one thread and two",
    "[property]") {
    const std::uint64_t seed = rbtest::seedFromEnv("RB_PROPERTY_SEED");
    GIVEN(std::to_string(kScenesPerChapter) + " random scenes of each chapter, 96 x 64 pixels") {
        WHEN("each is rendered by its chapter, 2 samples a pixel, on one thread and on two") {
            THEN("every pixel is finite and non-negative, and the two images are one") {
                int scenesWithBothThreads = 0, scenesRendered = 0, toneMapped = 0;
                for (int chapter = 1; chapter <= rb::newestChapter(); ++chapter) {
                    const rb::FeatureSet features = rbtest::chapters(chapter);
                    for (int i = 0; i < kScenesPerChapter; ++i) {
                        SceneWriter writer(seed * 1000003 + chapter * 1000 + i, chapter);
                        const std::string lua = writer.scene(96, 64);
                        CAPTURE(chapter, i, lua);
                        const std::unique_ptr<rb::World> world =
                            rbtest::worldFromLua(lua, features);
                        std::vector<int> tileThreads;
                        rb::RenderSettings one{.threads = 1, .seed = 7, .samplesPerPixel = 2};
                        rb::RenderSettings two{.threads = 2, .seed = 7, .samplesPerPixel = 2};
                        two.tileThreads = &tileThreads;
                        two.shouldStop = rbtest::bothThreadsTakeTiles();
                        const rb::Image a = rbtest::renderWorld(*world, one);
                        const rb::Image b = rbtest::renderWorld(*world, two);
                        REQUIRE(rbtest::allFiniteNonNegative(a));
                        REQUIRE(rbtest::bitIdentical(a, b));
                        if (world->pipeline.postProcess) {
                            // The tone map (chapter 12) turns the film into display values.
                            rb::Image displayA = a, displayB = b;
                            world->pipeline.postProcess->apply(displayA);
                            world->pipeline.postProcess->apply(displayB);
                            REQUIRE(rbtest::allFiniteNonNegative(displayA));
                            REQUIRE(allAtMostOne(displayA));
                            REQUIRE(rbtest::bitIdentical(displayA, displayB));
                            ++toneMapped;
                        }
                        ++scenesRendered;
                        const std::set<int> workers(tileThreads.begin(), tileThreads.end());
                        if (workers.size() == 2) ++scenesWithBothThreads;
                    }
                }
                // The thread comparison says something only for scenes whose 24 tiles were
                // shared by both threads. Left to the OpenMP runtime and the machine's load, as
                // few as 102 of 280 scenes were (2 cores, load average 7); the hook makes each
                // thread wait for the other before its first tile, so every scene is.
                INFO(scenesWithBothThreads << " of " << scenesRendered
                                           << " scenes had tiles on both threads");
                CHECK(scenesWithBothThreads == scenesRendered);
                // Chapters 12 to 15 each draw a tone map for about half their scenes: about
                // twice the scenes of one chapter in all.
                CHECK(toneMapped >= kScenesPerChapter);
            }
        }
    }
}

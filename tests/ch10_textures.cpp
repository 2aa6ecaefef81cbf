/// \file
/// Chapter 10 tests: textures.
///
/// Chapter 10 claims that every surface point has texture coordinates (u, v): the sphere's
/// angles (u = φ/2π, v = θ/π), each box face's square, a plane's projection and a mesh's `vt`
/// blended by barycentrics; that an image is looked up between its texels by bilinear
/// filtering, which is exact wherever the image is a linear function; that a repeating texture
/// has no seam (u = 0 and u = 1 give the same colour); that 8-bit files are sRGB-decoded to
/// linear light, and the decode is inverted exactly by the encode at every 8-bit level; and
/// that a scene without textures, or with the feature off, renders exactly as before. The
/// tests compare each mapping with points whose angles or faces are known by hand, the filter
/// with the ramp's own formula, and the decode with IEC 61966-2-1's; bad files must fail with
/// a message that names them.
#include <stb_image_write.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "core/error.h"
#include "smooth_mesh/smooth_mesh.h"
#include "test_helpers.h"
#include "texture/surface_texture.h"
#include "texture/texture.h"
#include "texture/texture_image.h"
#include "texture/uv_mapping.h"

using Catch::Contains;
using rb::Colour;
using rb::Vec2;
using rb::Vec3;

namespace {

constexpr double kPi = std::numbers::pi;

/// An image of width × height whose texel (x, y) is f(x, y), built in memory.
template <class F>
rb::TextureImage makeImage(int width, int height, F f) {
    rb::TextureImage image;
    image.width = width;
    image.height = height;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) image.texels.push_back(glm::vec3(f(x, y)));
    return image;
}

/// Write an 8-bit RGB PNG of width × height whose pixel (x, y) is f(x, y) (levels 0–255).
template <class F>
std::string writePng(const rbtest::TempDir& dir, const std::string& name, int width, int height,
                     F f) {
    std::vector<unsigned char> pixels;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const std::array<int, 3> c = f(x, y);
            for (int k = 0; k < 3; ++k) pixels.push_back(static_cast<unsigned char>(c[k]));
        }
    const std::string path = (dir.path() / name).string();
    REQUIRE(stbi_write_png(path.c_str(), width, height, 3, pixels.data(), width * 3) != 0);
    return path;
}

/// The bytes of a file.
std::string readBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

/// The hit of a world-space ray with one instance, turned into a world-space Hit.
rb::Hit hitInstance(const rb::Instance& instance, const rb::Ray& ray) {
    rb::ObjectHit oh;
    REQUIRE(instance.intersect(ray, std::numeric_limits<double>::infinity(), oh));
    return instance.toWorld(ray, oh);
}

/// The message of the InputError that loading `path` throws, or "".
std::string loadImageError(const std::string& path, const rb::MemoryBudget& budget = {}) {
    try {
        rb::loadTextureImage(path, budget);
    } catch (const rb::InputError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

// ---- UV mapping -----------------------------------------------------------------------------

// [ch10-sphere-uv]
SCENARIO("the sphere's (u, v) is (φ/2π, θ/π) at points whose angles are known", "[ch10][ex10.1]") {
    GIVEN("points on the unit sphere at known longitude φ and angle θ from the south pole") {
        // Source: φ measured about +y from +x towards −z, θ from −y (uv_mapping.h).
        struct Case {
            Vec3 d;
            double u, v;
        };
        const double s = std::sqrt(0.5);
        const std::vector<Case> cases = {
            {{1, 0, 0}, 0.0, 0.5},
            {{0, 0, -1}, 0.25, 0.5},
            {{-1, 0, 0}, 0.5, 0.5},
            {{0, 0, 1}, 0.75, 0.5},
            {{s, s, 0}, 0.0, 0.75},
            {{0, -s, -s}, 0.25, 0.25},
            {{-0.5, 0, std::sqrt(0.75)}, 2.0 / 3.0, 0.5},  // φ = 240°
        };
        THEN("sphereUV returns them, and the poles have v = 0 and v = 1") {
            for (const Case& c : cases) {
                const rb::SurfaceUV s = rb::sphereUV(c.d);
                CHECK(s.uv.x == Approx(c.u).margin(1e-12));
                CHECK(s.uv.y == Approx(c.v).margin(1e-12));
            }
            CHECK(rb::sphereUV(Vec3(0, -1, 0)).uv.y == 0.0);
            CHECK(rb::sphereUV(Vec3(0, 1, 0)).uv.y == 1.0);
        }
    }
    GIVEN("a sphere of radius 2 centred at (3, 1, -2), hit by a ray") {
        rb::Sphere sphere;
        const auto instance = rbtest::makeInstance(
            sphere, glm::scale(glm::translate(rb::Mat4(1.0), Vec3(3, 1, -2)), Vec3(2.0)));
        WHEN("the ray comes down the y axis onto its top, and along -x onto its +x side") {
            const rb::Hit top = hitInstance(instance, rb::Ray{Vec3(3, 10, -2), Vec3(0, -1, 0)});
            const rb::Hit side = hitInstance(instance, rb::Ray{Vec3(10, 1, -2), Vec3(-1, 0, 0)});
            THEN("the top is v = 1 and the +x side is (0, 1/2): the object's own angles") {
                CHECK(rb::surfaceUV(top).uv.y == Approx(1.0));
                CHECK(rb::surfaceUV(side).uv.x == Approx(0.0).margin(1e-12));
                CHECK(rb::surfaceUV(side).uv.y == Approx(0.5));
            }
        }
    }
}
// [ch10-sphere-uv]

SCENARIO("dp/du and dp/dv are the derivatives of the surface along its (u, v)", "[ch10][ex10.1]") {
    GIVEN("a point on the sphere away from the poles") {
        const Vec3 d = glm::normalize(Vec3(0.3, -0.4, 0.8));
        const rb::SurfaceUV s = rb::sphereUV(d);
        WHEN("the point is moved by a small step in u, then in v") {
            // p(u, v) = (sinθ cosφ, −cosθ, −sinθ sinφ) with φ = 2πu, θ = πv.
            const auto p = [](double u, double v) {
                const double phi = 2 * kPi * u, theta = kPi * v;
                return Vec3(std::sin(theta) * std::cos(phi), -std::cos(theta),
                            -std::sin(theta) * std::sin(phi));
            };
            const double h = 1e-6;
            const Vec3 du = (p(s.uv.x + h, s.uv.y) - p(s.uv.x - h, s.uv.y)) / (2 * h);
            const Vec3 dv = (p(s.uv.x, s.uv.y + h) - p(s.uv.x, s.uv.y - h)) / (2 * h);
            THEN("the central differences match dpdu and dpdv") {
                // Source: central differences err by O(h²) ≈ 1e-12 here, plus rounding ≈ 1e-10.
                CHECK(glm::length(du - s.dpdu) < 1e-7);
                CHECK(glm::length(dv - s.dpdv) < 1e-7);
            }
        }
    }
}

SCENARIO("every face of the box shows its texture upright and unmirrored from outside", "[ch10]") {
    GIVEN("the unit cube's six faces") {
        for (int axis = 0; axis < 3; ++axis)
            for (int side = 0; side < 2; ++side) {
                Vec3 p(0.3, 0.6, 0.8);
                p[axis] = side;
                const rb::SurfaceUV s = rb::boxFaceUV(p, axis);
                Vec3 outward(0.0);
                outward[axis] = side ? 1.0 : -1.0;
                // The face in the names: sections of one name in a loop run only the first time.
                THEN("dp/du × dp/dv is the outward normal (u right, v up, seen from outside), on "
                     "face " << axis << side) {
                    CHECK(glm::cross(s.dpdu, s.dpdv) == outward);
                }
                THEN("(u, v) lies in the unit square and moves with dp/du and dp/dv, on face "
                     << axis << side) {
                    const Vec3 q = p + 0.1 * s.dpdu + 0.05 * s.dpdv;
                    const rb::SurfaceUV t = rb::boxFaceUV(q, axis);
                    CHECK(t.uv.x == Approx(s.uv.x + 0.1));
                    CHECK(t.uv.y == Approx(s.uv.y + 0.05));
                    CHECK(s.uv.x >= 0.0);
                    CHECK(s.uv.x <= 1.0);
                }
            }
    }
    GIVEN("a ray hitting the front (+z) face at (0.25, 0.75)") {
        rb::Box box;
        const auto instance = rbtest::makeInstance(box, rb::Mat4(1.0));
        const rb::Hit hit = hitInstance(instance, rb::Ray{Vec3(0.25, 0.75, 5), Vec3(0, 0, -1)});
        THEN("its (u, v) is (0.25, 0.75): x to the right, y up") {
            CHECK(rb::surfaceUV(hit).uv.x == Approx(0.25));
            CHECK(rb::surfaceUV(hit).uv.y == Approx(0.75));
        }
    }
}

SCENARIO("the planar mapping projects onto the ground plane", "[ch10]") {
    GIVEN("a box scaled into a floor, hit from above at (2.5, 0, -1.5)") {
        rb::Box box;
        const auto floor =
            rbtest::makeInstance(box, rbtest::boxFromTo(Vec3(-5, -1, -5), Vec3(5, 0, 5)));
        const rb::Hit hit = hitInstance(floor, rb::Ray{Vec3(2.5, 3, -1.5), Vec3(0, -1, 0)});
        THEN("the planar (u, v) is the object-space (x, -z)") {
            // Source: object space of boxFromTo is (p - lo) / (hi - lo): x = 0.75, z = 0.35.
            const rb::SurfaceUV s = rb::surfaceUV(hit, rb::UVMapping::Planar);
            CHECK(s.uv.x == Approx(0.75));
            CHECK(s.uv.y == Approx(-0.35));
            AND_THEN("dp/du and dp/dv are the world-space axes scaled by the floor's size") {
                CHECK(s.dpdu == Vec3(10, 0, 0));
                CHECK(s.dpdv == Vec3(0, 0, -10));
            }
        }
    }
}

SCENARIO("the cylindrical mapping is the longitude about y and the height", "[ch10]") {
    GIVEN("points around the y axis at radius 0.3 and known angles and heights") {
        THEN("u = φ/2π as on the sphere and v = y, with dp/du = 2π(z, 0, -x)") {
            // Source: φ = 90° is the −z direction, φ = 180° the −x direction (uv_mapping.h).
            const rb::SurfaceUV a = rb::cylindricalUV(Vec3(0, 0.4, -0.3));
            CHECK(a.uv.x == Approx(0.25));
            CHECK(a.uv.y == Approx(0.4));
            const rb::SurfaceUV b = rb::cylindricalUV(Vec3(-0.3, -2, 0));
            CHECK(b.uv.x == Approx(0.5));
            CHECK(b.uv.y == Approx(-2));
            CHECK(glm::length(a.dpdu - 2 * kPi * Vec3(-0.3, 0, 0)) < 1e-12);
            CHECK(a.dpdv == Vec3(0, 1, 0));
        }
    }
}

// [ch10-mesh-uv]
SCENARIO("a mesh's (u, v) is its corners' vt blended by barycentrics", "[ch10][ex10.2]") {
    GIVEN("seed 000's plane.obj: a quad on y = 0 with vt at its corners") {
        // Source: seed 000, section 3.1 (the file as the report prints it).
        std::istringstream obj(
            "o plane\nv -1 0 -1\nv 1 0 -1\nv 1 0 1\nv -1 0 1\n"
            "vt 0 0\nvt 0 1\nvt 1 0\nvt 1 1\nvn 0 1 0\n"
            "f 1/2/1 3/3/1 2/4/1\nf 1/2/1 4/1/1 3/3/1\n");
        const rb::Mesh mesh(rb::parseObj(obj, "plane.obj"), "plane.obj");
        const auto instance = rbtest::makeInstance(mesh, rb::Mat4(1.0));
        WHEN("rays come down onto points of both triangles") {
            THEN("(u, v) = ((x + 1)/2, (1 - z)/2), the affine map the corners define") {
                for (const Vec2 xz : {Vec2(0.3, -0.4), Vec2(-0.7, 0.6), Vec2(0.9, 0.85)}) {
                    const rb::Hit hit =
                        hitInstance(instance, rb::Ray{Vec3(xz.x, 2, xz.y), Vec3(0, -1, 0)});
                    const rb::SurfaceUV s = rb::surfaceUV(hit);
                    CHECK(s.uv.x == Approx((xz.x + 1) / 2));
                    CHECK(s.uv.y == Approx((1 - xz.y) / 2));
                    CHECK(glm::length(s.dpdu - Vec3(2, 0, 0)) < 1e-12);
                    CHECK(glm::length(s.dpdv - Vec3(0, 0, -2)) < 1e-12);
                }
            }
        }
    }
    GIVEN("the same quad as chapter 9's smooth mesh (it wraps the faceted one)") {
        std::istringstream obj(
            "v -1 0 -1\nv 1 0 -1\nv 1 0 1\nv -1 0 1\nvt 0 0\nvt 0 1\nvt 1 0\nvt 1 1\n"
            "vn 0 1 0\nf 1/2/1 3/3/1 2/4/1\nf 1/2/1 4/1/1 3/3/1\n");
        const rb::ObjData data = rb::parseObj(obj, "plane.obj");
        const rb::SmoothMesh smooth(std::make_shared<rb::Mesh>(data, "plane.obj"), data, {});
        const auto instance = rbtest::makeInstance(smooth, rb::Mat4(1.0));
        const rb::Hit hit = hitInstance(instance, rb::Ray{Vec3(0.3, 2, -0.4), Vec3(0, -1, 0)});
        THEN("its (u, v) comes from the same vt") {
            CHECK(rb::surfaceUV(hit).uv.x == Approx(0.65));
            CHECK(rb::surfaceUV(hit).uv.y == Approx(0.7));
        }
    }
    GIVEN("a mesh without vt") {
        const auto mesh = rbtest::makeMesh({{0, 0, 0}, {1, 0, 0}, {0, 0, -1}}, {{0, 1, 2}});
        const auto instance = rbtest::makeInstance(*mesh, rb::Mat4(1.0));
        const rb::Hit hit = hitInstance(instance, rb::Ray{Vec3(0.2, 1, -0.3), Vec3(0, -1, 0)});
        THEN("it falls back to the planar mapping, and its barycentrics stay in Hit::uv") {
            CHECK(rb::surfaceUV(hit).uv.x == Approx(0.2));
            CHECK(rb::surfaceUV(hit).uv.y == Approx(0.3));
            CHECK(hit.uv.x == Approx(0.2));  // b1: the weight of corner (1, 0, 0)
            CHECK(hit.uv.y == Approx(0.3));  // b2: the weight of corner (0, 0, -1)
        }
    }
}
// [ch10-mesh-uv]

// ---- Lookup ---------------------------------------------------------------------------------

// [ch10-bilinear]
SCENARIO("bilinear filtering is exact on a linear ramp", "[ch10][ex10.4]") {
    GIVEN(
        "a 7 × 5 image whose texels sample the ramp f(s, t) = 0.1 + 0.6 s + 0.3 t at their "
        "centres") {
        const int w = 7, h = 5;
        const auto f = [](double s, double t) { return 0.1 + 0.6 * s + 0.3 * t; };
        // Texel (x, y) is centred at s = (x + ½)/w, t = 1 − (y + ½)/h (row 0 at the top).
        const auto image = makeImage(
            w, h, [&](int x, int y) { return Colour(f((x + 0.5) / w, 1.0 - (y + 0.5) / h)); });
        WHEN("it is looked up anywhere between the outermost texel centres") {
            rbtest::Rng rng(rbtest::seedFromEnv("RB_CH10_SEED"));
            THEN("the result is the ramp itself, to float precision") {
                for (int k = 0; k < 1000; ++k) {
                    const double s = (0.5 + (w - 1) * rng.uniform()) / w;
                    const double t = (0.5 + (h - 1) * rng.uniform()) / h;
                    const Colour c = rb::sampleBilinear(image, Vec2(s, t), rb::Wrap::Clamp);
                    // Source: a bilinear blend reproduces any function linear in s and t;
                    // the texels are floats (relative rounding 6e-8).
                    REQUIRE(c.r == Approx(f(s, t)).margin(1e-6));
                }
            }
        }
        WHEN("it is looked up beyond the edge texels' centres with clamp") {
            THEN("the edge value extends outwards") {
                const Colour c = rb::sampleBilinear(image, Vec2(0.02, 0.5), rb::Wrap::Clamp);
                CHECK(c.r == Approx(f(0.5 / w, 0.5)).margin(1e-6));
            }
        }
        WHEN("the nearest texel is taken instead") {
            THEN("it is off the ramp between centres: the filter is what makes it exact") {
                const Colour c = rb::sampleNearest(image, Vec2(1.0 / w, 0.5), rb::Wrap::Clamp);
                CHECK(std::abs(c.r - f(1.0 / w, 0.5)) > 0.04);
            }
        }
    }
}
// [ch10-bilinear]

// [ch10-seam]
SCENARIO("a repeating texture has no seam: u = 0 and u = 1 agree", "[ch10][ex10.1][ex10.4]") {
    GIVEN("an image of random texels") {
        rbtest::Rng rng(rbtest::seedFromEnv("RB_CH10_SEED"));
        const auto image =
            makeImage(9, 6, [&](int, int) { return Colour(rng.uniform(), rng.uniform(), 0.5); });
        THEN(
            "with repeat, (0, v) and (1, v) give the same colour for every v, bilinear or "
            "nearest") {
            for (int k = 0; k <= 20; ++k) {
                const double v = k / 20.0;
                CHECK(rb::sampleBilinear(image, Vec2(0.0, v), rb::Wrap::Repeat) ==
                      rb::sampleBilinear(image, Vec2(1.0, v), rb::Wrap::Repeat));
                CHECK(rb::sampleNearest(image, Vec2(0.0, v), rb::Wrap::Repeat) ==
                      rb::sampleNearest(image, Vec2(1.0, v), rb::Wrap::Repeat));
                // v wraps too, and the colour is continuous across the seam.
                CHECK(rb::sampleBilinear(image, Vec2(v, 0.0), rb::Wrap::Repeat) ==
                      rb::sampleBilinear(image, Vec2(v, 1.0), rb::Wrap::Repeat));
                const Colour left = rb::sampleBilinear(image, Vec2(-1e-9, v), rb::Wrap::Repeat);
                const Colour right = rb::sampleBilinear(image, Vec2(1e-9, v), rb::Wrap::Repeat);
                CHECK(glm::length(left - right) < 1e-7);
            }
        }
        THEN("with clamp the two edges differ: the seam test can fail") {
            CHECK(rb::sampleBilinear(image, Vec2(0.0, 0.5), rb::Wrap::Clamp) !=
                  rb::sampleBilinear(image, Vec2(1.0, 0.5), rb::Wrap::Clamp));
        }
    }
    GIVEN("points on a sphere just either side of its seam (φ = ±1e-9)") {
        const Vec3 before(std::cos(1e-9), 0.2, std::sin(1e-9));
        const Vec3 after(std::cos(1e-9), 0.2, -std::sin(1e-9));
        THEN("their u are 1 - 1.6e-10 and 1.6e-10, and a repeating image gives both one colour") {
            const Vec2 a = rb::sphereUV(glm::normalize(before)).uv;
            const Vec2 b = rb::sphereUV(glm::normalize(after)).uv;
            CHECK(a.x > 0.999);
            CHECK(b.x < 0.001);
            rbtest::Rng rng(7);
            const auto image = makeImage(16, 8, [&](int, int) { return Colour(rng.uniform()); });
            CHECK(std::abs(rb::sampleBilinear(image, a, rb::Wrap::Repeat).r -
                           rb::sampleBilinear(image, b, rb::Wrap::Repeat).r) < 1e-7);
        }
    }
}
// [ch10-seam]

// [ch10-srgb]
SCENARIO("8-bit sRGB levels decode to linear light and encode back to themselves", "[ch10][ex10.3]") {
    GIVEN("the decode and encode of IEC 61966-2-1") {
        THEN("mid-grey 0.5 is 21.4% linear, and the two pieces meet at the knee") {
            // Source: ((0.5 + 0.055) / 1.055)^2.4 = 0.214041140482232 (hand computation).
            CHECK(rb::srgbToLinear(0.5) == Approx(0.214041140482232).epsilon(1e-12));
            CHECK(rb::srgbToLinear(0.04045) == Approx(0.04045 / 12.92).epsilon(1e-12));
            CHECK(rb::srgbToLinear(0.0404500001) == Approx(0.04045 / 12.92).epsilon(1e-6));
            CHECK(rb::srgbToLinear(1.0) == Approx(1.0).epsilon(1e-15));
        }
        THEN("every level k/255 survives the round trip decode -> encode -> round(255 x)") {
            for (int k = 0; k < 256; ++k) {
                const double back = rb::linearToSrgb(rb::srgbToLinear(k / 255.0));
                REQUIRE(std::lround(back * 255.0) == k);
                REQUIRE(back == Approx(k / 255.0).margin(1e-12));
            }
        }
        THEN("the decode is increasing, so no two levels swap") {
            for (int k = 1; k < 256; ++k)
                REQUIRE(rb::srgbToLinear(k / 255.0) > rb::srgbToLinear((k - 1) / 255.0));
        }
    }
    GIVEN("a PNG with the levels 0, 64, 128 and 255") {
        rbtest::TempDir dir;
        const int levels[4] = {0, 64, 128, 255};
        const std::string png = writePng(dir, "levels.png", 4, 1, [&](int x, int) {
            return std::array<int, 3>{levels[x], levels[x], 255 - levels[x]};
        });
        const auto image = rb::loadTextureImage(png);
        THEN("the loaded texels are the decoded levels: the file is sRGB, the texture linear") {
            REQUIRE(image->width == 4);
            REQUIRE(image->height == 1);
            for (int x = 0; x < 4; ++x) {
                CHECK(image->texel(x, 0).r == Approx(rb::srgbToLinear(levels[x] / 255.0)));
                CHECK(image->texel(x, 0).b == Approx(rb::srgbToLinear((255 - levels[x]) / 255.0)));
            }
        }
    }
}
// [ch10-srgb]

// [ch10-checker]
SCENARIO("the checker alternates unit squares of texture space", "[ch10][ex10.5]") {
    GIVEN("a white and black checker tiled 8 × 8 over a face") {
        rb::CheckerTexture checker(Colour(1.0), Colour(0.0));
        THEN("squares whose corners' sum ⌊s⌋ + ⌊t⌋ is even are white, odd are black") {
            CHECK(checker.lookup(Vec2(0.5, 0.5)) == Colour(1.0));
            CHECK(checker.lookup(Vec2(1.5, 0.5)) == Colour(0.0));
            CHECK(checker.lookup(Vec2(1.5, 1.5)) == Colour(1.0));
            CHECK(checker.lookup(Vec2(-0.5, 0.5)) == Colour(0.0));  // ⌊−0.5⌋ = −1
            CHECK(checker.lookup(Vec2(-0.5, -0.5)) == Colour(1.0));
            CHECK(checker.lookup(Vec2(7.99, 0.01)) == Colour(0.0));
            CHECK(checker.lookup(Vec2(1e15 + 1, 0.5)) == Colour(0.0));  // exact far away
        }
        THEN("a face with scale {8, 8} has 32 white squares among its 64") {
            checker.scale = Vec2(8.0);
            int white = 0;
            for (int i = 0; i < 8; ++i)
                for (int j = 0; j < 8; ++j)
                    white += checker.lookup(checker.scale * Vec2((i + 0.5) / 8, (j + 0.5) / 8)) ==
                             Colour(1.0);
            CHECK(white == 32);
        }
    }
}
// [ch10-checker]

// ---- Images ---------------------------------------------------------------------------------

SCENARIO("missing, truncated, corrupt, empty or absurdly large images fail with their name",
         "[ch10][ex10.3]") {
    rbtest::TempDir dir;
    const std::string good = writePng(dir, "good.png", 32, 32, [](int x, int y) {
        return std::array<int, 3>{x * 8, y * 8, (x * y) % 256};
    });
    const std::string bytes = readBytes(good);
    GIVEN("a file that does not exist") {
        THEN("the message names it") {
            CHECK_THAT(loadImageError((dir.path() / "nope.png").string()),
                       Contains("nope.png: cannot open the texture image"));
        }
    }
    GIVEN("a PNG cut off half way") {
        const std::string cut = dir.write("cut.png", bytes.substr(0, bytes.size() / 2));
        THEN("the decode fails and says so") {
            CHECK_THAT(loadImageError(cut), Contains("cut.png: the image is truncated or corrupt"));
        }
    }
    GIVEN("a PNG whose compressed data is overwritten") {
        std::string broken = bytes;
        for (size_t k = 60; k < broken.size() - 20; ++k) broken[k] = static_cast<char>(k * 37);
        const std::string path = dir.write("broken.png", broken);
        THEN("the decode fails") {
            CHECK_THAT(loadImageError(path), Contains("broken.png: "));
        }
    }
    GIVEN("a text file named .jpg") {
        const std::string path = dir.write("text.jpg", "this is not an image\n");
        THEN("it is not an image stb_image can read") {
            CHECK_THAT(loadImageError(path), Contains("text.jpg: not an image stb_image can read"));
        }
    }
    /// The good PNG with its header's width and height (big-endian at bytes 16–23) replaced.
    const auto withSize = [&](const std::string& name, unsigned w, unsigned h) {
        std::string changed = bytes;
        for (int k = 0; k < 4; ++k) {
            changed[16 + k] = static_cast<char>((w >> (24 - 8 * k)) & 0xFF);
            changed[20 + k] = static_cast<char>((h >> (24 - 8 * k)) & 0xFF);
        }
        return dir.write(name, changed);
    };
    GIVEN("PNG headers claiming 16000 × 16000 and 60000 × 60000 pixels, and a 64 MiB budget") {
        const rb::MemoryBudget budget = rb::memoryBudgetFromOption("64M");
        THEN("both are refused before anything is decoded, naming the size and the budget") {
            const std::string big = loadImageError(withSize("big.png", 16000, 16000), budget);
            CHECK_THAT(big, Contains("big.png"));
            CHECK_THAT(big, Contains("the 16000x16000 texture image needs about"));
            CHECK_THAT(big, Contains("--max-memory 64M"));
            const std::string huge = loadImageError(withSize("huge.png", 60000, 60000), budget);
            CHECK_THAT(huge, Contains("the 60000x60000 texture image needs about"));
        }
        AND_WHEN("there is no budget") {
            THEN("the 60000 × 60000 one is still refused: stb_image decodes at most 1 GiB") {
                CHECK_THAT(loadImageError(withSize("huge.png", 60000, 60000)),
                           Contains("60000x60000 pixels are more than stb_image decodes"));
            }
        }
    }
    GIVEN("a PNG header claiming 0 × 16 pixels") {
        THEN("the image is empty") {
            CHECK_THAT(loadImageError(withSize("empty.png", 0, 16)),
                       Contains("empty.png: the image is empty (0x16)"));
        }
    }
    GIVEN("the intact file") {
        THEN("it loads") {
            CHECK(loadImageError(good).empty());
        }
    }
}

SCENARIO("each image file is loaded once and shared, found where meshes are found", "[ch10][ex10.3]") {
    rbtest::TempDir dir;
    std::filesystem::create_directories(dir.path() / "maps");
    writePng(dir, "maps/wood.png", 4, 4, [](int x, int) {
        return std::array<int, 3>{x * 60, 0, 0};
    });
    GIVEN("a scene in the same folder naming maps/wood.png through three calls") {
        const std::string lua =
            "local a = gr.material({1,1,1}, {0,0,0}, 1)\n"
            "local b = gr.material({1,1,1}, {0,0,0}, 1)\n"
            "local c = gr.material({1,1,1}, {0,0,0}, 1)\n"
            "gr.texture(a, 'maps/wood.png')\n"
            "b:set_texture_map('maps/../maps/wood.png')\n"
            "c:set_texture(gr.texture{image = 'maps/wood.png', wrap = 'clamp', scale = {2, 2}})\n"
            "root = gr.node('root')\n"
            "for i, m in ipairs({a, b, c}) do\n"
            "  local s = gr.sphere('s' .. i); s:set_material(m); s:translate(3 * i, 0, 0)\n"
            "  root:add_child(s)\n"
            "end\n" +
            rbtest::renderLine();
        rb::SceneLoadOptions options;
        options.era = rb::EraChoice::Modern;
        const auto renders =
            rb::loadScene(dir.write("scene.lua", lua), rbtest::chapters(10), options);
        THEN("the three textures hold one image") {
            std::vector<const rb::TextureImage*> images;
            for (const rb::Instance& i : renders.at(0).instances) {
                const auto* t = dynamic_cast<const rb::ImageTexture*>(i.material->texture("kd"));
                REQUIRE(t != nullptr);
                images.push_back(&t->image());
            }
            REQUIRE(images.size() == 3);
            CHECK(images[0] == images[1]);
            CHECK(images[1] == images[2]);
        }
    }
    GIVEN("a scene elsewhere naming wood.png, with --assets pointing at maps/") {
        rbtest::TempDir other;
        rb::SceneLoadOptions options;
        options.era = rb::EraChoice::Modern;
        options.assetDirs = {(dir.path() / "maps").string()};
        const std::string scene =
            other.write("scene.lua", rbtest::oneMaterialScene("gr.material({1,1,1}, {0,0,0}, 1)",
                                                              "m:set_texture('wood.png')\n"));
        THEN("it is found there") {
            const auto renders = rb::loadScene(scene, rbtest::chapters(10), options);
            CHECK(renders.at(0).instances.at(0).material->texture("kd") != nullptr);
        }
        AND_WHEN("no --assets is given") {
            options.assetDirs.clear();
            THEN("the error lists the places searched") {
                CHECK_THROWS_WITH(rb::loadScene(scene, rbtest::chapters(10), options),
                                  Contains("cannot find 'wood.png'; looked in"));
            }
        }
    }
}

// ---- Lua ------------------------------------------------------------------------------------

SCENARIO("raybook's gr.texture table and the seeds' calls bind textures to materials", "[ch10]") {
    const rb::FeatureSet features = rbtest::chapters(10);
    GIVEN("a checker texture made with named fields") {
        const auto renders = rbtest::loadSceneText(
            rbtest::oneMaterialScene(
                "gr.material({1,1,1}, {0,0,0}, 1)",
                "m:set_texture('ks', gr.texture{checker = {{1,0,0}, {0,0,1}}, scale = {4, 2},"
                " offset = {0.5, 0}, mapping = 'spherical'})\n"),
            features);
        const rb::Material& textured = *renders.at(0).instances.at(0).material;
        THEN("it sits in the ks slot with its placement") {
            REQUIRE(textured.texture("kd") == nullptr);
            const auto* t = dynamic_cast<const rb::CheckerTexture*>(textured.texture("ks"));
            REQUIRE(t != nullptr);
            CHECK(t->scale == Vec2(4, 2));
            CHECK(t->offset == Vec2(0.5, 0));
            CHECK(t->mapping == rb::UVMapping::Spherical);
        }
    }
    GIVEN("mistakes in the calls") {
        const auto error = [&](const std::string& extra) {
            return rbtest::loadError(
                rbtest::oneMaterialScene("gr.material({1,1,1}, {0,0,0}, 1)", extra), features);
        };
        THEN("each names the call and what was expected") {
            CHECK_THAT(error("gr.texture{checker = {{1,0,0}, {0,0,1}}, scael = {2, 2}}\n"),
                       Contains("gr.texture: unknown field 'scael'"));
            CHECK_THAT(error("gr.texture{}\n"), Contains("give exactly one of image"));
            CHECK_THAT(error("gr.texture{checker = {{1,0,0}}}\n"),
                       Contains("field 'checker' must be two colours"));
            CHECK_THAT(error("gr.texture{checker = {{1,0,0}, {0,0,0/0}}}\n"), Contains("colour 2"));
            CHECK_THAT(error("gr.texture{checker = {{1,0,0}, {0,0,1}}, scale = {1, 1/0}}\n"),
                       Contains("field 'scale'"));
            CHECK_THAT(error("gr.texture{checker = {{1,0,0}, {0,0,1}}, mapping = 'cube'}\n"),
                       Contains("field 'mapping' must be one of 'surface', 'planar', "
                                "'spherical', 'cylindrical'"));
            CHECK_THAT(error("gr.texture(m)\n"), Contains("gr.texture"));
            CHECK_THAT(error("gr.texture(42, 'a.png')\n"), Contains("must be a material"));
            CHECK_THAT(error("m:set_texture('bump', 'a.png')\n"), Contains("must be 'kd' or 'ks'"));
            CHECK_THAT(error("m:set_texture(7)\n"), Contains("must be a texture"));
            CHECK_THAT(error("m:set_texture_map()\n"), Contains("material:set_texture_map"));
        }
    }
    GIVEN("a build without chapter 10") {
        THEN("the seeds' calls name the chapter") {
            CHECK_THAT(
                rbtest::loadError(rbtest::oneMaterialScene("gr.material({1,1,1}, {0,0,0}, 1)",
                                                           "gr.texture(m, 'wood.jpg')\n"),
                                  rbtest::chapters(8)),
                Contains("chapter 10"));
            CHECK_THAT(
                rbtest::loadError(rbtest::oneMaterialScene("gr.material({1,1,1}, {0,0,0}, 1)",
                                                           "m:set_texture_map('wood.jpg')\n"),
                                  rbtest::chapters(8)),
                Contains("chapter 10"));
        }
    }
}

// ---- Rendering ------------------------------------------------------------------------------

namespace {

/// A sphere and a floor (a flattened cube) with a light; `floorExtra` and `sphereExtra` run on
/// their materials `fm` and `sm`.
std::string twoObjectScene(const std::string& sphereExtra, const std::string& floorExtra) {
    return "local sm = gr.material({0.7, 0.3, 0.2}, {0.4, 0.4, 0.4}, 30)\n"
           "local fm = gr.material({0.6, 0.6, 0.6}, {0, 0, 0}, 1)\n" +
           sphereExtra + floorExtra +
           "root = gr.node('root')\n"
           "local s = gr.sphere('s'); s:set_material(sm); root:add_child(s)\n"
           "local f = gr.cube('f'); f:scale(8, 0.2, 8); f:translate(-4, -1.2, -6)\n"
           "f:set_material(fm); root:add_child(f)\n"
           "gr.render(root, 'out.png', 48, 36, {0, 1, 5}, {0, -0.2, -1}, {0, 1, 0}, 50,"
           " {0.2, 0.2, 0.2}, {gr.light({3, 5, 5}, {0.9, 0.9, 0.9}, {1, 0, 0})})\n";
}

}  // namespace

SCENARIO("textures change the picture only when the feature is on and a scene uses them",
         "[ch10][ex10.5]") {
    const std::string plain = twoObjectScene("", "");
    const std::string textured = twoObjectScene(
        "",
        "fm:set_texture(gr.texture{checker = {{0.9,0.9,0.9}, {0.1,0.1,0.1}}, scale = {8, 8}})\n");
    GIVEN("a scene without textures") {
        const auto with = rbtest::worldFromLua(plain, rbtest::chapters(10));
        const auto without = rbtest::worldFromLua(plain, rbtest::chapters(8));
        THEN("nothing is installed, and the image equals chapter 8's bit for bit") {
            CHECK(with->pipeline.textureLookup == nullptr);
            CHECK(rbtest::bitIdentical(rbtest::renderSmall(*with), rbtest::renderSmall(*without)));
        }
    }
    GIVEN("the checkered scene") {
        WHEN("the texture feature is off") {
            const auto off = rbtest::worldFromLua(textured, rbtest::chapters(10, "all,-texture"));
            const auto plainWorld = rbtest::worldFromLua(plain, rbtest::chapters(10));
            THEN("it renders as if the texture were not there") {
                CHECK(off->pipeline.textureLookup == nullptr);
                CHECK(rbtest::bitIdentical(rbtest::renderSmall(*off),
                                           rbtest::renderSmall(*plainWorld)));
            }
        }
        WHEN("it is on") {
            const auto on = rbtest::worldFromLua(textured, rbtest::chapters(10));
            const auto plainWorld = rbtest::worldFromLua(plain, rbtest::chapters(10));
            THEN("the floor changes, and the image is the same on 1 and 2 threads") {
                CHECK(on->pipeline.textureLookup != nullptr);
                CHECK_FALSE(rbtest::bitIdentical(rbtest::renderSmall(*on),
                                                 rbtest::renderSmall(*plainWorld)));
                rb::RenderSettings one, two;
                one.threads = 1;
                two.threads = 2;
                CHECK(rbtest::bitIdentical(rbtest::renderWorld(*on, one),
                                           rbtest::renderWorld(*on, two)));
            }
        }
    }
}

SCENARIO("a one-colour image texture shades exactly like its decoded colour as kd", "[ch10][ex10.4]") {
    GIVEN("a 3 × 2 PNG filled with the sRGB level (200, 120, 40), on the sphere") {
        rbtest::TempDir dir;
        writePng(dir, "flat.png", 3, 2, [](int, int) { return std::array<int, 3>{200, 120, 40}; });
        const Colour linear(rb::srgbToLinear(200 / 255.0), rb::srgbToLinear(120 / 255.0),
                            rb::srgbToLinear(40 / 255.0));
        const auto load = [&](const std::string& lua) {
            rb::SceneLoadOptions options;
            options.era = rb::EraChoice::Modern;
            return rb::buildWorld(
                std::move(
                    rb::loadScene(dir.write("s.lua", lua), rbtest::chapters(10), options).at(0)),
                rbtest::chapters(10));
        };
        const auto textured = load(twoObjectScene("gr.texture(sm, 'flat.png')\n", ""));
        const auto direct = load(twoObjectScene(
            "sm = gr.material({" + std::to_string(linear.r) + ", " + std::to_string(linear.g) +
                ", " + std::to_string(linear.b) + "}, {0.4, 0.4, 0.4}, 30)\n",
            ""));
        THEN("every pixel agrees to float precision (the texels are floats)") {
            const rb::Image a = rbtest::renderSmall(*textured);
            const rb::Image b = rbtest::renderSmall(*direct);
            REQUIRE(a.data().size() == b.data().size());
            double worst = 0.0;
            for (size_t k = 0; k < a.data().size(); ++k)
                worst = std::max(worst, static_cast<double>(std::abs(a.data()[k] - b.data()[k])));
            // Source: float texels round the decoded level by ≤ 6e-8 relative; to_string keeps
            // 6 decimals (≤ 5e-7), scaled by light ≤ 1.3.
            CHECK(worst < 1e-6);
            CHECK(worst >= 0.0);
        }
    }
}

// ---- Stability ------------------------------------------------------------------------------

SCENARIO("texture lookups stay finite where the mapping degenerates",
         "[ch10][stability][ex10.2][ex10.5]") {
    GIVEN("the sphere's poles, where φ is undefined") {
        THEN("(u, v) and the derivatives are finite") {
            for (const Vec3 d : {Vec3(0, 1, 0), Vec3(0, -1, 0), Vec3(0, 1, -0.0)}) {
                const rb::SurfaceUV s = rb::sphereUV(d);
                CHECK(rb::isFinite(Vec3(s.uv, 0)));
                CHECK(rb::isFinite(s.dpdu));
                CHECK(rb::isFinite(s.dpdv));
            }
        }
    }
    GIVEN("texture coordinates that are huge, infinite or NaN") {
        const auto image = makeImage(5, 3, [](int x, int y) { return Colour(0.1 * x + 0.2 * y); });
        const double inf = std::numeric_limits<double>::infinity();
        const double nan = std::numeric_limits<double>::quiet_NaN();
        THEN("every lookup returns a texel blend: finite and in the image's range") {
            for (const Vec2 st : {Vec2(1e300, -1e300), Vec2(inf, 0.5), Vec2(nan, nan),
                                  Vec2(-inf, 1e-320), Vec2(-1e-17, 1.0 - 1e-17)})
                for (const rb::Wrap wrap : {rb::Wrap::Repeat, rb::Wrap::Clamp}) {
                    const Colour c = rb::sampleBilinear(image, st, wrap);
                    CHECK(rb::isFinite(c));
                    CHECK(c.r >= 0.0);
                    CHECK(c.r <= 0.8 + 1e-6);
                    CHECK(rb::isFinite(rb::sampleNearest(image, st, wrap)));
                }
            rb::CheckerTexture checker(Colour(1.0), Colour(0.0));
            CHECK(checker.lookup(Vec2(nan, 1.0)) == Colour(1.0));
            CHECK(checker.lookup(Vec2(inf, 1.0)) == Colour(1.0));
        }
    }
    GIVEN("a mesh triangle whose three vt are the same point") {
        std::istringstream obj("v 0 0 0\nv 1 0 0\nv 0 0 -1\nvt 0.5 0.5\nf 1/1 2/1 3/1\n");
        const rb::Mesh mesh(rb::parseObj(obj, "flat.obj"), "flat.obj");
        const auto instance = rbtest::makeInstance(mesh, rb::Mat4(1.0));
        const rb::Hit hit = hitInstance(instance, rb::Ray{Vec3(0.2, 1, -0.2), Vec3(0, -1, 0)});
        THEN("(u, v) is that point and dp/du, dp/dv are zero, not NaN") {
            const rb::SurfaceUV s = rb::surfaceUV(hit);
            CHECK(s.uv == Vec2(0.5, 0.5));
            CHECK(s.dpdu == Vec3(0.0));
            CHECK(s.dpdv == Vec3(0.0));
        }
    }
}

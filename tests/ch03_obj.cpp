/// \file
/// Chapter 3 tests: the Wavefront OBJ loader.
///
/// Chapter 3 claims that raybook reads the meshes people actually have: `v`, `vt` and `vn`
/// lines; faces in all four corner forms (`v`, `v/vt`, `v//vn`, `v/vt/vn`); polygons of any size,
/// split into fans of n-2 triangles; negative (relative) indices; comments, CRLF and tabs. It skips
/// `o`, `g`, `s`, `usemtl` and `mtllib` quietly, and reads the course's quad cube `cubeSq.obj`,
/// which the stock course loader gets wrong. Every malformed line is an InputError naming the file
/// and the line, and no input, however broken, crashes the loader. The tests feed small OBJ texts
/// through std::istringstream and check the exact indices that come out, the geometry of a closed
/// quad cube (its area and volume), the text of each error, and a few thousand random inputs.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <random>
#include <sstream>
#include <string>

#include "core/error.h"
#include "bvh/obj.h"

using Catch::Contains;
using Catch::StartsWith;
using rb::InputError;
using rb::ObjCorner;
using rb::ObjData;
using rb::parseObj;
using rb::Vec3;

namespace {

/// Parse OBJ text held in a string, as if it came from a file called `name`.
ObjData parseText(const std::string& text, const std::string& name = "x.obj") {
    std::istringstream in(text);
    return parseObj(in, name);
}

/// True when the corner has exactly these zero-based indices.
bool cornerIs(const ObjCorner& c, int v, int vt, int vn) {
    return c.v == v && c.vt == vt && c.vn == vn;
}

/// True when every index in every triangle points inside its array (or is -1 where allowed).
bool allIndicesValid(const ObjData& data) {
    const auto inRange = [](int index, std::size_t size) {
        return index >= 0 && static_cast<std::size_t>(index) < size;
    };
    for (const auto& triangle : data.triangles) {
        for (const ObjCorner& c : triangle) {
            if (!inRange(c.v, data.positions.size())) return false;
            if (c.vt != -1 && !inRange(c.vt, data.texcoords.size())) return false;
            if (c.vn != -1 && !inRange(c.vn, data.normals.size())) return false;
        }
    }
    return true;
}

/// Three vertices shared by the small examples below.
const std::string threeVertices =
    "v 0 0 0\n"
    "v 1 0 0\n"
    "v 0 1 0\n";

}  // namespace

//! [obj-face-forms]
SCENARIO("a face written with bare vertex indices gives positions only", "[ch03]") {
    GIVEN("three vertices and the face 'f 1 2 3'") {
        WHEN("it is parsed") {
            const ObjData data = parseText(threeVertices + "f 1 2 3\n");
            THEN("there is one triangle with 0-based position indices and no vt or vn") {
                REQUIRE(data.positions.size() == 3);
                REQUIRE(data.triangles.size() == 1);
                CHECK(cornerIs(data.triangles[0][0], 0, -1, -1));
                CHECK(cornerIs(data.triangles[0][1], 1, -1, -1));
                CHECK(cornerIs(data.triangles[0][2], 2, -1, -1));
                CHECK(data.positions[1] == Vec3(1, 0, 0));
            }
        }
    }
}

SCENARIO("a face written v/vt keeps its texture-coordinate indices", "[ch03]") {
    GIVEN("three vertices, two texture coordinates and the face 'f 1/2 2/1 3/2'") {
        WHEN("it is parsed") {
            const ObjData data = parseText(threeVertices +
                                           "vt 0.25 0.75\n"
                                           "vt 1 0.5\n"
                                           "f 1/2 2/1 3/2\n");
            THEN("each corner has a position and a texture coordinate, but no normal") {
                REQUIRE(data.triangles.size() == 1);
                CHECK(cornerIs(data.triangles[0][0], 0, 1, -1));
                CHECK(cornerIs(data.triangles[0][1], 1, 0, -1));
                CHECK(cornerIs(data.triangles[0][2], 2, 1, -1));
                CHECK(data.texcoords[0] == rb::Vec2(0.25, 0.75));
            }
        }
    }
}

SCENARIO("a face written v//vn keeps its normal indices", "[ch03]") {
    GIVEN("three vertices, one normal and the face 'f 1//1 2//1 3//1'") {
        WHEN("it is parsed") {
            const ObjData data = parseText(threeVertices +
                                           "vn 0 0 1\n"
                                           "f 1//1 2//1 3//1\n");
            THEN("each corner has a position and a normal, but no texture coordinate") {
                REQUIRE(data.triangles.size() == 1);
                for (const ObjCorner& c : data.triangles[0]) CHECK(c.vt == -1);
                for (const ObjCorner& c : data.triangles[0]) CHECK(c.vn == 0);
                CHECK(data.normals[0] == Vec3(0, 0, 1));
            }
        }
    }
}

SCENARIO("a face written v/vt/vn keeps all three indices", "[ch03]") {
    GIVEN("three of each array and the face 'f 1/3/2 2/2/3 3/1/1'") {
        WHEN("it is parsed") {
            const ObjData data = parseText(threeVertices +
                                           "vt 0 0\nvt 1 0\nvt 0 1\n"
                                           "vn 1 0 0\nvn 0 1 0\nvn 0 0 1\n"
                                           "f 1/3/2 2/2/3 3/1/1\n");
            THEN("every index arrives, each shifted to 0-based") {
                REQUIRE(data.triangles.size() == 1);
                CHECK(cornerIs(data.triangles[0][0], 0, 2, 1));
                CHECK(cornerIs(data.triangles[0][1], 1, 1, 2));
                CHECK(cornerIs(data.triangles[0][2], 2, 0, 0));
            }
        }
    }
    GIVEN("a face that mixes the four corner forms") {
        WHEN("it is parsed") {
            const ObjData data =
                parseText(threeVertices + "v 1 1 0\nvt 0 0\nvn 0 0 1\n" + "f 1 2/1 3//1 4/1/1\n");
            THEN("it is accepted, with -1 wherever a corner gave no index") {
                REQUIRE(data.triangles.size() == 2);
                CHECK(cornerIs(data.triangles[0][0], 0, -1, -1));
                CHECK(cornerIs(data.triangles[0][1], 1, 0, -1));
                CHECK(cornerIs(data.triangles[0][2], 2, -1, 0));
                CHECK(cornerIs(data.triangles[1][2], 3, 0, 0));
            }
        }
    }
}
//! [obj-face-forms]

SCENARIO("vertex statements accept their optional components", "[ch03]") {
    GIVEN("a 'v' with a w, a 'v' with an r g b colour, and 'vt' lines with 1, 2 and 3 numbers") {
        const std::string text =
            "v 1 2 3 1.0\n"
            "v 4 5 6 0.5 0.5 0.5\n"
            "v -1.5e2 +2 .5\n"
            "vt 0.5\n"
            "vt 0.25 0.75\n"
            "vt 0.1 0.2 0.3\n"
            "f 1/1 2/2 3/3\n";
        WHEN("it is parsed") {
            const ObjData data = parseText(text);
            THEN("w and the colour are ignored, and a missing vt v is 0") {
                REQUIRE(data.positions.size() == 3);
                CHECK(data.positions[0] == Vec3(1, 2, 3));
                CHECK(data.positions[1] == Vec3(4, 5, 6));
                CHECK(data.positions[2] == Vec3(-150, 2, 0.5));
                REQUIRE(data.texcoords.size() == 3);
                CHECK(data.texcoords[0] == rb::Vec2(0.5, 0.0));
                CHECK(data.texcoords[1] == rb::Vec2(0.25, 0.75));
                CHECK(data.texcoords[2] == rb::Vec2(0.1, 0.2));
            }
        }
    }
}

//! [obj-fan]
SCENARIO("an n-sided polygon is fan-triangulated into n-2 triangles", "[ch03]") {
    GIVEN("a hexagon 'f 1 2 3 4 5 6'") {
        const std::string text =
            "v 1 0 0\nv 0.5 0.866 0\nv -0.5 0.866 0\n"
            "v -1 0 0\nv -0.5 -0.866 0\nv 0.5 -0.866 0\n"
            "f 1 2 3 4 5 6\n";
        WHEN("it is parsed") {
            const ObjData data = parseText(text);
            THEN("it becomes 6-2 = 4 triangles (0,i,i+1) around the first corner") {
                REQUIRE(data.triangles.size() == 4);
                for (int i = 0; i < 4; ++i) {
                    CHECK(data.triangles[i][0].v == 0);
                    CHECK(data.triangles[i][1].v == i + 1);
                    CHECK(data.triangles[i][2].v == i + 2);
                }
            }
        }
    }
    GIVEN("polygons of 3 to 10 corners") {
        for (int n = 3; n <= 10; ++n) {
            std::string text;
            for (int i = 0; i < n; ++i) {
                text += "v " + std::to_string(std::cos(i * 0.5)) + " " +
                        std::to_string(std::sin(i * 0.5)) + " 0\n";
            }
            text += "f";
            for (int i = 1; i <= n; ++i) text += " " + std::to_string(i);
            text += "\n";
            WHEN("a polygon of " + std::to_string(n) + " corners is parsed") {
                THEN("it gives n-2 triangles") {
                    CHECK(parseText(text).triangles.size() == static_cast<std::size_t>(n - 2));
                }
            }
        }
    }
}
//! [obj-fan]

SCENARIO("negative indices count back from the last element defined so far", "[ch03]") {
    GIVEN("'f -3 -2 -1' after three vertices, then again after a fourth") {
        const std::string text = threeVertices +
                                 "vt 0 0\nvn 0 0 1\n"
                                 "f -3/-1/-1 -2/-1/-1 -1/-1/-1\n"
                                 "v 1 1 0\n"
                                 "f -3 -2 -1\n";
        WHEN("it is parsed") {
            const ObjData data = parseText(text);
            THEN("-1 means the latest vertex at the point where the face is written") {
                REQUIRE(data.triangles.size() == 2);
                CHECK(cornerIs(data.triangles[0][0], 0, 0, 0));
                CHECK(cornerIs(data.triangles[0][2], 2, 0, 0));
                CHECK(cornerIs(data.triangles[1][0], 1, -1, -1));
                CHECK(cornerIs(data.triangles[1][2], 3, -1, -1));
            }
        }
    }
}

SCENARIO("grouping, smoothing, material, line and point statements are skipped", "[ch03]") {
    GIVEN("a file using o, g, s, usemtl, mtllib, l, p and vp") {
        const std::string text =
            "mtllib scene.mtl\n"
            "o Triangle\n"
            "g group1 group2\n"
            "s off\n"
            "s 1\n"
            "usemtl red\n" +
            threeVertices +
            "vp 0.5 0.5\n"
            "l 1 2\n"
            "p 3\n"
            "f 1 2 3\n";
        WHEN("it is parsed") {
            const ObjData data = parseText(text);
            THEN("only the vertices and the face remain") {
                CHECK(data.positions.size() == 3);
                CHECK(data.texcoords.empty());
                CHECK(data.normals.empty());
                CHECK(data.triangles.size() == 1);
            }
        }
    }
}

SCENARIO("comments, blank lines, tabs and CRLF line endings are tolerated", "[ch03][stability]") {
    GIVEN("a Windows-style file with comments, indentation and trailing comments") {
        const std::string text =
            "# exported by some tool\r\n"
            "\r\n"
            "   v 0 0 0   # origin\r\n"
            "\tv\t1\t0\t0\r\n"
            "v 0 1 0#no space before the comment\r\n"
            "   \t \r\n"
            "f 1 2 3 \t# the only face\r\n"
            "#f 9 9 9\n";
        WHEN("it is parsed") {
            const ObjData data = parseText(text);
            THEN("it reads exactly like the clean version") {
                REQUIRE(data.positions.size() == 3);
                CHECK(data.positions[2] == Vec3(0, 1, 0));
                REQUIRE(data.triangles.size() == 1);
                CHECK(cornerIs(data.triangles[0][2], 2, -1, -1));
            }
        }
        WHEN("an error comes after CRLF lines") {
            THEN("the line number still counts every line") {
                REQUIRE_THROWS_WITH(parseText("v 0 0 0\r\n\r\nv 1 2\r\n"), StartsWith("x.obj:3: "));
            }
        }
    }
}

SCENARIO("the course's quad cube cubeSq.obj reads as 12 triangles", "[ch03]") {
    GIVEN("a unit cube written course-style: 8 vertices and 6 'f a b c d' quads") {
        // The faces wind counter-clockwise seen from outside, as in the course's cubeSq.obj
        const std::string cubeSq =
            "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
            "v 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
            "f 1 4 3 2\n"
            "f 5 6 7 8\n"
            "f 1 2 6 5\n"
            "f 4 8 7 3\n"
            "f 1 5 8 4\n"
            "f 2 3 7 6\n";
        WHEN("it is parsed") {
            const ObjData data = parseText(cubeSq, "cubeSq.obj");
            THEN("6 quads give 12 triangles that close the cube with outward normals") {
                REQUIRE(data.positions.size() == 8);
                REQUIRE(data.triangles.size() == 12);

                double area = 0.0, volume = 0.0;
                int outwardFacing = 0;
                const Vec3 centre(0.5, 0.5, 0.5);
                for (const auto& t : data.triangles) {
                    const Vec3 p0 = data.positions[t[0].v];
                    const Vec3 p1 = data.positions[t[1].v];
                    const Vec3 p2 = data.positions[t[2].v];
                    const Vec3 n = glm::cross(p1 - p0, p2 - p0);
                    area += 0.5 * glm::length(n);
                    volume += glm::dot(p0, glm::cross(p1, p2)) / 6.0;
                    if (glm::dot(n, (p0 + p1 + p2) / 3.0 - centre) > 0.0) ++outwardFacing;
                }
                // Source: a unit cube has surface area 6 and volume 1; the volume is the sum of
                // signed tetrahedra p0·(p1×p2)/6 over a closed, consistently wound surface
                // (divergence theorem), so it is 1 only if the fans kept every quad's winding.
                CHECK(area == Approx(6.0));
                CHECK(volume == Approx(1.0));
                CHECK(outwardFacing == 12);
            }
        }
    }
}

//! [obj-errors]
SCENARIO("every malformed line is an InputError naming the file and the line",
         "[ch03][stability]") {
    GIVEN("a 'v' line with too few numbers on line 3") {
        const std::string text = "v 0 0 0\nv 1 0 0\nv 1 2\nf 1 2 3\n";
        THEN("the error says how many numbers were expected and found") {
            REQUIRE_THROWS_AS(parseText(text), InputError);
            REQUIRE_THROWS_WITH(parseText(text),
                                Contains("x.obj:3: expected 3 numbers after 'v', got 2"));
        }
    }
    GIVEN("a coordinate that is NaN or infinite on line 4") {
        const std::string prefix = threeVertices;
        THEN("the bad token is named as not finite") {
            REQUIRE_THROWS_WITH(parseText(prefix + "v 0 nan 0\n"),
                                Contains("x.obj:4: 'nan' is not a finite number"));
            REQUIRE_THROWS_WITH(parseText(prefix + "vn inf 0 0\n"),
                                Contains("x.obj:4: 'inf' is not a finite number"));
            // Source: 1e400 exceeds DBL_MAX (about 1.8e308), so it would read as infinity
            REQUIRE_THROWS_WITH(parseText(prefix + "vt 1e400\n"),
                                Contains("x.obj:4: '1e400' is not a finite number"));
        }
    }
    GIVEN("a vertex coordinate of 1e39, finite in double, on line 4") {
        const std::string prefix = threeVertices;
        THEN("it is named as beyond the range of the float vertices a mesh keeps") {
            // Source: FLT_MAX is (2 − 2⁻²³)·2¹²⁷ ≈ 3.40e38, so 1e39 rounds to infinity in float.
            REQUIRE_THROWS_WITH(parseText(prefix + "v 0 1e39 0\n"),
                                Contains("x.obj:4: '1e39' is beyond a float's range"));
            // 3e38 fits, and a texture coordinate is not a vertex.
            REQUIRE_NOTHROW(parseText(prefix + "v 0 3e38 0\nvt 1e39\nf 1 2 3\n"));
        }
    }
    GIVEN("a coordinate that is not a number") {
        THEN("the bad token is quoted") {
            REQUIRE_THROWS_WITH(parseText("v 0 0 0\nv 1 O 0\n"),
                                Contains("x.obj:2: 'O' is not a number"));
            REQUIRE_THROWS_WITH(parseText("v 1,5 0 0\n"),
                                Contains("x.obj:1: '1,5' is not a number"));
        }
    }
    GIVEN("'vt' and 'vn' lines with the wrong number of values") {
        THEN("each error says what the statement takes") {
            REQUIRE_THROWS_WITH(parseText("vt\n"),
                                Contains("x.obj:1: expected 1 to 3 numbers after 'vt', got 0"));
            REQUIRE_THROWS_WITH(parseText("\nvn 0 1\n"),
                                Contains("x.obj:2: expected 3 numbers after 'vn', got 2"));
        }
    }
    GIVEN("an unknown statement keyword") {
        THEN("the keyword is named") {
            REQUIRE_THROWS_WITH(parseText(threeVertices + "face 1 2 3\n", "scene.obj"),
                                Contains("scene.obj:4: unknown statement 'face'"));
        }
    }
    GIVEN("a face with fewer than 3 corners") {
        THEN("the error asks for at least 3") {
            REQUIRE_THROWS_WITH(parseText(threeVertices + "f 1 2\n"),
                                Contains("x.obj:4: a face needs at least 3 corners, got 2"));
        }
    }
    GIVEN("a face using index 0, which OBJ never uses") {
        THEN("index 0 is rejected") {
            REQUIRE_THROWS_WITH(parseText(threeVertices + "f 0 1 2\n"),
                                Contains("x.obj:4: face index 0 is invalid"));
        }
    }
    GIVEN("face indices beyond the vertices defined so far") {
        THEN("the error gives the index and the count so far") {
            REQUIRE_THROWS_WITH(
                parseText(threeVertices + "f 1 2 912\n", "bunny.obj"),
                Contains("bunny.obj:4: face index 912 is out of range (the file has 3 "
                         "vertices so far)"));
            REQUIRE_THROWS_WITH(parseText(threeVertices + "f 1 2 -4\n"),
                                Contains("x.obj:4: face index -4 is out of range"));
            REQUIRE_THROWS_WITH(parseText(threeVertices + "vt 0 0\nf 1/2 2/1 3/1\n"),
                                Contains("x.obj:5: texture coordinate index 2 is out of range "
                                         "(the file has 1 texture coordinate so far)"));
            REQUIRE_THROWS_WITH(parseText(threeVertices + "f 1//1 2//1 3//1\n"),
                                Contains("x.obj:4: normal index 1 is out of range"));
        }
        THEN("a vertex defined after the face does not count (OBJ reads top to bottom)") {
            REQUIRE_THROWS_WITH(parseText("v 0 0 0\nv 1 0 0\nf 1 2 3\nv 0 1 0\n"),
                                Contains("x.obj:3: face index 3 is out of range"));
        }
    }
    GIVEN("face indices that are not integers") {
        THEN("the field and its corner are quoted") {
            REQUIRE_THROWS_WITH(parseText(threeVertices + "f 1 2 3.0\n"),
                                Contains("x.obj:4: face index '3.0' is not an integer"));
            REQUIRE_THROWS_WITH(
                parseText(threeVertices + "vt 0 0\nf 1/a 2/1 3/1\n"),
                Contains("x.obj:5: texture coordinate index 'a' in corner '1/a' is not "
                         "an integer"));
            REQUIRE_THROWS_WITH(parseText(threeVertices + "f 1 2 99999999999999999999\n"),
                                Contains("x.obj:4: face index '99999999999999999999' is out of "
                                         "range"));
        }
    }
    GIVEN("corners whose slashes do not match one of the four forms") {
        THEN("each is malformed") {
            for (const char* corner : {"1/", "/1", "1//", "1/1/", "//", "1/1/1/1"}) {
                const std::string text = threeVertices + "vt 0 0\nvn 0 0 1\nf 1 2 " + corner + "\n";
                CAPTURE(corner);
                REQUIRE_THROWS_AS(parseText(text), InputError);
                REQUIRE_THROWS_WITH(parseText(text), StartsWith("x.obj:6: corner '"));
            }
        }
    }
}
//! [obj-errors]

SCENARIO("a file without faces is an InputError", "[ch03][stability]") {
    GIVEN("an empty file, a file of comments, and a file of vertices only") {
        THEN("each says it has no faces") {
            for (const char* text : {"", "# nothing here\n\n", "v 0 0 0\nv 1 0 0\nv 0 1 0\n"}) {
                CAPTURE(text);
                REQUIRE_THROWS_AS(parseText(text, "empty.obj"), InputError);
                REQUIRE_THROWS_WITH(parseText(text, "empty.obj"),
                                    Contains("empty.obj: has no faces"));
            }
        }
    }
}

SCENARIO("a missing OBJ file is an InputError naming the path", "[ch03][stability]") {
    GIVEN("a path where no file exists") {
        const std::string path = "/nonexistent-raybook-dir/no-such-mesh.obj";
        WHEN("it is loaded") {
            THEN("the error names the path and the reason") {
                REQUIRE_THROWS_AS(rb::loadObj(path), InputError);
                REQUIRE_THROWS_WITH(rb::loadObj(path), Contains(path + ": cannot open OBJ file") &&
                                                           Contains("No such file or directory"));
            }
        }
    }
}

SCENARIO("garbage input never crashes the loader", "[ch03][stability]") {
    GIVEN("a few thousand random byte strings and randomly damaged OBJ files (fixed seed)") {
        const std::string valid = threeVertices +
                                  "vt 0 0\nvn 0 0 1\n"
                                  "f 1/1/1 2/1/1 3/1/1\n"
                                  "f -3//-1 -2//1 -1//1\n";
        const std::string alphabet = "vtnfgs/ -+0123456789.eE#\n\r\tnai";
        std::mt19937 rng(20240601);  // fixed seed: the same inputs on every run
        int parsed = 0, rejected = 0, badResults = 0, badMessages = 0, badLines = 0, noFaces = 0;

        WHEN("each is parsed") {
            for (int trial = 0; trial < 3000; ++trial) {
                // Make an input: random bytes, random OBJ-ish characters, or a damaged valid file
                std::string text;
                const unsigned length = rng() % 120;
                if (trial % 3 == 0) {
                    for (unsigned i = 0; i < length; ++i) text += static_cast<char>(rng() % 256);
                } else if (trial % 3 == 1) {
                    for (unsigned i = 0; i < length; ++i) text += alphabet[rng() % alphabet.size()];
                } else {
                    text = valid;
                    for (int edits = 1 + rng() % 4; edits > 0; --edits) {
                        text[rng() % text.size()] = static_cast<char>(rng() % 256);
                    }
                }

                // Either a well-formed result or an InputError with a clean message
                try {
                    const ObjData data = parseText(text, "fuzz.obj");
                    ++parsed;
                    if (!allIndicesValid(data)) ++badResults;
                    if (data.triangles.empty()) ++noFaces;  // the loader must reject those
                } catch (const InputError& e) {
                    ++rejected;
                    const std::string message = e.what();
                    bool printable = message.rfind("fuzz.obj:", 0) == 0;
                    for (unsigned char c : message) printable = printable && c >= 0x20 && c < 0x7f;
                    if (!printable) ++badMessages;
                    // The message names a line of this input ("fuzz.obj:N: ..." with 1 <= N <=
                    // the number of lines), or is the one whole-file error, "has no faces".
                    const long lines = 1 + std::count(text.begin(), text.end(), '\n');
                    const std::string rest = message.substr(std::min(message.size(), std::size_t{9}));
                    if (rest.rfind(" has no faces", 0) != 0) {
                        char* end = nullptr;
                        const long n = std::strtol(rest.c_str(), &end, 10);
                        if (end == rest.c_str() || *end != ':' || n < 1 || n > lines) ++badLines;
                    }
                }
            }
            THEN("every input parses to valid indices or is rejected with a printable message naming a real line") {
                CHECK(badResults == 0);
                CHECK(badMessages == 0);
                // Every rejection points at a line that exists, and nothing without a face parses
                CHECK(badLines == 0);
                CHECK(noFaces == 0);
                // Both outcomes must occur, or one of the checks above is idle
                CHECK(parsed > 0);
                CHECK(rejected > 0);
            }
        }
    }
}

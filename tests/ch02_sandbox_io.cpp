/// \file
/// Chapter 2 tests: the sandbox's read-only io, which lets pre-2015 course scenes read their
/// OBJ files the way the course's readobj.lua did.
///
/// This file claims that a sandboxed scene can io.open a file beside it (or in an --assets
/// folder) with mode "r" or "rb", iterate it with file:lines() or io.lines(), and read it with
/// the formats "l", "L", "n", "a" and a byte count (and Lua 5.1's "*l", "*n", "*a"), so that a
/// readobj-style helper built on io.open, file:lines() and string.gfind turns an OBJ file into
/// the legacy gr.mesh(name, vertices, faces) form; that a missing file gives nil and a message,
/// as in plain Lua; and that everything beyond reading those folders is refused with an error
/// naming the scene's file and line and the folders that may be read: a path that leads out
/// ("../x", an absolute path, a symlink to outside), a write mode, and the rest of io
/// (io.popen, io.write, io.stdout, file:write). Reading a file larger than the Lua memory
/// limit ends in the memory-limit error, not a crash. The tests write scenes, data files and
/// symlinks into temporary folders and run them through rb::loadScene.
#include <catch2/catch.hpp>
#include <filesystem>
#include <string>

#include "bvh/mesh.h"
#include "core/error.h"
#include "scene/lua_scene.h"
#include "test_helpers.h"

using Catch::Contains;
using rbtest::renderLine;

namespace fs = std::filesystem;

namespace {

/// A scene folder inside a temporary folder, with room for files outside it:
///   root/scene/   the scene and the files it may read
///   root/         files the scene must not read
struct SceneFolder {
    rbtest::TempDir root;
    fs::path dir = root.path() / "scene";

    SceneFolder() { fs::create_directories(dir); }
    /// Write a file under the scene folder; returns its path.
    std::string write(const std::string& name, const std::string& text) const {
        return root.write("scene/" + name, text);
    }
    /// Write a file outside the scene folder (in root); returns its path.
    std::string writeOutside(const std::string& name, const std::string& text) const {
        return root.write(name, text);
    }
    /// Run `lua` as root/scene/scene.lua with chapters 1 to 3.
    std::vector<rb::LoadedRender> load(const std::string& lua,
                                       const rb::SceneLoadOptions& options = {}) const {
        return rb::loadScene(write("scene.lua", lua), rbtest::chapters(3), options);
    }
    /// The InputError message of load(lua), or "" when it loads.
    std::string error(const std::string& lua, const rb::SceneLoadOptions& options = {}) const {
        try {
            load(lua, options);
        } catch (const rb::InputError& e) {
            return e.what();
        }
        return "";
    }
};

/// An OBJ reader in the manner of the course's pre-2015 readobj.lua, in our own words: open the
/// file with io.open, walk its lines with file:lines(), split each into words with
/// string.gfind, and keep "v" lines as vertices and "f" lines as faces whose corners (v, v/vt,
/// v//vn or v/vt/vn) become 0-based vertex indices, the form the legacy gr.mesh takes.
const char* const kReadObj = R"(
function read_obj(name)
  local file = io.open(name, 'r')
  if not file then error('read_obj: cannot open ' .. name) end
  local vertices, faces = {}, {}
  for line in file:lines() do
    local words = {}
    for word in string.gfind(line, '%S+') do words[#words + 1] = word end
    if words[1] == 'v' then
      vertices[#vertices + 1] = {tonumber(words[2]), tonumber(words[3]), tonumber(words[4])}
    elseif words[1] == 'f' then
      local face = {}
      for k = 2, #words do
        local index = tonumber((string.gsub(words[k], '/.*', '')))
        face[#face + 1] = index - 1
      end
      faces[#faces + 1] = face
    end
  end
  file:close()
  return vertices, faces
end
)";

/// A unit square (one quad) and a triangle beside it, with comments, a normal and corners
/// written v, v/vt and v//vn: three triangles once the quad is split.
const char* const kSquareAndTriangle =
    "# a square and a triangle\n"
    "v 0 0 0\n"
    "v 1 0 0\n"
    "v 1 1 0\n"
    "v 0 1 0\n"
    "v 2 0 0\n"
    "vn 0 0 1\n"
    "f 1 2 3 4\n"
    "f 2/1 5//1 3\n";

/// The scene's lines: `body` on line 1, then a render call.
std::string oneLine(const std::string& body) {
    return body + "\nroot = gr.node('root')\n" + renderLine();
}

}  // namespace

// ---- Reading OBJ files the old way ----------------------------------------------------------

// [ch02-sandbox-readobj]
SCENARIO("a readobj-style helper reads an OBJ beside the scene with io.open and file:lines",
         "[ch02][ex2.2]") {
    GIVEN("square.obj (a quad and a triangle) beside a scene that reads it with read_obj") {
        SceneFolder folder;
        folder.write("square.obj", kSquareAndTriangle);
        const std::string lua = std::string(kReadObj) +
                                "local mesh = gr.mesh('square', read_obj('square.obj'))\n"
                                "root = gr.node('root')\n"
                                "root:add_child(mesh)\n" +
                                renderLine();
        WHEN("the scene is loaded in the sandbox") {
            const auto renders = folder.load(lua);
            THEN("the mesh holds the three triangles of the quad and the triangle") {
                REQUIRE(renders.size() == 1);
                REQUIRE(renders[0].instances.size() == 1);
                const auto* mesh = dynamic_cast<const rb::Mesh*>(renders[0].instances[0].shape);
                REQUIRE(mesh != nullptr);
                CHECK(mesh->triangleCount() == 3);
            }
        }
    }
    GIVEN("the same OBJ in an --assets folder, outside the scene's folder") {
        SceneFolder folder;
        fs::create_directories(folder.root.path() / "assets");
        folder.writeOutside("assets/square.obj", kSquareAndTriangle);
        rb::SceneLoadOptions options;
        options.assetDirs = {(folder.root.path() / "assets").string()};
        THEN("read_obj finds it by name, as gr.mesh would") {
            const auto renders =
                folder.load(std::string(kReadObj) +
                                "local mesh = gr.mesh('square', read_obj('square.obj'))\n"
                                "root = gr.node('root')\nroot:add_child(mesh)\n" +
                                renderLine(),
                            options);
            const auto* mesh = dynamic_cast<const rb::Mesh*>(renders.at(0).instances.at(0).shape);
            REQUIRE(mesh != nullptr);
            CHECK(mesh->triangleCount() == 3);
        }
    }
}
// [ch02-sandbox-readobj]

// ---- Read formats -----------------------------------------------------------------------

SCENARIO("file:read understands Lua 5.4's formats and Lua 5.1's spellings of them", "[ch02]") {
    GIVEN("a text file with lines, numbers and a tail without a newline") {
        SceneFolder folder;
        folder.write("data.txt", "first line\nsecond\n  42  3.5e1 0x10 -7\nrest\nof it");
        WHEN("a scene reads it with each format in turn (assert stops the load on a mismatch)") {
            const std::string message = folder.error(
                oneLine("local f = assert(io.open('data.txt'))\n"
                        "assert(io.type(f) == 'file')\n"
                        "assert(f:read() == 'first line', 'no format means l')\n"
                        "assert(f:read('L') == 'second\\n', 'L keeps the newline')\n"
                        "local a, b, c = f:read('n', '*n', 'n')\n"
                        "assert(a == 42 and math.type(a) == 'integer', 'n reads an integer')\n"
                        "assert(b == 35.0 and math.type(b) == 'float', '*n reads a float')\n"
                        "assert(c == 16, 'n reads hexadecimal')\n"
                        "assert(f:read('n') == -7, 'n reads a sign')\n"
                        "assert(f:read('*l') == '', '*l reads the rest of the line')\n"
                        "assert(f:read('n') == nil, 'n fails on a word')\n"
                        "assert(f:read(3) == 'res', 'a count reads that many bytes')\n"
                        "assert(f:read(0) == '', 'a count of 0 is empty before the end')\n"
                        "assert(f:read('l') == 't', 'l reads the rest of the line')\n"
                        "assert(f:read('*a') == 'of it', '*a reads the rest')\n"
                        "assert(f:read('a') == '', 'a at the end is empty')\n"
                        "assert(f:read('l') == nil, 'l at the end is nil')\n"
                        "assert(f:read(0) == nil, 'a count of 0 at the end is nil')\n"
                        "assert(f:close() == true)\n"
                        "assert(io.type(f) == 'closed file')\n"
                        "assert(io.type(42) == nil)\n"));
            THEN("every read returns what Lua's own io would") {
                CHECK(message == "");
            }
        }
        WHEN("a scene counts its lines with io.lines, file:lines and a to-be-closed file") {
            const std::string message = folder.error(oneLine(
                "local n = 0\n"
                "for line in io.lines('data.txt') do n = n + 1 end\n"
                "assert(n == 5, 'io.lines: ' .. n)\n"
                "local words = {}\n"
                "for a, b in io.lines('data.txt', 1, 'l') do words[#words + 1] = a .. '|' .. b "
                "end\n"
                "assert(words[1] == 'f|irst line' and #words == 5, 'io.lines with formats')\n"
                "do\n"
                "  local f <close> = assert(io.open('data.txt', 'rb'))\n"
                "  local m = 0\n"
                "  for line in f:lines('L') do m = m + 1 end\n"
                "  assert(m == 5 and io.type(f) == 'file', 'file:lines leaves it open')\n"
                "  g = f\n"
                "end\n"
                "assert(io.type(g) == 'closed file', '<close> closes it')\n"));
            THEN("each sees five lines") {
                CHECK(message == "");
            }
        }
        WHEN("a scene reads a file it has closed") {
            const std::string message =
                folder.error(oneLine("local f = io.open('data.txt') f:close() f:read()"));
            THEN("it is an error at that line") {
                CHECK_THAT(message, Contains("scene.lua:1:"));
                CHECK_THAT(message, Contains("closed file"));
            }
        }
    }
}

SCENARIO("a missing file gives nil and a message, as Lua's io.open does", "[ch02]") {
    GIVEN("a scene folder without nope.obj") {
        SceneFolder folder;
        THEN("io.open returns nil, 'nope.obj: No such file or directory' and 2") {
            CHECK(folder.error(
                      oneLine("local f, message, code = io.open('nope.obj')\n"
                              "assert(f == nil)\n"
                              "assert(message == 'nope.obj: No such file or directory', message)\n"
                              "assert(code == 2)\n")) == "");
        }
        THEN("io.lines raises that message at the line of the call") {
            const std::string message =
                folder.error(oneLine("for l in io.lines('nope.obj') do end"));
            CHECK_THAT(message, Contains("scene.lua:1:"));
            CHECK_THAT(message, Contains("nope.obj: No such file or directory"));
        }
    }
}

// ---- What the sandbox refuses -------------------------------------------------------------

SCENARIO("io reads only under the scene's folder and the --assets folders", "[ch02]") {
    GIVEN("secret.txt beside the scene's folder, and symlinks inside it that lead out") {
        SceneFolder folder;
        const std::string secret = folder.writeOutside("secret.txt", "secret\n");
        folder.write("data.txt", "inside\n");
        fs::create_symlink(secret, folder.dir / "link.txt");
        fs::create_directory_symlink(folder.root.path(), folder.dir / "up");
        fs::create_symlink(folder.dir / "data.txt", folder.dir / "alias.txt");
        const std::string calls[] = {
            "io.open('../secret.txt')",       "io.open('" + secret + "')",
            "io.open('/etc/passwd')",         "io.open('link.txt')",
            "io.open('up/secret.txt')",       "io.open('sub/../../secret.txt')",
            "io.open('../no-such-file.txt')", "io.lines('../secret.txt')",
        };
        THEN("each way out is refused at its line, naming the file and the allowed folder") {
            const std::string allowed = fs::canonical(folder.dir).string();
            for (const std::string& call : calls) {
                CAPTURE(call);
                const std::string message = folder.error(oneLine("local f = " + call));
                CAPTURE(message);
                CHECK_THAT(message, Contains("scene.lua:1:"));
                CHECK_THAT(message, Contains("cannot read"));
                CHECK_THAT(message, Contains("raybook's sandbox reads only files under"));
                CHECK_THAT(message, Contains("the scene's folder " + allowed));
                CHECK_THAT(message, Contains("--unsafe-lua"));
            }
        }
        THEN("the symlink's message says where it leads") {
            const std::string message = folder.error(oneLine("local f = io.open('link.txt')"));
            CHECK_THAT(message, Contains("'link.txt' (" + fs::canonical(secret).string() + ")"));
        }
        THEN("a symlink that stays inside, and the file's absolute path, are readable") {
            const std::string absolute = fs::canonical(folder.dir / "data.txt").string();
            CHECK(folder.error(
                      oneLine("assert(io.open('alias.txt'):read() == 'inside')\n"
                              "assert(io.open('" +
                              absolute +
                              "'):read() == 'inside')\n"
                              "assert(io.open('./up/scene/data.txt'):read() == 'inside')")) == "");
        }
        WHEN("root is given as an --assets folder") {
            rb::SceneLoadOptions options;
            options.assetDirs = {folder.root.path().string()};
            THEN("its files may be read, and the refusals name it") {
                CHECK(folder.error(oneLine("assert(io.open('secret.txt'):read() == 'secret')\n"
                                           "assert(io.open('../secret.txt'):read() == 'secret')"),
                                   options) == "");
                const std::string message =
                    folder.error(oneLine("local f = io.open('/etc/passwd')"), options);
                CHECK_THAT(message, Contains("--assets folder " +
                                             fs::canonical(folder.root.path()).string()));
            }
        }
    }
}

SCENARIO("io opens files for reading only, and leaves out the rest of Lua's io", "[ch02]") {
    GIVEN("a scene folder with data.txt") {
        SceneFolder folder;
        folder.write("data.txt", "inside\n");
        THEN("every write mode is refused at its line, and no file is made") {
            for (const char* mode : {"w", "a", "r+", "w+", "a+", "wb", "rw", "x"}) {
                CAPTURE(mode);
                const std::string message = folder.error(
                    oneLine(std::string("local f = io.open('out.txt', '") + mode + "')"));
                CAPTURE(message);
                CHECK_THAT(message, Contains("scene.lua:1:"));
                CHECK_THAT(message, Contains("io.open('out.txt', '" + std::string(mode) + "')"));
                CHECK_THAT(message, Contains("reading only (mode 'r' or 'rb')"));
                CHECK_FALSE(fs::exists(folder.dir / "out.txt"));
            }
        }
        THEN("io.popen, io.write, io.stdout and the rest say they are left out, and why") {
            for (const char* name : {"popen", "write", "output", "input", "read", "tmpfile",
                                     "stdout", "stderr", "stdin", "flush"}) {
                CAPTURE(name);
                const std::string message =
                    folder.error(oneLine(std::string("local x = io.") + name));
                CHECK_THAT(message, Contains("scene.lua:1:"));
                CHECK_THAT(message, Contains(std::string("io.") + name +
                                             " is not available in raybook's sandbox"));
                CHECK_THAT(message, Contains("read-only"));
                CHECK_THAT(message, Contains("--unsafe-lua"));
            }
        }
        THEN("file:write and the other writing methods are left out too") {
            for (const char* method : {"write", "flush", "seek", "setvbuf"}) {
                CAPTURE(method);
                const std::string message = folder.error(
                    oneLine(std::string("local f = io.open('data.txt') f:") + method + "('x')"));
                CHECK_THAT(message, Contains("scene.lua:1:"));
                CHECK_THAT(message, Contains(std::string("file:") + method +
                                             " is not available in raybook's sandbox"));
            }
        }
        THEN("io.lines() and io.close() without a file (standard input and output) are refused") {
            CHECK_THAT(folder.error(oneLine("for l in io.lines() do end")),
                       Contains("standard input"));
            CHECK_THAT(folder.error(oneLine("io.close()")), Contains("standard output"));
        }
        THEN("with --unsafe-lua, io is Lua's own") {
            rb::SceneLoadOptions options;
            options.unsafeLua = true;
            CHECK(folder.error(oneLine("assert(type(io.write) == 'function')"), options) == "");
        }
    }
}

// ---- Limits -------------------------------------------------------------------------------

SCENARIO("reading a file larger than the memory limit ends in the memory-limit error", "[ch02]") {
    GIVEN("a 24 MiB file and a memory limit of 8 MiB") {
        SceneFolder folder;
        folder.write("big.txt", std::string(size_t(24) << 20, 'x'));
        rb::SceneLoadOptions options;
        options.memoryLimit = size_t(8) << 20;
        THEN("file:read('a') stops with the memory-limit error") {
            CHECK_THAT(folder.error(oneLine("local s = io.open('big.txt'):read('a')"), options),
                       Contains("exceeded the memory limit"));
        }
        THEN("so does one line that long, and a byte count that large") {
            CHECK_THAT(folder.error(oneLine("local s = io.open('big.txt'):read('l')"), options),
                       Contains("exceeded the memory limit"));
            CHECK_THAT(folder.error(oneLine("local s = io.open('big.txt'):read(1 << 40)"), options),
                       Contains("exceeded the memory limit"));
        }
        THEN("reading it a little at a time stays within the limit") {
            CHECK(folder.error(oneLine("local f = io.open('big.txt')\n"
                                       "local n = 0\n"
                                       "while true do\n"
                                       "  local s = f:read(65536)\n"
                                       "  if not s then break end\n"
                                       "  n = n + #s\n"
                                       "end\n"
                                       "assert(n == 24 << 20, n)"),
                               options) == "");
        }
    }
}

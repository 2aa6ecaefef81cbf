/// \file
/// The Wavefront OBJ reader. One pass over the lines: split each into tokens, then dispatch on the
/// statement keyword. Numbers are read with std::from_chars, which is locale-independent and fast
/// enough for meshes of a few hundred thousand triangles.
#include "bvh/obj.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string_view>
#include <system_error>

#include "core/error.h"
#include "core/from_chars.h"

namespace rb {
namespace {

/// True for the characters OBJ treats as space between tokens ('\r' covers CRLF files).
bool isObjSpace(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

/// A token made safe to quote in an error message: non-printing bytes become '?', and long
/// tokens are shortened, so garbage input cannot produce a garbage message.
std::string quoted(std::string_view token) {
    constexpr std::size_t maxShown = 40;
    std::string out = "'";
    for (std::size_t i = 0; i < token.size() && i < maxShown; ++i) {
        const unsigned char c = static_cast<unsigned char>(token[i]);
        out += (c >= 0x20 && c < 0x7f) ? static_cast<char>(c) : '?';
    }
    if (token.size() > maxShown) out += "...";
    return out + "'";
}

/// "1 vertex" or "3 vertices": a count with the right form of the noun.
std::string countOf(std::size_t n, const char* singular, const char* plural) {
    return std::to_string(n) + " " + (n == 1 ? singular : plural);
}

/// Where we are in the file, for error messages.
struct LineContext {
    const std::string& displayName;  ///< The file name shown to the user.
    long lineNumber = 0;             ///< One-based number of the current line.

    /// Throw an InputError "name:line: what".
    [[noreturn]] void fail(const std::string& what) const {
        throw InputError(displayName + ":" + std::to_string(lineNumber) + ": " + what);
    }
};

/// Split a line into whitespace-separated tokens, dropping a trailing `#` comment.
void splitTokens(std::string_view line, std::vector<std::string_view>& tokens) {
    tokens.clear();
    if (const std::size_t hash = line.find('#'); hash != std::string_view::npos) {
        line = line.substr(0, hash);
    }
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && isObjSpace(line[i])) ++i;
        const std::size_t start = i;
        while (i < line.size() && !isObjSpace(line[i])) ++i;
        if (i > start) tokens.push_back(line.substr(start, i - start));
    }
}

/// Read one finite floating-point number that fills the whole token.
double parseNumber(std::string_view token, const LineContext& ctx) {
    // from_chars rejects a leading '+', which some exporters write
    std::string_view digits = token;
    if (digits.size() > 1 && digits[0] == '+' && digits[1] != '-' && digits[1] != '+') {
        digits.remove_prefix(1);
    }
    double value = 0.0;
    const char* first = digits.data();
    const char* last = digits.data() + digits.size();
    const auto [ptr, ec] = rb::fromChars(first, last, value);
    if (ptr != last || ec == std::errc::invalid_argument) {
        ctx.fail(quoted(token) + " is not a number");
    }
    if (ec == std::errc::result_out_of_range) {
        // from_chars reports underflow and overflow alike; strtod tells them apart (an
        // underflow such as 1e-400 is harmlessly 0, an overflow is an error below)
        value = std::strtod(std::string(digits).c_str(), nullptr);
    }
    if (!std::isfinite(value)) {
        ctx.fail(quoted(token) + " is not a finite number");
    }
    return value;
}

/// Read a statement's numbers into values; returns how many the line had.
std::size_t parseNumbers(const std::vector<std::string_view>& tokens, double* values,
                         std::size_t maxCount, const LineContext& ctx) {
    const std::size_t count = tokens.size() - 1;
    for (std::size_t i = 0; i < count && i < maxCount; ++i) {
        values[i] = parseNumber(tokens[i + 1], ctx);
    }
    return count;
}

/// What a face index refers to, for resolving it and for error messages.
struct IndexKind {
    const char* name;      ///< "face index", "texture coordinate index", ...
    const char* singular;  ///< "vertex", "texture coordinate", ...
    const char* plural;    ///< "vertices", "texture coordinates", ...
};

constexpr IndexKind positionIndex{"face index", "vertex", "vertices"};
constexpr IndexKind texcoordIndex{"texture coordinate index", "texture coordinate",
                                  "texture coordinates"};
constexpr IndexKind normalIndex{"normal index", "normal", "normals"};

/// Turn one OBJ index (1-based, or negative = relative to the end) into a 0-based index into an
/// array that currently holds `count` entries.
int resolveIndex(std::string_view text, std::string_view corner, const IndexKind& kind,
                 std::size_t count, const LineContext& ctx) {
    // Parse the integer; it must fill the whole field
    long long index = 0;
    const char* last = text.data() + text.size();
    const auto [ptr, ec] = rb::fromChars(text.data(), last, index);
    if (text.empty() || ptr != last || ec == std::errc::invalid_argument) {
        // Name the corner too when the field is only part of it ("1/a/2")
        const std::string where = text == corner ? "" : " in corner " + quoted(corner);
        ctx.fail(std::string(kind.name) + " " + quoted(text) + where + " is not an integer");
    }
    const std::string have =
        "(the file has " + countOf(count, kind.singular, kind.plural) + " so far)";
    if (ec == std::errc::result_out_of_range) {
        ctx.fail(std::string(kind.name) + " " + quoted(text) + " is out of range " + have);
    }

    // Index 0 means nothing in OBJ: positive indices count from 1, negative ones from the end
    if (index == 0) {
        ctx.fail(std::string(kind.name) +
                 " 0 is invalid (OBJ indices start at 1; -1 means the last one defined)");
    }
    const long long n = static_cast<long long>(count);
    const long long resolved = index > 0 ? index - 1 : n + index;
    if (resolved < 0 || resolved >= n) {
        ctx.fail(std::string(kind.name) + " " + std::to_string(index) + " is out of range " + have);
    }
    return static_cast<int>(resolved);
}

/// Parse one face corner `v`, `v/vt`, `v//vn` or `v/vt/vn` against the arrays read so far.
ObjCorner parseCorner(std::string_view token, const ObjData& data, const LineContext& ctx) {
    // Split at the slashes into at most three fields
    std::string_view fields[3];
    std::size_t fieldCount = 0;
    std::size_t start = 0;
    for (;;) {
        const std::size_t slash = token.find('/', start);
        if (fieldCount == 3) {
            ctx.fail("corner " + quoted(token) +
                     " has too many '/' (expected v, v/vt, v//vn or v/vt/vn)");
        }
        fields[fieldCount++] = token.substr(
            start, slash == std::string_view::npos ? std::string_view::npos : slash - start);
        if (slash == std::string_view::npos) break;
        start = slash + 1;
    }

    // Check the shape: v is required, a written '/' must be followed by an index
    const bool shapeOk = !fields[0].empty() &&
                         (fieldCount < 2 || !fields[1].empty() || fieldCount == 3) &&
                         (fieldCount < 3 || !fields[2].empty());
    if (!shapeOk) {
        ctx.fail("corner " + quoted(token) + " is malformed (expected v, v/vt, v//vn or v/vt/vn)");
    }

    // Resolve each index against what the file has defined so far
    ObjCorner corner;
    corner.v = resolveIndex(fields[0], token, positionIndex, data.positions.size(), ctx);
    if (fieldCount >= 2 && !fields[1].empty()) {
        corner.vt = resolveIndex(fields[1], token, texcoordIndex, data.texcoords.size(), ctx);
    }
    if (fieldCount == 3) {
        corner.vn = resolveIndex(fields[2], token, normalIndex, data.normals.size(), ctx);
    }
    return corner;
}

/// True for statements we read past: grouping, smoothing, materials, lines, points and
/// free-form parameter vertices do not change a triangle mesh.
bool isSkippedStatement(std::string_view keyword) {
    return keyword == "o" || keyword == "g" || keyword == "s" || keyword == "usemtl" ||
           keyword == "mtllib" || keyword == "l" || keyword == "p" || keyword == "vp";
}

/// Guard the int indices in ObjCorner: an array may not outgrow them.
void checkCapacity(std::size_t size, const char* what, const LineContext& ctx) {
    if (size >= static_cast<std::size_t>(INT_MAX)) {
        ctx.fail(std::string("too many ") + what + " (at most " + std::to_string(INT_MAX) +
                 " are supported)");
    }
}

/// Refuse the mesh once what it needs so far passes `free` bytes. Checked each time an array
/// doubles (from 4096 entries on), so the arrays never grow far past the budget: an OBJ with 50
/// million faces fails after reading the first few million.
class MeshBudgetCheck {
  public:
    MeshBudgetCheck(const MemoryBudget& budget) : budget_(budget), free_(budget.available()) {}

    /// Check `data` whenever its largest array has doubled since the last check, and always
    /// when `final`.
    void check(const ObjData& data, const LineContext& ctx, bool final = false) {
        const std::size_t size = std::max({data.positions.size(), data.texcoords.size(),
                                           data.normals.size(), data.triangles.size()});
        if (size < nextCheck_ && !final) return;
        nextCheck_ = 2 * size;
        const std::uint64_t bytes = meshLoadBytes(data);
        if (bytes > free_)
            throw InputError(budget_.refusal(
                bytes, free_, ctx.displayName + ":" + std::to_string(ctx.lineNumber),
                "the mesh read so far (" + countOf(data.triangles.size(), "triangle", "triangles") +
                    ", " + countOf(data.positions.size(), "vertex", "vertices") +
                    ") with its BVH"));
    }

  private:
    const MemoryBudget& budget_;
    std::uint64_t free_;
    std::size_t nextCheck_ = 4096;
};

}  // namespace

std::uint64_t meshLoadBytes(const ObjData& data) {
    const std::uint64_t vertices =
        data.positions.size() + data.texcoords.size() + data.normals.size();
    // A mesh with texture coordinates keeps three of them per triangle, with dp/du and dp/dv
    // (chapter 10): 96 bytes.
    const std::uint64_t texcoordBytes =
        data.texcoords.empty() ? 0 : saturatingProduct(data.triangles.size(), 96);
    return saturatingProduct(data.triangles.size(), kMeshBytesPerTriangle) +
           saturatingProduct(vertices, kMeshBytesPerVertex) + texcoordBytes;
}

ObjData parseObj(std::istream& in, const std::string& displayName, const MemoryBudget& budget) {
    ObjData data;
    LineContext ctx{displayName};
    MeshBudgetCheck memory(budget);
    std::string line;
    std::vector<std::string_view> tokens;
    std::vector<ObjCorner> polygon;
    double values[6];

    while (std::getline(in, line)) {
        ++ctx.lineNumber;
        splitTokens(line, tokens);
        if (tokens.empty()) continue;  // Blank line or comment
        const std::string_view keyword = tokens[0];

        if (keyword == "v") {
            // Position: x y z, optionally w (ignored) or an r g b vertex colour (ignored)
            const std::size_t n = parseNumbers(tokens, values, 6, ctx);
            if (n != 3 && n != 4 && n != 6) {
                ctx.fail("expected 3 numbers after 'v', got " + std::to_string(n) +
                         " (x y z, with an optional w or r g b colour)");
            }
            // A mesh keeps its vertices in float (mesh.h): a coordinate must fit in one.
            for (int axis = 0; axis < 3; ++axis)
                if (!std::isfinite(static_cast<float>(values[axis])))
                    ctx.fail(quoted(tokens[axis + 1]) +
                             " is beyond a float's range (about ±3.4e38), in which a mesh keeps"
                             " its vertices");
            checkCapacity(data.positions.size(), "vertices", ctx);
            data.positions.emplace_back(values[0], values[1], values[2]);
        } else if (keyword == "vt") {
            // Texture coordinate: u, optionally v (default 0) and w (ignored)
            values[1] = 0.0;
            const std::size_t n = parseNumbers(tokens, values, 3, ctx);
            if (n < 1 || n > 3) {
                ctx.fail("expected 1 to 3 numbers after 'vt', got " + std::to_string(n) +
                         " (u, with an optional v and w)");
            }
            checkCapacity(data.texcoords.size(), "texture coordinates", ctx);
            data.texcoords.emplace_back(values[0], values[1]);
        } else if (keyword == "vn") {
            // Normal: exactly x y z (it need not be unit length; the mesh normalises it)
            const std::size_t n = parseNumbers(tokens, values, 3, ctx);
            if (n != 3) {
                ctx.fail("expected 3 numbers after 'vn', got " + std::to_string(n) + " (x y z)");
            }
            checkCapacity(data.normals.size(), "normals", ctx);
            data.normals.emplace_back(values[0], values[1], values[2]);
        } else if (keyword == "f") {
            // [obj-face]
            // Read every corner first, so a bad corner anywhere rejects the whole face
            if (tokens.size() - 1 < 3) {
                ctx.fail("a face needs at least 3 corners, got " +
                         std::to_string(tokens.size() - 1));
            }
            polygon.clear();
            for (std::size_t i = 1; i < tokens.size(); ++i) {
                polygon.push_back(parseCorner(tokens[i], data, ctx));
            }

            // Fan-triangulate the polygon around its first corner: (0, i, i+1)
            for (std::size_t i = 1; i + 1 < polygon.size(); ++i) {
                data.triangles.push_back({polygon[0], polygon[i], polygon[i + 1]});
            }
            // [obj-face]
        } else if (!isSkippedStatement(keyword)) {
            ctx.fail("unknown statement " + quoted(keyword) +
                     " (expected v, vt, vn or f; o, g, s, usemtl, mtllib, l, p and vp are "
                     "skipped)");
        }
        memory.check(data, ctx);
    }

    // getline stops at end of file or on a read error; only the first is a success
    if (in.bad()) {
        throw InputError(displayName + ":" + std::to_string(ctx.lineNumber + 1) +
                         ": read error while reading the OBJ file");
    }
    memory.check(data, ctx, true);
    if (data.triangles.empty()) {
        throw InputError(displayName + ": has no faces (expected at least one 'f' line)");
    }
    return data;
}

ObjData loadObj(const std::string& path, const MemoryBudget& budget) {
    // A directory opens like a file on POSIX but cannot be read, so rule it out first
    std::error_code fsError;
    if (std::filesystem::is_directory(path, fsError)) {
        throw InputError(path + ": cannot open OBJ file (" + std::strerror(EISDIR) + ")");
    }

    errno = 0;
    std::ifstream file(path, std::ios::binary);
    if (!file) {
        // The failed open leaves the reason in errno (libstdc++ opens with fopen/open)
        const int reason = errno;
        throw InputError(path + ": cannot open OBJ file (" +
                         (reason != 0 ? std::strerror(reason) : "unknown reason") + ")");
    }
    return parseObj(file, path, budget);
}

}  // namespace rb

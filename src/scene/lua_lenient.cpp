// Names nobody defined and arguments a known call cannot read: the error that names the chapter
// a build lacks, or, under --lenient, a stand-in (a material of the call's colour, a point
// light at its position, the nearest shape raybook has, or an empty node) and a line in the
// list rt prints at the end.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <glm/gtc/matrix_transform.hpp>
#include <initializer_list>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/error.h"
#include "scene/lua_scene.h"
#include "scene/lua_types.h"

namespace rb {

namespace {

/// Calls of later chapters that also tell a scene's era, by their name alone. gr.cone and
/// gr.texture are not among them: raybook has forms of its own under the same names, so only a
/// built chapter, which sees the arguments, can tell seed 001's gr.cone(name) or seed 000's
/// gr.texture(material, file) from them.
struct EraCall {
    const char* name;
    Era era;
    const char* what;
};
constexpr EraCall kEraCalls[] = {
    {"cyllinder", Era::Legacy, "seed 001's gr.cyllinder"},
    {"csg", Era::Legacy, "seed 001's node:csg"},
    {"set_texture_map", Era::Modern, "seed 002's set_texture_map"},
    {"set_bump_map", Era::Modern, "seed 002's set_bump_map"},
};

/// True when `lower` (a call's name in lower case) contains any of `words`.
bool nameHas(const std::string& lower, std::initializer_list<const char*> words) {
    for (const char* w : words)
        if (lower.find(w) != std::string::npos) return true;
    return false;
}

/// The numbers of the table at `index` when it holds exactly 3 finite numbers (the value at
/// `field` of it instead, when `field` is given and the table has no list part).
bool readTriple(lua_State* L, int index, Vec3& out, const char* field = nullptr) {
    if (lua_type(L, index) != LUA_TTABLE) return false;
    index = lua_absindex(L, index);
    if (field) {
        // Raw access: a scene's metatables must not run inside a stand-in.
        lua_pushstring(L, field);
        lua_rawget(L, index);
        const bool ok = readTriple(L, -1, out);
        lua_pop(L, 1);
        return ok;
    }
    if (lua_rawlen(L, index) != 3) return false;
    double v[3];
    for (int i = 0; i < 3; ++i) {
        const bool number = lua_rawgeti(L, index, i + 1) == LUA_TNUMBER;
        v[i] = lua_tonumber(L, -1);
        lua_pop(L, 1);
        if (!number || !std::isfinite(v[i])) return false;
    }
    out = Vec3(v[0], v[1], v[2]);
    return true;
}

/// A colour a material can reflect: 3 numbers from 0 to 1.
bool colourLike(const Vec3& c) {
    return c.x >= 0.0 && c.y >= 0.0 && c.z >= 0.0 && c.x <= 1.0 && c.y <= 1.0 && c.z <= 1.0;
}

/// The first argument from `from` on that holds a triple passing `accept` (or a table with one
/// at a field named in `fields`); 0 when none does.
template <class Accept>
int findTriple(lua_State* L, int from, Vec3& out, Accept accept,
               std::initializer_list<const char*> fields = {}) {
    for (int arg = from; arg <= lua_gettop(L); ++arg) {
        if (readTriple(L, arg, out) && accept(out)) return arg;
        for (const char* f : fields)
            if (readTriple(L, arg, out, f) && accept(out)) return arg;
    }
    return 0;
}

/// "{0.8, 0.2, 0.2}": a triple as a scene writes it.
std::string tripleText(const Vec3& v) {
    char text[96];
    std::snprintf(text, sizeof text, "{%g, %g, %g}", v.x, v.y, v.z);
    return text;
}

/// A material stand-in: diffuse, its kd the call's first colour-like argument; magenta
/// (visible, and plainly not the student's) when it has none.
void pushMaterialStandIn(lua_State* L, const std::string& call) {
    Vec3 kd;
    const int arg =
        findTriple(L, 1, kd, colourLike, {"kd", "diffuse", "colour", "color", "albedo"});
    if (arg) {
        sceneWarning(L, call + " stand-in",
                     call + ": --lenient stands in a diffuse material whose kd is argument " +
                         std::to_string(arg) + " " + tripleText(kd) + ", its first colour");
    } else {
        kd = Vec3(0.8, 0.2, 0.8);
        sceneWarning(L, call + " stand-in",
                     call + ": --lenient stands in a magenta material (no argument is a colour)");
    }
    pushMaterial(L, std::make_shared<Material>(Material{kd, Colour(0.0), 1.0, {}, {}}));
}

/// A light stand-in: a point light at the call's first triple, of the colour of the next one
/// (white when there is none), with no falloff; dark when it has no position.
void pushLightStandIn(lua_State* L, const std::string& call) {
    const auto any = [](const Vec3&) { return true; };
    const auto bright = [](const Vec3& c) {
        return c.x >= 0.0 && c.y >= 0.0 && c.z >= 0.0 && c.x + c.y + c.z > 0.0;
    };
    PointLight light{Vec3(0.0), Colour(0.0), Vec3(1.0, 0.0, 0.0), nullptr};
    const int at = findTriple(L, 1, light.position, any, {"position", "pos", "center", "centre"});
    if (!at) {
        sceneWarning(L, call + " stand-in",
                     call + ": --lenient stands in a dark light (no argument is a position)");
    } else {
        // A table of named fields holds the colour too; else it is a later argument.
        const bool fields = lua_rawlen(L, at) == 0;
        if (!(fields && readTriple(L, at, light.colour, "colour")) &&
            !(fields && readTriple(L, at, light.colour, "color")) &&
            !(fields && readTriple(L, at, light.colour, "intensity")) &&
            !findTriple(L, at + 1, light.colour, bright))
            light.colour = Colour(1.0);
        sceneWarning(L, call + " stand-in",
                     call + ": --lenient stands in a point light at " + tripleText(light.position) +
                         " of colour " + tripleText(light.colour) + " (its first two triples)");
    }
    pushLight(L, light);
    if (at) sceneBuilder(L).standInLights[lua_touserdata(L, -1)] = call;
}

/// Call raybook's own gr.`name` with the `n` values on top of the stack (popped), leaving its
/// node on the stack. False, with nothing left, when this build lacks the call or it fails.
/// What the call takes for a sign of an era is not: the stand-in, not the scene, made it.
bool callOwn(lua_State* L, const char* name, int n) {
    SceneBuilder& builder = sceneBuilder(L);
    const size_t signs = builder.eraSigns.size();
    lua_getglobal(L, "gr");
    const bool table = lua_type(L, -1) == LUA_TTABLE;
    // Raw: gr's __index would make a stand-in of a call this build lacks, and so on forever.
    if (table) {
        lua_pushstring(L, name);
        lua_rawget(L, -2);
    }
    if (!table || !lua_iscfunction(L, -1)) {
        lua_pop(L, n + (table ? 2 : 1));
        return false;
    }
    lua_remove(L, -2);  // gr
    lua_insert(L, -n - 1);
    const bool ok = lua_pcall(L, n, 1, 0) == LUA_OK && luaL_testudata(L, -1, kNodeType);
    builder.eraSigns.resize(signs);
    if (!ok) lua_pop(L, 1);
    return ok;
}

/// Give the node on top of the stack the shape transform `m` (on top of its own).
void reshape(lua_State* L, const Mat4& m) {
    auto node = *static_cast<std::shared_ptr<SceneNode>*>(lua_touserdata(L, -1));
    node->shapeTransform = m * node->shapeTransform;
}

/// The vertices of a polygon call: its triples, or the triples in its first table of them.
std::vector<Vec3> polygonVertices(lua_State* L) {
    std::vector<Vec3> vertices;
    Vec3 v;
    for (int arg = 1; arg <= lua_gettop(L); ++arg) {
        if (readTriple(L, arg, v)) {
            vertices.push_back(v);
        } else if (vertices.empty() && lua_type(L, arg) == LUA_TTABLE) {
            const lua_Unsigned n = lua_rawlen(L, arg);
            for (lua_Unsigned i = 1; i <= n && n <= 64; ++i) {
                lua_rawgeti(L, arg, static_cast<lua_Integer>(i));
                if (readTriple(L, -1, v)) vertices.push_back(v);
                lua_pop(L, 1);
            }
            if (vertices.size() != n) vertices.clear();
        }
    }
    return vertices;
}

/// A mesh of the polygon's vertices, built by gr.mesh's table form.
bool pushPolygon(lua_State* L, const std::string& name, const std::vector<Vec3>& vertices) {
    if (vertices.size() < 3) return false;
    lua_pushstring(L, name.c_str());
    lua_createtable(L, static_cast<int>(vertices.size()), 0);
    for (size_t i = 0; i < vertices.size(); ++i) {
        lua_createtable(L, 3, 0);
        for (int k = 0; k < 3; ++k) {
            lua_pushnumber(L, vertices[i][k]);
            lua_rawseti(L, -2, k + 1);
        }
        lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
    }
    lua_createtable(L, 1, 0);
    lua_createtable(L, static_cast<int>(vertices.size()), 0);
    for (size_t i = 0; i < vertices.size(); ++i) {
        lua_pushinteger(L, static_cast<lua_Integer>(i));  // 0-based, as gr.mesh's tables are
        lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
    }
    lua_rawseti(L, -2, 1);
    return callOwn(L, "mesh", 3);
}

/// The node of one of raybook's own shapes, gr.`own`(name).
bool pushOwnShape(lua_State* L, const char* own, const std::string& name) {
    lua_pushstring(L, name.c_str());
    return callOwn(L, own, 1);
}

/// The stand-in of a shape call raybook does not know, by its name: a plane, a polygon, a
/// disc, a torus, a cylinder, a cone, a sphere or a box. False when the name is none of them.
bool pushShapeStandIn(lua_State* L, const std::string& call, const std::string& lower,
                      const std::string& name) {
    std::string what;
    if (nameHas(lower, {"plane", "ground", "floor"})) {
        // The plane y = 0, as a box 2000 wide and 0.001 thick under it.
        if (!pushOwnShape(L, "cube", name)) return false;
        reshape(L, glm::scale(glm::translate(Mat4(1.0), Vec3(-1000.0, -0.001, -1000.0)),
                              Vec3(2000.0, 0.001, 2000.0)));
        what = "a thin box 2000 wide, its top the plane y = 0";
    } else if (nameHas(lower, {"triangle", "quad", "polygon", "rect", "square", "face"})) {
        const std::vector<Vec3> vertices = polygonVertices(L);
        if (!pushPolygon(L, name, vertices)) return false;
        what = "a mesh of its " + std::to_string(vertices.size()) + " vertices";
    } else if (nameHas(lower, {"disc", "disk", "circle"})) {
        // The unit disc in the plane y = 0, facing +y.
        const Mat4 flat = glm::scale(Mat4(1.0), Vec3(1.0, 0.001, 1.0));
        if (pushOwnShape(L, "cylinder", name)) {
            what = "a cylinder of radius 1, 0.002 thick, in the plane y = 0";
        } else if (pushOwnShape(L, "sphere", name)) {
            what = "a sphere of radius 1 flattened to the plane y = 0";
        } else {
            return false;
        }
        reshape(L, flat);
    } else if (nameHas(lower, {"torus", "donut", "ring"})) {
        // The outer radius: major + minor, from the call's numbers (a unit major radius when
        // it gives one number).
        std::vector<double> radii;
        for (int arg = 1; arg <= lua_gettop(L) && radii.size() < 2; ++arg)
            if (lua_type(L, arg) == LUA_TNUMBER && lua_tonumber(L, arg) > 0.0)
                radii.push_back(lua_tonumber(L, arg));
        double outer = radii.empty()       ? 1.0
                       : radii.size() == 1 ? 1.0 + radii[0]
                                           : radii[0] + radii[1];
        if (!std::isfinite(outer)) outer = 1.0;
        if (!pushOwnShape(L, "sphere", name)) return false;
        reshape(L, glm::scale(Mat4(1.0), Vec3(outer)));
        char text[64];
        std::snprintf(text, sizeof text, "a sphere of its outer radius %g", outer);
        what = text;
    } else if (nameHas(lower, {"cyl", "tube", "pipe"})) {
        if (pushOwnShape(L, "cylinder", name)) {
            what = "raybook's gr.cylinder (radius 1, y from -1 to 1)";
        } else if (pushOwnShape(L, "sphere", name)) {
            what = "a unit sphere (this build has no cylinder)";
        } else {
            return false;
        }
    } else if (nameHas(lower, {"cone"})) {
        if (pushOwnShape(L, "cone", name)) {
            what = "raybook's gr.cone (base radius 1 at y = -1, apex at y = 1)";
        } else if (pushOwnShape(L, "sphere", name)) {
            what = "a unit sphere (this build has no cone)";
        } else {
            return false;
        }
    } else if (nameHas(lower, {"sphere", "ball", "ellipsoid"})) {
        if (!pushOwnShape(L, "sphere", name)) return false;
        what = "raybook's unit sphere";
    } else if (nameHas(lower, {"box", "cube", "block"})) {
        if (!pushOwnShape(L, "cube", name)) return false;
        what = "raybook's unit cube, from (0, 0, 0) to (1, 1, 1)";
    } else {
        return false;
    }
    sceneWarning(L, call + " stand-in", call + ": --lenient stands in " + what);
    return true;
}

/// The value an ignored gr call returns under --lenient, guessed from its name so the rest of
/// the scene can go on as its author meant, as far as raybook can tell: a material of the
/// call's first colour, a point light at its position, the nearest shape raybook has, or an
/// empty node. Each stand-in but the empty node says what it is in a warning.
int pushLenientStandIn(lua_State* L, const std::string& name) {
    std::string lower = name;
    for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    const std::string call = "gr." + name;
    const std::string nodeName = lua_type(L, 1) == LUA_TSTRING ? lua_tostring(L, 1) : name;
    if (nameHas(lower, {"mat", "glass", "metal", "mirror", "dielectric", "lambert", "phong",
                        "chrome", "shader"})) {
        pushMaterialStandIn(L, call);
    } else if (nameHas(lower, {"light", "lamp"})) {
        pushLightStandIn(L, call);
    } else if (!pushShapeStandIn(L, call, lower, nodeName)) {
        auto node = std::make_shared<SceneNode>();
        node->name = nodeName;
        pushNode(L, node);
    }
    return 1;
}

/// The stand-in for a gr call or method nobody defined, under --lenient: upvalue 1 is its full
/// name ("gr.foo" or "node:foo"), upvalue 2 why it is unknown. Records the call, then returns a
/// stand-in (gr calls) or nothing (methods).
int lenientCall(lua_State* L) {
    const std::string full = lua_tostring(L, lua_upvalueindex(1));
    const std::string why = lua_tostring(L, lua_upvalueindex(2));
    SceneBuilder& builder = sceneBuilder(L);
    recordKind(builder.ignoredKinds, builder.ignoredCounts, full,
               full + " (" + why + "), first at " + luaCaller(L));
    if (full.rfind("gr.", 0) != 0) return 0;
    return pushLenientStandIn(L, full.substr(3));
}

}  // namespace

// ---- Arguments a known call cannot read (--lenient) ---------------------------------------

LenientReading startReading(lua_State* L) {
    LenientReading reading;
    reading.arguments = lua_gettop(L);
    reading.eraSigns = sceneBuilder(L).eraSigns.size();
    reading.warnings = sceneBuilder(L).warningKinds.size();
    return reading;
}

namespace {

/// An ArgumentError's message split into the call it names and what it says after the name:
/// "gr.material: argument 2 ..." gives "gr.material" and "argument 2 ...".
std::pair<std::string, std::string> splitCall(const std::string& message) {
    const size_t space = message.find(' ');
    if (space == std::string::npos) return {message, ""};
    std::string call = message.substr(0, space);
    if (!call.empty() && call.back() == ':') call.pop_back();
    return {call, message.substr(space + 1)};
}

/// List a call whose arguments could not be read: what its first reading said, where, and
/// what became of it.
void recordUnreadable(SceneBuilder& builder, const std::string& call, const std::string& said,
                      const std::string& where, const std::string& outcome) {
    recordKind(builder.unreadableKinds, builder.unreadableCounts, call,
               call + " (arguments raybook cannot read: " + said + "; " + outcome + "), first at " +
                   where);
}

/// What became of a call that could not be read at all: a gr call returns a stand-in, a method
/// does nothing.
std::string standInOutcome(const std::string& call) {
    return call.rfind("gr.", 0) == 0 ? "a stand-in took its place" : "the call was ignored";
}

}  // namespace

int lenientArgument(lua_State* L, const ArgumentError& e, LenientReading& reading) {
    SceneBuilder& builder = sceneBuilder(L);
    if (!builder.options.lenient) throw;
    // What a failed reading took for a sign of an era may mean something else entirely.
    builder.eraSigns.erase(builder.eraSigns.begin() + static_cast<long>(reading.eraSigns),
                           builder.eraSigns.end());
    // So may the guesses it warned of: the next reading makes its own.
    for (size_t k = reading.warnings; k < builder.warningKinds.size(); ++k)
        builder.warningCounts.erase(builder.warningKinds[k].first);
    builder.warningKinds.resize(std::min(reading.warnings, builder.warningKinds.size()));
    const auto [call, said] = splitCall(e.what());
    const bool first = builder.reread.call.empty();
    if (e.argument > 1 && e.argument <= reading.arguments) {
        // Leave out the argument and those after it; the first reading's line covers the call.
        if (first)
            builder.reread = {call, said, luaCaller(L), e.argument - 1, false};
        else
            builder.reread.kept = std::min(builder.reread.kept, e.argument - 1);
        reading.ownsReread = first;
        reading.rereadWith = e.argument - 1;
        return 0;
    }
    if (first)
        recordUnreadable(builder, call, said, luaCaller(L), standInOutcome(call));
    else
        builder.reread.stoodIn = true;
    // A gr call's stand-in is chosen by its name; a method does nothing.
    if (call.rfind("gr.", 0) != 0) return 0;
    return pushLenientStandIn(L, call.substr(3));
}

int rereadLeniently(lua_State* L, const LenientReading& reading) {
    lua_settop(L, reading.rereadWith);
    lua_Debug ar;
    lua_getstack(L, 0, &ar);
    lua_getinfo(L, "f", &ar);  // the running function: a C function called directly is its own
    lua_insert(L, 1);
    const int status = lua_pcall(L, reading.rereadWith, LUA_MULTRET, 0);
    if (reading.ownsReread) {
        SceneBuilder& builder = sceneBuilder(L);
        if (status == LUA_OK) {
            const SceneBuilder::Reread& r = builder.reread;
            const std::string kept =
                r.kept == 1 ? "argument" : std::to_string(r.kept) + " arguments";
            recordUnreadable(builder, r.call, r.first, r.where,
                             r.stoodIn ? standInOutcome(r.call) : "read with its first " + kept);
        }
        builder.reread = {};
    }
    if (status == LUA_OK) return lua_gettop(L);
    // A message raised where no Lua code called has no "file:line:": add the script's.
    if (status == LUA_ERRRUN) addScriptWhere(L);
    return lua_error(L);
}

/// Raise the error for a name nobody defined (argument 2 of an __index): which chapter provides
/// it, or that it is unknown. `what` names it in the message ("gr.mesh", "method 'csg'").
/// Under --lenient, return a stand-in function instead (lenientCall).
int unknownName(lua_State* L, const char* prefix, const char* suffix, const char* unknown) {
    const char* name = lua_tostring(L, 2);
    if (!name) return luaL_error(L, "%sindex must be a string", prefix);
    for (const EraCall& c : kEraCalls)
        if (std::strcmp(name, c.name) == 0) noteEraSign(L, c.era, c.what);
    // The message is built in this block and raised after it (see pushCallerError).
    {
        std::string title;
        const int chapter = missingChapter(L, name, title);
        if (sceneBuilder(L).options.lenient) {
            const bool method = std::strcmp(prefix, "gr.") != 0;
            lua_pushstring(L, ((method ? "node:" : "gr.") + std::string(name)).c_str());
            lua_pushstring(
                L, chapter ? ("needs chapter " + std::to_string(chapter) + ", " + title).c_str()
                           : "unknown to raybook");
            lua_pushcclosure(L, luaGuard<lenientCall>, 2);  // the stand-in may throw
            return 1;
        }
        if (chapter) {
            pushCallerError(L, prefix + std::string(name) + suffix + " needs chapter " +
                                   std::to_string(chapter) + " (" + title +
                                   "), which this build does not have; " + chapterAdvice(chapter));
        } else {
            pushScriptWhere(L);
            lua_pushfstring(L, unknown, name);
            lua_concat(L, 2);
        }
    }
    return lua_error(L);
}

/// A node or material method nobody defined.
int unknownMethod(lua_State* L) {
    return unknownName(L, "method '", "'", "'%s' is not a method of raybook nodes or materials");
}

/// `gr.NAME` for a NAME nobody defined.
int unknownGrCall(lua_State* L) {
    return unknownName(L, "gr.", "",
                       "gr.%s is not a raybook call (see --help and the reference page)");
}

void noteStandInLighting(lua_State* L, int arg) {
    const auto& standIns = sceneBuilder(L).standInLights;
    if (standIns.empty() || lua_type(L, arg) != LUA_TTABLE) return;
    const lua_Unsigned n = lua_rawlen(L, arg);
    std::vector<std::string> calls;
    for (lua_Unsigned i = 1; i <= n; ++i) {
        lua_rawgeti(L, arg, static_cast<lua_Integer>(i));
        const auto it = standIns.find(lua_touserdata(L, -1));
        lua_pop(L, 1);
        if (it == standIns.end()) return;  // one of raybook's own lights
        if (std::find(calls.begin(), calls.end(), it->second) == calls.end())
            calls.push_back(it->second);
    }
    if (calls.empty()) return;
    std::string names;
    for (const std::string& c : calls) names += (names.empty() ? "" : ", ") + c;
    sceneWarning(L, "gr.render stand-in lights",
                 "gr.render: every light is a --lenient stand-in (point lights in place of " +
                     names + "): the lighting is a guess");
}

}  // namespace rb

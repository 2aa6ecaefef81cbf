// Names nobody defined and arguments a known call cannot read: the error that names the chapter
// a build lacks, or, under --lenient, a stand-in (a magenta material, a dark light, an empty
// node) and a line in the list rt prints at the end.
#include <cctype>
#include <cstring>
#include <memory>
#include <string>
#include <utility>

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

/// The value an ignored gr call returns under --lenient, guessed from its name so the rest of
/// the scene can go on: a magenta material for a material constructor (visible, and plainly
/// not the student's), a dark point light for a light, an empty node for anything else.
int pushLenientStandIn(lua_State* L, const std::string& name) {
    std::string lower = name;
    for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (lower.find("mat") != std::string::npos) {
        pushMaterial(L, std::make_shared<Material>(
                            Material{Colour(0.8, 0.2, 0.8), Colour(0.0), 1.0, {}, {}}));
    } else if (lower.find("light") != std::string::npos) {
        pushLight(L, PointLight{Vec3(0.0), Colour(0.0), Vec3(1.0, 0.0, 0.0), nullptr});
    } else {
        auto node = std::make_shared<SceneNode>();
        node->name = lua_type(L, 1) == LUA_TSTRING ? lua_tostring(L, 1) : name;
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
    const auto [call, said] = splitCall(e.what());
    const bool first = builder.reread.call.empty();
    if (e.argument > 1 && e.argument <= reading.arguments) {
        // Leave out the argument and those after it; the first reading's line covers the call.
        if (first) builder.reread = {call, said, luaCaller(L), e.argument - 1, false};
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
    // The message of a call made from C has no "file:line:": add the script's.
    if (status == LUA_ERRRUN) {
        luaL_where(L, 1);
        lua_insert(L, -2);
        lua_concat(L, 2);
    }
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
            luaL_where(L, 1);
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

}  // namespace rb

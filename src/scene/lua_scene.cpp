#include "scene/lua_scene.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include "core/box.h"
#include "core/error.h"
#include "core/interrupt.h"
#include "core/sphere.h"
#include "scene/lua_sandbox_io.h"
#include "scene/lua_types.h"

namespace rb {

namespace fs = std::filesystem;

// ---- Userdata types -----------------------------------------------------------------------

namespace {
/// Place a shared_ptr in a new userdata whose metatable is `type` (destroyed by __gc).
template <class T>
void pushShared(lua_State* L, std::shared_ptr<T> p, const char* type) {
    void* mem = lua_newuserdatauv(L, sizeof(std::shared_ptr<T>), 0);
    new (mem) std::shared_ptr<T>(std::move(p));
    luaL_setmetatable(L, type);
}

template <class T>
int collectShared(lua_State* L) {
    // __gc runs once per userdata; reset the pointer it holds.
    static_cast<std::shared_ptr<T>*>(lua_touserdata(L, 1))->~shared_ptr<T>();
    return 0;
}

const char* typeName(lua_State* L, int arg) {
    if (luaL_testudata(L, arg, kNodeType)) return "a scene node";
    if (luaL_testudata(L, arg, kMaterialType)) return "a material";
    if (luaL_testudata(L, arg, "rb.light")) return "a light";
    return lua_typename(L, lua_type(L, arg));
}
}  // namespace

// Lua's allocator sees only a node's userdata (a pointer), so without this a loop of gr.node
// calls with long names, or of gr.render calls, could take all the machine's memory under
// the limit. Never given back: a node may live on as another node's child after its userdata
// is collected.
void chargeMemory(lua_State* L, size_t bytes) {
    SceneBuilder& builder = sceneBuilder(L);
    if (builder.bytesInUse + bytes > builder.options.memoryLimit)
        throw InputError("the scene script exceeded the memory limit of " +
                         std::to_string(builder.options.memoryLimit >> 20) +
                         " MiB (its nodes and materials count too)");
    builder.bytesInUse += bytes;
}

void pushNode(lua_State* L, std::shared_ptr<SceneNode> node) {
    chargeMemory(L, sizeof(SceneNode) + node->name.capacity());
    pushShared(L, std::move(node), kNodeType);
}
void pushMaterial(lua_State* L, std::shared_ptr<Material> material) {
    chargeMemory(L, sizeof(Material));
    pushShared(L, std::move(material), kMaterialType);
}

void chargeInstructions(lua_State* L, size_t count, const char* call) {
    SceneBuilder& builder = sceneBuilder(L);
    builder.instructions += static_cast<long long>(count);
    if (builder.instructions > builder.options.instructionLimit)
        throw InputError(std::string(call) + ": the scene script ran more than " +
                         std::to_string(builder.options.instructionLimit) +
                         " Lua instructions, counting the work of its calls (an endless loop?)");
}

// ---- Argument checks ----------------------------------------------------------------------

SceneBuilder& sceneBuilder(lua_State* L) {
    return **static_cast<SceneBuilder**>(lua_getextraspace(L));
}

std::string luaCaller(lua_State* L) {
    // The nearest Lua code: a call made by another C function (chapter 6's gr.light calls the
    // core's) is the script's line too.
    lua_Debug ar;
    for (int level = 1; lua_getstack(L, level, &ar); ++level)
        if (lua_getinfo(L, "Sl", &ar) && ar.currentline > 0)
            return std::string(ar.short_src) + ":" + std::to_string(ar.currentline);
    return sceneBuilder(L).scenePath;
}

namespace {
/// Add one occurrence of `kind` to a list of kinds with counts, keeping the first message.
void recordKind(std::vector<std::pair<std::string, std::string>>& kinds,
                std::map<std::string, int>& counts, const std::string& kind,
                const std::string& message) {
    if (counts[kind]++ == 0) kinds.emplace_back(kind, message);
}
}  // namespace

void sceneWarning(lua_State* L, const std::string& kind, const std::string& message) {
    SceneBuilder& builder = sceneBuilder(L);
    recordKind(builder.warningKinds, builder.warningCounts, kind, luaCaller(L) + ": " + message);
}

bool calledFromDialect(lua_State* L) {
    lua_Debug ar;
    if (!lua_getstack(L, 1, &ar) || !lua_getinfo(L, "S", &ar) || ar.source[0] != '@') return false;
    const auto& dialects = sceneBuilder(L).options.dialects;
    return std::find(dialects.begin(), dialects.end(), ar.source + 1) != dialects.end();
}

void noteEraSign(lua_State* L, Era era, const std::string& what) {
    SceneBuilder& builder = sceneBuilder(L);
    // A TA's dialect file is not the student's scene: its calls say nothing of the era.
    if (calledFromDialect(L)) return;
    for (const EraSign& s : builder.eraSigns)
        if (s.what == what) return;
    builder.eraSigns.push_back({era, what, luaCaller(L)});
}

void checkArgCount(lua_State* L, const char* call, int min, int max, const char* signature) {
    const int n = lua_gettop(L);
    if (n > max && n >= min) {
        // The course framework reads the arguments it knows and ignores the rest.
        const int extra = n - max;
        sceneWarning(L, std::string(call) + " extra",
                     std::string(call) + ": ignored " + std::to_string(extra) + " extra argument" +
                         (extra == 1 ? "" : "s") + " after " + signature +
                         ", as the course framework does");
        lua_settop(L, max);
        return;
    }
    if (n < min || n > max)
        throw ArgumentError(std::string(call) + " expects " +
                            (min == max ? std::to_string(min)
                                        : std::to_string(min) + " to " + std::to_string(max)) +
                            " argument" + (max == 1 ? "" : "s") + " " + signature + ", got " +
                            std::to_string(n));
}

namespace {
/// "gr.nh_sphere: argument 3 (radius)": how a message names positional argument `arg`.
std::string argumentLabel(const char* call, int arg, const char* argName) {
    return std::string(call) + ": argument " + std::to_string(arg) + " (" + argName + ")";
}
}  // namespace

double checkNumberAt(lua_State* L, int index, const std::string& label) {
    if (lua_type(L, index) != LUA_TNUMBER)
        throw ArgumentError(label + " must be a number, got " + typeName(L, index), index);
    const double v = lua_tonumber(L, index);
    if (!std::isfinite(v))
        throw ArgumentError(label + " must be finite, got " + (std::isnan(v) ? "nan" : "inf"),
                            index);
    return v;
}

double checkNumber(lua_State* L, int arg, const char* call, const char* argName) {
    return checkNumberAt(L, arg, argumentLabel(call, arg, argName));
}

std::string checkString(lua_State* L, int arg, const char* call, const char* argName) {
    if (lua_type(L, arg) != LUA_TSTRING)
        throw ArgumentError(
            argumentLabel(call, arg, argName) + " must be a string, got " + typeName(L, arg), arg);
    size_t len = 0;
    const char* s = lua_tolstring(L, arg, &len);
    return std::string(s, len);
}

std::vector<double> checkTupleAt(lua_State* L, int index, int n, const std::string& label) {
    const std::string what = label + " must be a table of " + std::to_string(n) + " numbers";
    if (lua_type(L, index) != LUA_TTABLE)
        throw ArgumentError(what + ", got " + typeName(L, index), index);
    const lua_Unsigned len = lua_rawlen(L, index);
    if (len != static_cast<lua_Unsigned>(n))
        throw ArgumentError(what + ", got a table of " + std::to_string(len), index);
    std::vector<double> values(n);
    for (int i = 1; i <= n; ++i) {
        const int type = lua_rawgeti(L, index, i);
        const double v = lua_tonumber(L, -1);
        lua_pop(L, 1);
        if (type != LUA_TNUMBER)
            throw ArgumentError(
                what + ", but element " + std::to_string(i) + " is a " + lua_typename(L, type),
                index);
        if (!std::isfinite(v))
            throw ArgumentError(what + ", but element " + std::to_string(i) + " is " +
                                    (std::isnan(v) ? "nan" : "inf"),
                                index);
        values[i - 1] = v;
    }
    return values;
}

std::vector<double> checkTuple(lua_State* L, int arg, int n, const char* call,
                               const char* argName) {
    return checkTupleAt(L, arg, n, argumentLabel(call, arg, argName));
}

Vec3 checkVec3(lua_State* L, int arg, const char* call, const char* argName) {
    const std::vector<double> v = checkTuple(L, arg, 3, call, argName);
    return {v[0], v[1], v[2]};
}

std::shared_ptr<SceneNode> checkNode(lua_State* L, int arg, const char* call, const char* argName) {
    void* p = luaL_testudata(L, arg, kNodeType);
    if (!p)
        throw ArgumentError(std::string(call) + ": argument " + std::to_string(arg) + " (" +
                                argName + ") must be a scene node, got " + typeName(L, arg) +
                                (arg == 1 && std::strchr(call, ':')
                                     ? " (call methods with a colon: node:method(...))"
                                     : ""),
                            arg);
    return *static_cast<std::shared_ptr<SceneNode>*>(p);
}

std::shared_ptr<Material> checkMaterial(lua_State* L, int arg, const char* call,
                                        const char* argName) {
    void* p = luaL_testudata(L, arg, kMaterialType);
    if (!p)
        throw ArgumentError(std::string(call) + ": argument " + std::to_string(arg) + " (" +
                                argName + ") must be a material, got " + typeName(L, arg),
                            arg);
    return *static_cast<std::shared_ptr<Material>*>(p);
}

std::vector<std::string> sceneFileCandidates(const SceneBuilder& builder, const std::string& name) {
    if (fs::path(name).is_absolute()) return {name};
    // The search order: the working directory, the scene's folder, then each --assets folder;
    // a folder named twice (the scene's folder is often the working directory) counts once.
    std::vector<std::string> folders = {"", builder.sceneDir};
    folders.insert(folders.end(), builder.options.assetDirs.begin(),
                   builder.options.assetDirs.end());
    std::vector<std::string> places, seen;
    std::error_code ec;
    for (const std::string& folder : folders) {
        // Compare folders in one spelling: absolute, normalised, with a trailing separator.
        const fs::path full = folder.empty() ? fs::current_path(ec) : fs::absolute(folder, ec);
        const std::string key = (full / "").lexically_normal().string();
        if (std::find(seen.begin(), seen.end(), key) != seen.end()) continue;
        seen.push_back(key);
        places.push_back(folder.empty() ? name : (fs::path(folder) / name).string());
    }
    return places;
}

std::string findSceneFile(const SceneBuilder& builder, const std::string& name,
                          const std::string& call) {
    const std::vector<std::string> places = sceneFileCandidates(builder, name);
    std::error_code ec;
    // The first place that holds something by that name; a folder there fails in the
    // loader, which says so.
    for (const std::string& place : places)
        if (fs::exists(place, ec)) return place;
    // Name every place, absolute, so the student sees where the file should go.
    std::string looked;
    for (const std::string& place : places)
        looked +=
            (looked.empty() ? "" : ", ") + fs::absolute(place, ec).lexically_normal().string();
    throw InputError(call + ": cannot find '" + name + "'; looked in: " + looked +
                     " (add a folder to the search with --assets DIR)");
}

// ---- The sandbox --------------------------------------------------------------------------

namespace {

/// Lua's allocator, with a cap on the bytes in use.
void* limitedAlloc(void* ud, void* ptr, size_t oldSize, size_t newSize) {
    auto* builder = static_cast<SceneBuilder*>(ud);
    const size_t old = ptr ? oldSize : 0;
    if (newSize == 0) {
        builder->bytesInUse -= old;
        std::free(ptr);
        return nullptr;
    }
    if (newSize > old && builder->bytesInUse + (newSize - old) > builder->options.memoryLimit)
        return nullptr;  // Lua raises "not enough memory"
    void* p = std::realloc(ptr, newSize);
    if (p) builder->bytesInUse = builder->bytesInUse - old + newSize;
    return p;
}

/// The count hook: stop a script that runs too long (an endless loop).
constexpr int kHookInterval = 10000;
void instructionHook(lua_State* L, lua_Debug* ar) {
    SceneBuilder& builder = sceneBuilder(L);
    // Ctrl-C or SIGTERM while the script runs: stop it (runFile says why).
    if (pendingInterrupt()) luaL_error(L, "interrupted");
    builder.instructions += kHookInterval;
    if (builder.instructions <= builder.options.instructionLimit) return;
    // Name the line the script was running when it hit the limit.
    lua_getinfo(L, "Sl", ar);
    luaL_error(L, "%s:%d: the scene script ran more than %I Lua instructions (an endless loop?)",
               ar->short_src, ar->currentline,
               static_cast<lua_Integer>(builder.options.instructionLimit));
}

/// Push "file:line: message" for the Lua code that called the running C function, as
/// luaL_error would, so that lua_error can be raised once the C++ objects that built the
/// message are destroyed (lua_error longjmps over destructors: strings would leak).
void pushCallerError(lua_State* L, const std::string& message) {
    luaL_where(L, 1);
    lua_pushlstring(L, message.data(), message.size());
    lua_concat(L, 2);
}

/// require(name): name.lua (dots become slashes) from the places scene files are searched.
/// No C++ object may be alive where Lua raises an error (see pushCallerError).
int sandboxRequire(lua_State* L) {
    const char* raw = luaL_checkstring(L, 1);
    for (const char* c = raw; *c; ++c)
        if (!(std::isalnum(static_cast<unsigned char>(*c)) || *c == '_' || *c == '.' || *c == '-'))
            return luaL_error(L, "require: module name '%s' may use only letters, digits, _ . -",
                              raw);
    if (std::strstr(raw, "..") || raw[0] == '.')
        return luaL_error(L, "require: module name '%s' may not leave the scene's folder", raw);
    // Return the cached module if it was loaded before.
    lua_getfield(L, LUA_REGISTRYINDEX, "rb.loaded");
    lua_getfield(L, -1, raw);
    if (!lua_isnil(L, -1)) return 1;
    lua_pop(L, 1);
    // Search the same places as meshes and textures; a missing module lists them all. The
    // result (the file, or the error) leaves this block as a Lua string.
    bool found = false;
    {
        std::string name = raw;
        for (char& c : name)
            if (c == '.') c = '/';
        std::string fileOrError;
        try {
            fileOrError = findSceneFile(sceneBuilder(L), name + ".lua",
                                        std::string("require('") + raw + "')");
            found = true;
        } catch (const InputError& e) {
            fileOrError = e.what();
        }
        if (found)
            lua_pushlstring(L, fileOrError.data(), fileOrError.size());
        else
            pushCallerError(L, fileOrError);
    }
    if (!found) return lua_error(L);
    // Text chunks only: precompiled bytecode can crash the VM.
    const int status = luaL_loadfilex(L, lua_tostring(L, -1), "t");
    if (status != LUA_OK) return lua_error(L);
    lua_remove(L, -2);  // the file name
    lua_pushstring(L, raw);
    lua_call(L, 1, 1);
    if (lua_isnil(L, -1)) {
        lua_pop(L, 1);
        lua_pushboolean(L, 1);
    }
    lua_pushvalue(L, -1);
    lua_setfield(L, -3, raw);
    return 1;
}

/// load() restricted to text chunks.
int sandboxLoad(lua_State* L) {
    size_t len = 0;
    const char* chunk = lua_tolstring(L, 1, &len);
    if (!chunk) return luaL_error(L, "load: only strings can be loaded in the sandbox");
    const char* name = luaL_optstring(L, 2, "=(load)");
    if (luaL_loadbufferx(L, chunk, len, name, "t") != LUA_OK) {
        lua_pushnil(L);
        lua_insert(L, -2);
        return 2;
    }
    if (!lua_isnone(L, 4)) {
        lua_pushvalue(L, 4);
        if (!lua_setupvalue(L, -2, 1)) lua_pop(L, 1);
    }
    return 1;
}

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
        pushMaterial(
            L, std::make_shared<Material>(Material{Colour(0.8, 0.2, 0.8), Colour(0.0), 1.0, {}, {}}));
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

namespace {

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

/// gr.<name> for a name nobody defined.
int unknownGrCall(lua_State* L) {
    return unknownName(L, "gr.", "",
                       "gr.%s is not a raybook call (see --help and the reference page)");
}

/// __index of the sandbox's globals: reading os or io, which the sandbox leaves out, says so;
/// any other undefined global is nil, as in plain Lua.
int sandboxGlobal(lua_State* L) {
    const char* name = lua_tostring(L, 2);
    if (name && (std::strcmp(name, "os") == 0 || std::strcmp(name, "io") == 0))
        return luaL_error(L,
                          "'%s' is not available: scene files run in raybook's Lua sandbox, "
                          "which leaves out os and has a read-only io (./rt --unsafe-lua "
                          "allows them)",
                          name);
    lua_pushnil(L);
    return 1;
}

/// A Lua 5.1 name (upvalue 2) for a 5.4 function (upvalue 1): notes the pre-2015 sign, then
/// calls the function with the same arguments and returns what it returns.
int legacyAlias(lua_State* L) {
    noteEraSign(L, Era::Legacy, lua_tostring(L, lua_upvalueindex(2)));
    const int n = lua_gettop(L);
    lua_pushvalue(L, lua_upvalueindex(1));
    lua_insert(L, 1);
    lua_call(L, n, LUA_MULTRET);
    return lua_gettop(L);
}

/// Open only base, math, string and table (all libraries with --unsafe-lua).
void openSandbox(lua_State* L, const SceneBuilder& builder) {
    if (builder.options.unsafeLua) {
        luaL_openlibs(L);
    } else {
        luaL_requiref(L, LUA_GNAME, luaopen_base, 1);
        luaL_requiref(L, LUA_MATHLIBNAME, luaopen_math, 1);
        luaL_requiref(L, LUA_STRLIBNAME, luaopen_string, 1);
        luaL_requiref(L, LUA_TABLIBNAME, luaopen_table, 1);
        lua_pop(L, 4);
        // Remove what reads files or loads bytecode; keep a text-only load.
        for (const char* name : {"dofile", "loadfile"}) {
            lua_pushnil(L);
            lua_setglobal(L, name);
        }
        lua_pushcfunction(L, sandboxLoad);
        lua_setglobal(L, "load");
        // The course's readobj.lua reads OBJ files with io: a read-only io serves it.
        openReadOnlyIo(L);
        // A scene that reaches for os or io learns why it is missing.
        lua_pushglobaltable(L);
        lua_newtable(L);
        lua_pushcfunction(L, sandboxGlobal);
        lua_setfield(L, -2, "__index");
        lua_setmetatable(L, -2);
        lua_pop(L, 1);
    }
    lua_newtable(L);
    lua_setfield(L, LUA_REGISTRYINDEX, "rb.loaded");
    lua_pushcfunction(L, sandboxRequire);
    lua_setglobal(L, "require");
    // Lua 5.1 names that legacy course scenes use: unpack and string.gfind. Each is the 5.4
    // function behind a stand-in that notes the pre-2015 sign first.
    lua_getglobal(L, "table");
    lua_getfield(L, -1, "unpack");
    lua_pushstring(L, "unpack");
    lua_pushcclosure(L, legacyAlias, 2);
    lua_setglobal(L, "unpack");
    lua_pop(L, 1);
    lua_getglobal(L, "string");
    lua_getfield(L, -1, "gmatch");
    lua_pushstring(L, "string.gfind");
    lua_pushcclosure(L, legacyAlias, 2);
    lua_setfield(L, -2, "gfind");
    lua_pop(L, 1);
}

/// Create the gr table and the node and material metatables.
void createTypes(lua_State* L) {
    lua_newtable(L);  // gr
    lua_newtable(L);  // its metatable: unknown calls name their chapter
    lua_pushcfunction(L, unknownGrCall);
    lua_setfield(L, -2, "__index");
    lua_setmetatable(L, -2);
    lua_setglobal(L, "gr");
    // gr.methods.node and gr.methods.material: the method tables, where a --dialect file
    // adds or replaces methods.
    lua_getglobal(L, "gr");
    lua_newtable(L);
    lua_setfield(L, -2, "methods");
    lua_pop(L, 1);
    for (const char* type : {kNodeType, kMaterialType}) {
        luaL_newmetatable(L, type);
        lua_newtable(L);  // the methods; unknown ones name their chapter
        // Expose the method table as gr.methods.node / gr.methods.material.
        lua_getglobal(L, "gr");
        lua_getfield(L, -1, "methods");
        lua_pushvalue(L, -3);
        lua_setfield(L, -2, std::strcmp(type, kNodeType) == 0 ? "node" : "material");
        lua_pop(L, 2);
        lua_newtable(L);
        lua_pushcfunction(L, unknownMethod);
        lua_setfield(L, -2, "__index");
        lua_setmetatable(L, -2);
        lua_setfield(L, -2, "__index");
        lua_pushcfunction(L, std::strcmp(type, kNodeType) == 0 ? collectShared<SceneNode>
                                                               : collectShared<Material>);
        lua_setfield(L, -2, "__gc");
        lua_pop(L, 1);
    }
}

struct LuaStateCloser {
    void operator()(lua_State* L) const { lua_close(L); }
};

}  // namespace

namespace {

/// Run one Lua file in the scene's state: text only, errors raised as InputError with
/// "file:line:" (or the memory limit named).
void runFile(lua_State* L, const std::string& file, const SceneLoadOptions& options,
             const std::string* text = nullptr) {
    // "@file" names the chunk the way luaL_loadfilex does, so messages read "file:line:".
    int status = text ? luaL_loadbufferx(L, text->data(), text->size(), ("@" + file).c_str(), "t")
                      : luaL_loadfilex(L, file.c_str(), "t");
    if (status == LUA_OK) status = lua_pcall(L, 0, 0, 0);
    if (status == LUA_OK) return;
    if (const int signal = pendingInterrupt()) throw interruptedBy(signal);
    std::string message = lua_tostring(L, -1) ? lua_tostring(L, -1) : "unknown Lua error";
    if (status == LUA_ERRMEM)
        message = file + ": the scene script exceeded the memory limit of " +
                  formatBytes(options.memoryLimit) +
                  " for scripts (2 GiB, or what the run's memory limit leaves free if less: " +
                  options.memory.origin + ")";
    throw InputError(message);
}

/// Run the dialect files, then the scene, in one sandboxed state, with transforms in the
/// given era. Fills `builder`.
void runScene(const std::string& path, const FeatureSet& features, bool legacy,
              SceneBuilder& builder) {
    builder.scenePath = path;
    builder.sceneDir = fs::path(path).parent_path().string();
    builder.legacy = legacy;
    builder.unitSphere = std::make_shared<Sphere>();
    builder.unitCube = std::make_shared<Box>();
    for (const Feature& f : features.built()) {
        builder.lastChapter = std::max(builder.lastChapter, f.chapter);
        builder.builtChapters.push_back(f.chapter);
    }
    for (const Feature& f : features.on()) builder.featuresOn.insert(f.name);

    // A fresh state with a capped allocator; the builder is reachable from the state itself.
    std::unique_ptr<lua_State, LuaStateCloser> state(lua_newstate(limitedAlloc, &builder));
    if (!state) throw InputError(path + ": cannot create a Lua state");
    lua_State* L = state.get();
    *static_cast<SceneBuilder**>(lua_getextraspace(L)) = &builder;
    openSandbox(L, builder);
    createTypes(L);
    LuaBindings bindings(L);
    for (const Feature& f : features.built())
        if (f.bindLua) f.bindLua(bindings);
    lua_sethook(L, instructionHook, LUA_MASKCOUNT, kHookInterval);

    // A TA's dialect files first: they may define or replace gr calls and methods.
    for (const std::string& dialect : builder.options.dialects) {
        if (!fs::is_regular_file(dialect))
            throw InputError("--dialect: cannot open '" + dialect + "'");
        runFile(L, dialect, builder.options);
    }
    const std::string& text = builder.options.sceneText;
    runFile(L, path, builder.options, text.empty() ? nullptr : &text);
    if (builder.renders.empty()) throw InputError(path + ": the scene never calls gr.render");
}

/// "kind (N times)" lines from a list of kinds with counts.
std::vector<std::string> withCounts(const std::vector<std::pair<std::string, std::string>>& kinds,
                                    const std::map<std::string, int>& counts) {
    std::vector<std::string> lines;
    for (const auto& [kind, message] : kinds) {
        const int n = counts.at(kind);
        lines.push_back(message + (n > 1 ? " (" + std::to_string(n) + " times)" : ""));
    }
    return lines;
}

}  // namespace

// [load-scene]
std::vector<LoadedRender> loadScene(const std::string& path, const FeatureSet& features,
                                    const SceneLoadOptions& options, SceneLoadReport* report) {
    const auto start = std::chrono::steady_clock::now();
    // Run in the forced era, or as a current scene first.
    auto builder = std::make_unique<SceneBuilder>();
    builder->options = options;
    runScene(path, features, options.era == EraChoice::Legacy, *builder);
    // What the scene used decides its era; a pre-2015 scene runs again with its transforms
    // post-multiplied (scripts are cheap).
    const EraDecision era =
        decideEra(options.era, builder->eraSigns, builder->orderMatters, placementIdiom(*builder));
    if ((era.era == Era::Legacy) != builder->legacy) {
        builder = std::make_unique<SceneBuilder>();
        builder->options = options;
        runScene(path, features, era.era == Era::Legacy, *builder);
    }
    if (report) {
        report->times = builder->times;
        report->times.total =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        report->era = era;
        report->warnings = withCounts(builder->warningKinds, builder->warningCounts);
        report->ignored = withCounts(builder->ignoredKinds, builder->ignoredCounts);
        report->unreadable = withCounts(builder->unreadableKinds, builder->unreadableCounts);
    }
    return std::move(builder->renders);
}
// [load-scene]

}  // namespace rb

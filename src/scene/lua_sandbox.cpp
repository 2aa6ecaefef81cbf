// The sandbox scene files run in: a capped allocator, an instruction limit (an endless loop
// stops with its file and line), only Lua's base, math, string and table libraries with a
// text-only load, a read-only io, and require() that searches the scene's folders.
#include <cctype>
#include <cstdlib>
#include <cstring>
#include <string>

#include "core/error.h"
#include "core/interrupt.h"
#include "scene/lua_sandbox_io.h"
#include "scene/lua_scene.h"
#include "scene/lua_types.h"

namespace rb {

void pushCallerError(lua_State* L, const std::string& message) {
    pushScriptWhere(L);
    lua_pushlstring(L, message.data(), message.size());
    lua_concat(L, 2);
}

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

}  // namespace

lua_State* newSandboxState(SceneBuilder& builder) {
    lua_State* L = lua_newstate(limitedAlloc, &builder);
    if (!L) return nullptr;
    *static_cast<SceneBuilder**>(lua_getextraspace(L)) = &builder;
    // The limit, for a Lua that allocates with an allocator of its own: the page's (src/web)
    // holds its scripts to it.
    lua_pushinteger(L, static_cast<lua_Integer>(builder.options.memoryLimit));
    lua_setfield(L, LUA_REGISTRYINDEX, "rb.memory_limit");
    openSandbox(L, builder);
    return L;
}

void limitInstructions(lua_State* L) {
    lua_sethook(L, instructionHook, LUA_MASKCOUNT, kHookInterval);
}

}  // namespace rb

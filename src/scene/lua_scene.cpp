// The scene loader: the userdata of nodes and materials, the builder a script fills, its
// warnings and era signs, where scene files are found, and loadScene, which runs the dialect
// files and the scene in the sandbox (lua_sandbox.cpp) with every built chapter's calls.
// Reading arguments is in lua_arguments.cpp; unknown names and --lenient in lua_lenient.cpp.
#include "scene/lua_scene.h"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <regex>

#include "core/box.h"
#include "core/error.h"
#include "core/interrupt.h"
#include "core/sphere.h"
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

// ---- The builder, warnings and era signs --------------------------------------------------

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

void pushScriptWhere(lua_State* L) {
    // Only Lua's own calls here: an error may be raised right after (no C++ objects alive).
    lua_Debug ar;
    for (int level = 1; lua_getstack(L, level, &ar); ++level)
        if (lua_getinfo(L, "Sl", &ar) && ar.currentline > 0) {
            lua_pushfstring(L, "%s:%d: ", ar.short_src, ar.currentline);
            return;
        }
    lua_pushliteral(L, "");
}

void addScriptWhere(lua_State* L) {
    pushScriptWhere(L);
    size_t whereLength = 0, messageLength = 0;
    const char* where = lua_tolstring(L, -1, &whereLength);
    const char* message = lua_tolstring(L, -2, &messageLength);
    if (!message ||
        (messageLength >= whereLength && std::memcmp(message, where, whereLength) == 0)) {
        lua_pop(L, 1);
        return;
    }
    lua_insert(L, -2);
    lua_concat(L, 2);
}

void recordKind(std::vector<std::pair<std::string, std::string>>& kinds,
                std::map<std::string, int>& counts, const std::string& kind,
                const std::string& message) {
    if (counts[kind]++ == 0) kinds.emplace_back(kind, message);
}

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

std::string findSceneFile(SceneBuilder& builder, const std::string& name, const std::string& call) {
    const std::vector<std::string> places = sceneFileCandidates(builder, name);
    std::error_code ec;
    // The first place that holds something by that name; a folder there fails in the
    // loader, which says so. Each file found is remembered, once, for the render's identity.
    for (const std::string& place : places)
        if (fs::exists(place, ec)) {
            const std::pair<std::string, std::string> file{name, place};
            if (std::find(builder.filesRead.begin(), builder.filesRead.end(), file) ==
                builder.filesRead.end())
                builder.filesRead.push_back(file);
            return place;
        }
    // Name every place, absolute, so the student sees where the file should go.
    std::string looked;
    for (const std::string& place : places)
        looked +=
            (looked.empty() ? "" : ", ") + fs::absolute(place, ec).lexically_normal().string();
    throw InputError(call + ": cannot find '" + name + "'; looked in: " + looked +
                     " (add a folder to the search with --assets DIR)");
}

// ---- The state ----------------------------------------------------------------------------

namespace {

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

/// The message handler of a script's run: a string passes as it is; any other error value
/// (error() with a table, say) becomes a message that says what it was, at the script's line.
int scriptMessage(lua_State* L) {
    if (lua_type(L, 1) == LUA_TSTRING || lua_type(L, 1) == LUA_TNUMBER) return 1;
    if (luaL_callmeta(L, 1, "__tostring") && lua_type(L, -1) == LUA_TSTRING) {
        addScriptWhere(L);
        return 1;
    }
    lua_settop(L, 1);
    pushScriptWhere(L);
    lua_pushfstring(L,
                    "the script raised an error whose value is a %s, not a message (error() "
                    "takes a string)",
                    luaL_typename(L, 1));
    lua_concat(L, 2);
    return 1;
}

/// "a.lua:3: a.lua:3: what" as "a.lua:3: what": a message raised again by error(message) on
/// the line that made it names its place once.
std::string withoutRepeatedPlace(const std::string& message) {
    static const std::regex repeated(R"(^([^ \n]+:[0-9]+: )\1+)");
    return std::regex_replace(message, repeated, "$1", std::regex_constants::format_first_only);
}

/// Run one Lua file in the scene's state: text only, errors raised as InputError with
/// "file:line:" (or the memory limit named).
void runFile(lua_State* L, const std::string& file, const SceneLoadOptions& options,
             const std::string* text = nullptr) {
    // "@file" names the chunk the way luaL_loadfilex does, so messages read "file:line:".
    int status = text ? luaL_loadbufferx(L, text->data(), text->size(), ("@" + file).c_str(), "t")
                      : luaL_loadfilex(L, file.c_str(), "t");
    if (status == LUA_OK) {
        lua_pushcfunction(L, scriptMessage);
        lua_insert(L, -2);
        status = lua_pcall(L, 0, 0, -2);
    }
    if (status == LUA_OK) {
        lua_pop(L, 1);  // the message handler
        return;
    }
    if (const int signal = pendingInterrupt()) throw interruptedBy(signal);
    std::string message = lua_tostring(L, -1) ? lua_tostring(L, -1) : "unknown Lua error";
    if (status == LUA_ERRMEM)
        message = file + ": the scene script exceeded the memory limit of " +
                  formatBytes(options.memoryLimit) +
                  " for scripts (2 GiB, or what the run's memory limit leaves free if less: " +
                  options.memory.origin + ")";
    throw InputError(withoutRepeatedPlace(message));
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
    std::unique_ptr<lua_State, LuaStateCloser> state(newSandboxState(builder));
    if (!state) throw InputError(path + ": cannot create a Lua state");
    lua_State* L = state.get();
    createTypes(L);
    LuaBindings bindings(L);
    for (const Feature& f : features.built())
        if (f.bindLua) f.bindLua(bindings);
    limitInstructions(L);

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
        report->files = builder->filesRead;
    }
    return std::move(builder->renders);
}
// [load-scene]

}  // namespace rb

/// \file
/// The Lua scene loader: a sandboxed Lua 5.4 that runs a scene script and collects its
/// gr.render calls, plus the helpers chapter modules use to add their own Lua calls.
#pragma once

#include <lua.hpp>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/error.h"
#include "core/feature.h"
#include "core/memory_budget.h"
#include "core/scene_graph.h"
#include "scene/scene_era.h"

namespace rb {

/// How to run a scene script.
struct SceneLoadOptions {
    EraChoice era = EraChoice::Detect;           ///< --legacy, --modern, or decided from the scene.
    bool unsafeLua = false;                      ///< Allow os and io.
    long long instructionLimit = 1'000'000'000;  ///< Lua VM instructions before we give up.
    size_t memoryLimit = size_t(2) << 30;        ///< Bytes the script may allocate.
    MemoryBudget memory;  ///< The whole run's budget (--max-memory): meshes are checked against it.
    std::vector<std::string> assetDirs;  ///< --assets DIR, searched after the scene's folder.
    bool lenient = false;  ///< --lenient: stand-ins for unknown names and unreadable arguments.
    std::vector<std::string> dialects;  ///< --dialect FILE.lua: run before the scene.
    /// The chapters' --name=value options, for calls that need one while the script runs
    /// (chapter 3's gr.mesh builds its BVH with --bvh's layout).
    std::map<std::string, std::string> featureOptions;
    /// The script itself, when it is not to be read from the scene path (the fuzz harness);
    /// the path still names it in messages and still decides the scene's folder.
    std::string sceneText;
};

/// Where the time of loading a scene went (for --stats).
struct SceneLoadTimes {
    double total = 0.0;     ///< The whole script run, including the two below.
    double meshLoad = 0.0;  ///< Reading OBJ files.
    double meshBvh = 0.0;   ///< Building the meshes' BVHs.
};

/// What loading a scene found out besides its renders: times, the era and the warnings.
struct SceneLoadReport {
    SceneLoadTimes times;
    EraDecision era;
    std::vector<std::string> warnings;  ///< "scene.lua:12: gr.sphere: ..." one per kind.
    std::vector<std::string> ignored;   ///< --lenient: unknown names ignored, with counts.
    /// --lenient: known calls whose arguments could not be read, with counts.
    std::vector<std::string> unreadable;
    /// Every file the scene read (meshes, textures, density files, required Lua files): the
    /// name it gave and the path where it was found, in the order first read.
    std::vector<std::pair<std::string, std::string>> files;
};

/// What the Lua calls build while the script runs. One per load; reached through the
/// lua_State, so no global state is needed.
struct SceneBuilder {
    std::string scenePath;  ///< As given on the command line.
    std::string sceneDir;   ///< Folder of the scene ("" for the working directory).
    SceneLoadOptions options;
    std::vector<LoadedRender> renders;
    std::map<std::string, std::shared_ptr<const Shape>> meshCache;  ///< One load per file.
    /// Every file findSceneFile found: the name the scene gave, the path (SceneLoadReport).
    std::vector<std::pair<std::string, std::string>> filesRead;
    std::shared_ptr<const Shape> unitSphere, unitCube;  ///< Shared by all nodes.
    /// For nodes without a material: grey, no highlight. Shared with each render.
    std::shared_ptr<const Material> defaultMaterial =
        std::make_shared<const Material>(Material{Colour(0.5), Colour(0.0), 1.0, {}, {}});
    std::map<std::string, int> materialFields;  ///< Named material parameters, by chapter.
    /// What gr.option accepts for one name.
    struct OptionSpec {
        int chapter;
        double min, max;
        bool integer;
    };
    std::map<std::string, OptionSpec> optionNames;  ///< gr.option names and their ranges.
    std::map<std::string, double> sceneOptions;     ///< gr.option values set so far.
    std::shared_ptr<const Medium> fog;              ///< Chapter 17's gr.fog so far, or null.
    SceneLoadTimes times;
    bool legacy = false;  ///< This run's era: transforms post-multiply (pre-2015 framework).
    std::vector<EraSign> eraSigns;  ///< What the scene used that belongs to one era.
    std::string orderMatters;       ///< Where a transform first did not commute with the node's.
    /// A node's translations and scales so far, for the era's idiom (see EraIdiom).
    struct Placement {
        std::weak_ptr<const SceneNode> node;  ///< Which node: an address may be reused.
        /// Runs of translates and scales ("TS", "STS"), and of rotations and scales ("SR").
        std::string translateScale, rotateScale;
        Mat4 translation{1.0}, scale{1.0}, rotation{1.0};  ///< The products of each kind.
        std::string whereTS, whereRS;  ///< The calls that began each string's second run.
        long first = 0;                ///< When the node was first placed.
    };
    std::map<const SceneNode*, Placement> placements;
    std::vector<Placement> pastPlacements;  ///< Of nodes whose placement restarted.
    long placingCalls = 0;
    /// Warnings by kind: the first message (with its line) and how often the kind occurred.
    std::vector<std::pair<std::string, std::string>> warningKinds;
    std::map<std::string, int> warningCounts;
    std::vector<std::pair<std::string, std::string>> ignoredKinds;  ///< --lenient, the same way.
    std::map<std::string, int> ignoredCounts;
    /// --lenient: known calls whose arguments could not be read, the same way.
    std::vector<std::pair<std::string, std::string>> unreadableKinds;
    std::map<std::string, int> unreadableCounts;
    /// --lenient: the call being read again without the arguments it could not read, and
    /// what its first reading said, and where; empty when no call is. A reading that fails again,
    /// or stands in, belongs to the same call: the whole call gets one line.
    struct Reread {
        std::string call, first, where;
        int kept = 0;          ///< The arguments it is read with.
        bool stoodIn = false;  ///< A later reading failed too, and a stand-in was returned.
    } reread;
    /// --lenient: the lights that stand in for calls raybook does not know, by their userdata,
    /// with the call each stands in for.
    std::map<const void*, std::string> standInLights;
    int lastChapter = 0;               ///< The newest chapter built into this binary.
    std::vector<int> builtChapters;    ///< Every chapter built in (they may land out of order).
    std::set<std::string> featuresOn;  ///< The features switched on for this run.
    long long instructions = 0;
    size_t bytesInUse = 0;
};

/// Registers Lua calls. Chapter modules receive one in Feature::bindLua.
class LuaBindings {
  public:
    explicit LuaBindings(lua_State* L) : L_(L) {}
    /// Define or replace `gr.name`.
    void function(const char* name, lua_CFunction f);
    /// Define or replace a method of scene nodes (`node:name(...)`).
    void nodeMethod(const char* name, lua_CFunction f);
    /// Define or replace a method of materials (`material:name(...)`).
    void materialMethod(const char* name, lua_CFunction f);
    /// Accept a numeric material parameter in gr.material{...} (chapter: who reads it).
    void materialField(const char* name, int chapter);
    /// Accept a scene option gr.option(name, value) (chapter: who reads it), with the values
    /// it allows: [min, max], and whole numbers only when `integer`.
    void option(const char* name, int chapter, double min = -1e308, double max = 1e308,
                bool integer = false);
    lua_State* state() const { return L_; }

  private:
    lua_State* L_;
};

/// Run the scene script and return its render requests in call order. Binds the Lua calls of
/// every built feature. Throws InputError ("file:line: what was expected") for bad input.
std::vector<LoadedRender> loadScene(const std::string& path, const FeatureSet& features,
                                    const SceneLoadOptions& options,
                                    SceneLoadReport* report = nullptr);

// ---- Helpers for writing Lua calls --------------------------------------------------------
// A call written with RB_LUA_CALL may throw InputError with a message that names the call and
// argument; the wrapper adds "file:line:" and raises it as a Lua error. Never call lua_error or
// luaL_error* inside such a body: they would jump over C++ destructors.

/// An argument a known call cannot read: of the wrong type, one too few, or outside the range
/// raybook allows. The message begins with the call's name, then a colon or " expects"
/// ("gr.material: argument 2 (ks) must be ...", "node:scale expects 3 arguments ..."). Without
/// --lenient it stops the scene like any InputError; under --lenient luaGuard reads the call
/// without that argument, or returns a stand-in (see lenientArgument).
class ArgumentError : public InputError {
  public:
    explicit ArgumentError(const std::string& message, int argument = 0)
        : InputError(message), argument(argument) {}
    /// The position of the argument at fault; 0 when no one argument is (a count, a field).
    int argument;
};

/// One reading of a call's arguments by luaGuard, and what it leaves to do under --lenient.
/// Trivially destructible: it may live where Lua raises errors.
struct LenientReading {
    int arguments = -1;   ///< How many arguments the call received.
    size_t eraSigns = 0;  ///< Era signs before the call: a failed reading's are taken back.
    size_t warnings = 0;  ///< Kinds of warning before the call: a failed reading's new ones too.
    int rereadWith = 0;   ///< Read the call again with this many arguments (0: do not).
    bool ownsReread = false;  ///< This reading began the call's rereading (lists the call).
};
static_assert(std::is_trivially_destructible_v<LenientReading>);

/// Under --lenient, what becomes of a call whose argument `e` could not be read (rethrows `e`
/// otherwise). An argument after the first, among those the call received, is left out with
/// the ones after it: `reading.rereadWith` says how many to keep, and the caller calls again
/// (rereadLeniently). Otherwise the call returns a stand-in chosen by its name, as an unknown
/// name does (its result count is returned). Either way the call is listed at the end of the
/// run. May throw InputError (the stand-in counts against the memory limit).
int lenientArgument(lua_State* L, const ArgumentError& e, LenientReading& reading);
/// Call the running function again with its first `reading.rereadWith` arguments, and return
/// what it returns; the whole call gets one line in the list. May raise a Lua error: call it
/// where no C++ object with a destructor is alive.
int rereadLeniently(lua_State* L, const LenientReading& reading);
/// The call's arguments and era signs as a reading starts.
LenientReading startReading(lua_State* L);

/// Push "file:line: " for the nearest Lua code on the call stack that has a line (the script's
/// line, also under pcall, table.sort or a call made from C), or "" when there is none.
void pushScriptWhere(lua_State* L);
/// Prefix the error message on top of the stack with pushScriptWhere's "file:line: ", unless it
/// already begins with it (a message must never repeat its place).
void addScriptWhere(lua_State* L);

/// Wrap a C++ body `int body(lua_State*)` that may throw into a lua_CFunction. Under
/// --lenient, an ArgumentError becomes a second reading or a stand-in (lenientArgument).
template <int (*Body)(lua_State*)>
int luaGuard(lua_State* L) {
    LenientReading reading = startReading(L);
    {
        std::string message;
        try {
            try {
                return Body(L);
            } catch (const ArgumentError& e) {
                const int results = lenientArgument(L, e, reading);
                if (reading.rereadWith == 0) return results;
            }
        } catch (const std::exception& e) {
            message = e.what();
        }
        if (reading.rereadWith == 0) {
            pushScriptWhere(L);
            lua_pushlstring(L, message.data(), message.size());
            lua_concat(L, 2);
        }
    }
    if (reading.rereadWith > 0) return rereadLeniently(L, reading);
    return lua_error(L);
}

/// The SceneBuilder of the running script.
SceneBuilder& sceneBuilder(lua_State* L);
/// "scene.lua:12": where the running Lua code called the current C function (through any C
/// functions between them).
std::string luaCaller(lua_State* L);
/// Record a warning of kind `kind` (once per kind; later ones only count) at the caller's line.
void sceneWarning(lua_State* L, const std::string& kind, const std::string& message);
/// True when the running C function was called from a --dialect file, not the scene.
bool calledFromDialect(lua_State* L);
/// Record a translate ('T'), scale ('S') or rotate ('R') of `node` by `m`, for the era's idiom.
void notePlacement(lua_State* L, const std::shared_ptr<SceneNode>& node, char kind, const Mat4& m);

/// Start `node`'s placement afresh: node:csg made its transforms so far an operand's.
void restartPlacement(lua_State* L, const SceneNode* node);

/// The nodes' votes for an era's idiom. A node whose scale does not commute with its rotation
/// votes by which it wrote first: rotate, then scale is pre-2015 (post-multiplied, the scale
/// acts first), scale, then rotate current. Otherwise a node written translate, then scale
/// (pre-2015) or scale, then translate (current), with no further run, votes by that.
EraIdiom placementIdiom(const SceneBuilder& builder);

/// Record that the scene used `what`, a sign of `era` (the first use of each is kept).
void noteEraSign(lua_State* L, Era era, const std::string& what);
/// Throw unless the call received at least min arguments. More than max is what the course
/// framework ignores: a warning, and the extra arguments are not read.
void checkArgCount(lua_State* L, const char* call, int min, int max, const char* signature);
/// A finite number at stack index `index`; `label` names it in messages
/// ("gr.material: field 'shininess'").
double checkNumberAt(lua_State* L, int index, const std::string& label);
/// A table of exactly n finite numbers at stack index `index`, named by `label`.
std::vector<double> checkTupleAt(lua_State* L, int index, int n, const std::string& label);
/// A finite number argument.
double checkNumber(lua_State* L, int arg, const char* call, const char* argName);
/// A string argument.
std::string checkString(lua_State* L, int arg, const char* call, const char* argName);
/// A table of exactly n finite numbers.
std::vector<double> checkTuple(lua_State* L, int arg, int n, const char* call, const char* argName);
/// A table of exactly 3 finite numbers.
Vec3 checkVec3(lua_State* L, int arg, const char* call, const char* argName);
/// A scene node argument.
std::shared_ptr<SceneNode> checkNode(lua_State* L, int arg, const char* call, const char* argName);
/// A material argument.
std::shared_ptr<Material> checkMaterial(lua_State* L, int arg, const char* call,
                                        const char* argName);
/// Push a new scene node userdata. Its C++ size (and its name's) counts against the script's
/// memory limit, for good: throws InputError past the limit (call it inside luaGuard).
void pushNode(lua_State* L, std::shared_ptr<SceneNode> node);
/// Push a new material userdata; counted like a node.
void pushMaterial(lua_State* L, std::shared_ptr<Material> material);
/// Count `bytes` that C++ holds for the script (nodes, copies, instances) against its memory
/// limit, for good; throws InputError past the limit.
void chargeMemory(lua_State* L, size_t bytes);
/// Count `count` units of C++ work done for the script (nodes visited, say) as Lua
/// instructions; throws InputError naming `call` past the instruction limit.
void chargeInstructions(lua_State* L, size_t count, const char* call);
/// The places a file named by the scene is looked for, in order: the working directory, the
/// scene's folder, then each --assets folder (only the name itself when it is absolute).
std::vector<std::string> sceneFileCandidates(const SceneBuilder& builder, const std::string& name);
/// The first of sceneFileCandidates() that exists, remembered in builder.filesRead. Throws
/// InputError naming `call` and every place searched when none is.
std::string findSceneFile(SceneBuilder& builder, const std::string& name, const std::string& call);

/// Push a light userdata (gr.light's result).
void pushLight(lua_State* L, const PointLight& light);
/// The light made by gr.light at stack index arg.
PointLight checkLight(lua_State* L, int arg, const char* call, const char* argName);
/// The table of lights at argument arg: at least one, each made by gr.light.
std::vector<PointLight> checkLights(lua_State* L, int arg);

/// Under --lenient, warn (one line) when every light in the table at argument `arg` of
/// gr.render is a stand-in: the scene's lighting is then a guess.
void noteStandInLighting(lua_State* L, int arg);

/// Store scene option `name` (a gr.option name) after checking the range gr.option allows;
/// out of range throws InputError "<what> must be a number from MIN to MAX", where `what`
/// names the call and argument, e.g. "gr.option: 'max_depth'" or "gr.lens: field 'aperture'".
void setSceneOption(lua_State* L, const std::string& name, double value, const std::string& what);

/// The chapter that provides `name` when this build lacks it, else 0 (the name is then
/// simply unknown: a typo, or not a name of that kind).
int missingChapter(lua_State* L, const std::string& name, std::string& title);

/// Set a named material parameter after checking that a built chapter reads it; `value`
/// must be finite. Throws InputError naming the chapter that would read an unknown name.
void setMaterialParam(lua_State* L, Material& m, const std::string& name, double value,
                      const char* call);

/// Throws InputError unless a built chapter reads material field `name` (naming the chapter
/// that would, when one does).
void checkMaterialField(lua_State* L, const std::string& name, const char* call);

/// gr.material{...}: raybook's named-field form (a call body; may throw).
int materialTable(lua_State* L);
/// gr.material(kd, ks, shininess): A4's form (a call body; may throw).
int a4Material(lua_State* L);

/// Chapter 1's Lua calls: the A4 language except gr.mesh.
void bindA4(LuaBindings& lua);

}  // namespace rb

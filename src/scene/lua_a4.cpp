// The CS488 A4 scene language: gr.node, gr.joint, gr.sphere, gr.cube, gr.nh_sphere, gr.nh_box,
// gr.material, gr.light, gr.render and the node methods. gr.mesh comes with chapter 3.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/gtc/matrix_transform.hpp>

#include "core/error.h"
#include "core/image.h"
#include "core/target_error.h"
#include "scene/lua_scene.h"

namespace rb {

namespace {

/// A new node named by argument 1.
std::shared_ptr<SceneNode> newNode(lua_State* L, const char* call) {
    auto node = std::make_shared<SceneNode>();
    node->name = checkString(L, 1, call, "name");
    return node;
}

// [lua-primitives]
int grNode(lua_State* L) {
    checkArgCount(L, "gr.node", 1, 1, "(name)");
    pushNode(L, newNode(L, "gr.node"));
    return 1;
}

int grJoint(lua_State* L) {
    // A4 draws joints as plain transform nodes; the ranges matter only to A3's puppet UI.
    checkArgCount(L, "gr.joint", 3, 3, "(name, {xmin,xinit,xmax}, {ymin,yinit,ymax})");
    auto node = newNode(L, "gr.joint");
    checkTuple(L, 2, 3, "gr.joint", "x range");
    checkTuple(L, 3, 3, "gr.joint", "y range");
    pushNode(L, node);
    return 1;
}

int grSphere(lua_State* L) {
    checkArgCount(L, "gr.sphere", 1, 1, "(name)");
    auto node = newNode(L, "gr.sphere");
    node->shape = sceneBuilder(L).unitSphere;
    pushNode(L, node);
    return 1;
}

int grCube(lua_State* L) {
    checkArgCount(L, "gr.cube", 1, 1, "(name)");
    auto node = newNode(L, "gr.cube");
    node->shape = sceneBuilder(L).unitCube;
    pushNode(L, node);
    return 1;
}

int grNhSphere(lua_State* L) {
    // A non-hierarchical sphere is the unit sphere scaled by r and moved to the centre.
    checkArgCount(L, "gr.nh_sphere", 3, 3, "(name, {x,y,z}, radius)");
    auto node = newNode(L, "gr.nh_sphere");
    const Vec3 centre = checkVec3(L, 2, "gr.nh_sphere", "centre");
    const double radius = checkNumber(L, 3, "gr.nh_sphere", "radius");
    if (!(radius > 0.0))
        throw ArgumentError("gr.nh_sphere: argument 3 (radius) must be positive", 3);
    node->shape = sceneBuilder(L).unitSphere;
    node->shapeTransform = glm::scale(glm::translate(Mat4(1.0), centre), Vec3(radius));
    pushNode(L, node);
    return 1;
}

int grNhBox(lua_State* L) {
    // The tuple is the box's minimum corner, as in the course framework.
    checkArgCount(L, "gr.nh_box", 3, 3, "(name, {x,y,z}, size)");
    auto node = newNode(L, "gr.nh_box");
    const Vec3 corner = checkVec3(L, 2, "gr.nh_box", "minimum corner");
    const double size = checkNumber(L, 3, "gr.nh_box", "size");
    if (!(size > 0.0)) throw ArgumentError("gr.nh_box: argument 3 (size) must be positive", 3);
    node->shape = sceneBuilder(L).unitCube;
    node->shapeTransform = glm::scale(glm::translate(Mat4(1.0), corner), Vec3(size));
    pushNode(L, node);
    return 1;
}
// [lua-primitives]

// [lua-material-table]
/// raybook's own form: gr.material{kd = {..}, ks = {..}, shininess = n, reflect = r, ...}.
/// Every chapter's parameters are named fields; a field no built chapter reads is an error.
}  // namespace

int materialTable(lua_State* L) {
    auto m = std::make_shared<Material>();
    m->kd = Colour(0.0);
    m->ks = Colour(0.0);
    m->shininess = 1.0;
    lua_pushnil(L);
    while (lua_next(L, 1) != 0) {
        // The key is at -2, the value at -1.
        if (lua_type(L, -2) != LUA_TSTRING) {
            lua_pop(L, 2);
            throw ArgumentError("gr.material: the table's keys must be field names");
        }
        const std::string key = lua_tostring(L, -2);
        const int top = lua_gettop(L);
        const std::string label = "gr.material: field '" + key + "'";
        if (key == "kd" || key == "ks") {
            const auto c = checkTupleAt(L, top, 3, label);
            (key == "kd" ? m->kd : m->ks) = Vec3(c[0], c[1], c[2]);
        } else if (key == "emission") {
            // Chapter 18's emitting surfaces: a colour of radiance, each channel finite and ≥ 0.
            checkMaterialField(L, key, "gr.material");
            const auto c = checkTupleAt(L, top, 3, label);
            for (double v : c)
                if (!(v >= 0.0 && std::isfinite(v)))
                    throw ArgumentError(label + ": expected 3 finite numbers >= 0");
            m->emission = Vec3(c[0], c[1], c[2]);
        } else if (lua_type(L, -1) == LUA_TBOOLEAN) {
            setMaterialParam(L, *m, key, lua_toboolean(L, -1) ? 1.0 : 0.0, "gr.material");
        } else {
            const double v = checkNumberAt(L, top, label);
            if (key == "shininess")
                m->shininess = v;
            else
                setMaterialParam(L, *m, key, v, "gr.material");
        }
        lua_pop(L, 1);
    }
    pushMaterial(L, m);
    return 1;
}
// [lua-material-table]

int a4Material(lua_State* L) {
    if (lua_gettop(L) > 3 && lua_type(L, 4) == LUA_TSTRING)
        throw ArgumentError(
            "gr.material: more than 3 arguments is seed 000's dialect (\"reflect\", "
            "\"refract\", \"glossy\"), which needs chapter 4 (reflection) or later",
            4);
    checkArgCount(L, "gr.material", 3, 3, "(kd, ks, shininess)");
    auto m = std::make_shared<Material>();
    m->kd = checkVec3(L, 1, "gr.material", "kd");
    m->ks = checkVec3(L, 2, "gr.material", "ks");
    m->shininess = checkNumber(L, 3, "gr.material", "shininess");
    pushMaterial(L, m);
    return 1;
}

namespace {

int grMaterial(lua_State* L) {
    if (lua_gettop(L) == 1 && lua_type(L, 1) == LUA_TTABLE) return materialTable(L);
    return a4Material(L);
}

int grOption(lua_State* L) {
    // gr.option(name, value): a scene-wide setting (max_depth, light_samples, ...) for the
    // renders requested after it.
    checkArgCount(L, "gr.option", 2, 2, "(name, value)");
    const std::string name = checkString(L, 1, "gr.option", "name");
    SceneBuilder& builder = sceneBuilder(L);
    if (!builder.optionNames.count(name)) {
        std::string title;
        const int chapter = missingChapter(L, name, title);
        if (chapter)
            throw ArgumentError("gr.option: '" + name + "' needs chapter " +
                                std::to_string(chapter) + " (" + title +
                                "), which this build does not have");
        throw ArgumentError("gr.option: unknown option '" + name + "'");
    }
    setSceneOption(L, name, checkNumber(L, 2, "gr.option", "value"), "gr.option: '" + name + "'");
    return 0;
}

// ---- Lights -------------------------------------------------------------------------------

constexpr const char* kLightType = "rb.light";

int collectLight(lua_State* L) {
    // A new light may take a collected stand-in's address.
    sceneBuilder(L).standInLights.erase(lua_touserdata(L, 1));
    static_cast<PointLight*>(lua_touserdata(L, 1))->~PointLight();
    return 0;
}

int grLight(lua_State* L) {
    if (lua_gettop(L) == 6)
        throw ArgumentError(
            "gr.light: 6 arguments is seed 001's rectangular area light, which needs chapter 6 "
            "(soft_shadows)",
            4);
    checkArgCount(L, "gr.light", 3, 3, "(position, colour, {c0,c1,c2})");
    PointLight light;
    light.position = checkVec3(L, 1, "gr.light", "position");
    light.colour = checkVec3(L, 2, "gr.light", "colour");
    light.falloff = checkVec3(L, 3, "gr.light", "falloff");
    if (light.falloff.x < 0 || light.falloff.y < 0 || light.falloff.z < 0 ||
        !(light.falloff.x + light.falloff.y + light.falloff.z > 0))
        throw ArgumentError("gr.light: argument 3 (falloff) must be non-negative and not all zero",
                            3);
    pushLight(L, light);
    return 1;
}

// ---- Node methods -------------------------------------------------------------------------

/// The node a method is called on (argument 1), then exactly `count` more arguments.
/// Checking the node first turns n.translate(...) into a hint about the colon.
std::shared_ptr<SceneNode> checkSelf(lua_State* L, const char* call, int count,
                                     const char* signature) {
    auto node = checkNode(L, 1, call, "self");
    if (lua_gettop(L) - 1 > count) {
        // Extra arguments are what the course framework ignores: warn, then drop them.
        const int extra = lua_gettop(L) - 1 - count;
        sceneWarning(L, std::string(call) + " extra",
                     std::string(call) + ": ignored " + std::to_string(extra) + " extra argument" +
                         (extra == 1 ? "" : "s") + " after " + signature +
                         ", as the course framework does");
        lua_settop(L, count + 1);
    }
    if (lua_gettop(L) - 1 != count)
        throw ArgumentError(std::string(call) + " expects " + std::to_string(count) + " argument" +
                            (count == 1 ? "" : "s") + " " + signature + ", got " +
                            std::to_string(lua_gettop(L) - 1));
    return node;
}

/// True when a and b agree to within 1e-9 of their largest entry: products of the same
/// transforms in either order, differing only by rounding.
bool nearlyEqual(const Mat4& a, const Mat4& b) {
    double scale = 0.0, diff = 0.0;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) {
            scale = std::max({scale, std::abs(a[c][r]), std::abs(b[c][r])});
            diff = std::max(diff, std::abs(a[c][r] - b[c][r]));
        }
    return diff <= 1e-9 * std::max(scale, 1.0);
}

// [lua-transforms]
/// Apply a local transform: pre-multiplied (calls apply in the order written) in A4, and
/// post-multiplied for legacy (pre-2015) scenes, which list their transforms in reverse.
void applyTransform(lua_State* L, SceneNode& node, const Mat4& m) {
    SceneBuilder& builder = sceneBuilder(L);
    const Mat4 pre = m * node.transform, post = node.transform * m;
    // Note where the order first changes the result: only then does the era matter.
    if (builder.orderMatters.empty() && !nearlyEqual(pre, post) && !calledFromDialect(L))
        builder.orderMatters = luaCaller(L);
    node.transform = builder.legacy ? post : pre;
}

int nodeScale(lua_State* L) {
    auto node = checkSelf(L, "node:scale", 3, "(x, y, z)");
    const Vec3 s(checkNumber(L, 2, "node:scale", "x"), checkNumber(L, 3, "node:scale", "y"),
                 checkNumber(L, 4, "node:scale", "z"));
    if (s.x == 0.0 || s.y == 0.0 || s.z == 0.0)
        throw ArgumentError("node:scale: scale factors must be non-zero");
    notePlacement(L, node, 'S', glm::scale(Mat4(1.0), s));
    applyTransform(L, *node, glm::scale(Mat4(1.0), s));
    return 0;
}

int nodeTranslate(lua_State* L) {
    auto node = checkSelf(L, "node:translate", 3, "(x, y, z)");
    const Vec3 t(checkNumber(L, 2, "node:translate", "x"), checkNumber(L, 3, "node:translate", "y"),
                 checkNumber(L, 4, "node:translate", "z"));
    notePlacement(L, node, 'T', glm::translate(Mat4(1.0), t));
    applyTransform(L, *node, glm::translate(Mat4(1.0), t));
    return 0;
}

int nodeRotate(lua_State* L) {
    auto node = checkSelf(L, "node:rotate", 2, "(axis, degrees)");
    const std::string axisName = checkString(L, 2, "node:rotate", "axis");
    const double degrees = checkNumber(L, 3, "node:rotate", "degrees");
    Vec3 axis(0.0);
    if (axisName == "x" || axisName == "X")
        axis.x = 1.0;
    else if (axisName == "y" || axisName == "Y")
        axis.y = 1.0;
    else if (axisName == "z" || axisName == "Z")
        axis.z = 1.0;
    else
        throw ArgumentError("node:rotate: the axis must be 'x', 'y' or 'z', got '" + axisName + "'",
                            2);
    notePlacement(L, node, 'R', glm::rotate(Mat4(1.0), glm::radians(degrees), axis));
    applyTransform(L, *node, glm::rotate(Mat4(1.0), glm::radians(degrees), axis));
    return 0;
}
// [lua-transforms]

int nodeAddChild(lua_State* L) {
    auto parent = checkSelf(L, "node:add_child", 1, "(child)");
    auto child = checkNode(L, 2, "node:add_child", "child");
    // Instancing makes the graph a DAG; a cycle would make it infinite. The nodes the check
    // visits count as the script's instructions: adding ever new parents above a large graph
    // would otherwise take quadratic time that no Lua instruction limit sees.
    size_t visited = 0;
    const bool cycle = reaches(*child, parent.get(), &visited);
    // A visit (a hash-set insert and a pointer chase) takes about as long as 100 Lua
    // instructions: a loop of them should hit the limit in about the same time.
    chargeInstructions(L, 100 * visited, "node:add_child");
    if (cycle)
        throw InputError("node:add_child: adding '" + child->name + "' under '" + parent->name +
                         "' would make a cycle in the scene graph");
    parent->children.push_back(child);
    return 0;
}

int nodeSetMaterial(lua_State* L) {
    auto node = checkSelf(L, "node:set_material", 1, "(material)");
    node->material = checkMaterial(L, 2, "node:set_material", "material");
    return 0;
}

// ---- gr.render ----------------------------------------------------------------------------

/// Copy the graph under root, keeping shared children shared, so later edits by the script
/// do not change a render that was already requested.
std::shared_ptr<SceneNode> snapshot(const std::shared_ptr<SceneNode>& node,
                                    std::map<const SceneNode*, std::shared_ptr<SceneNode>>& done) {
    auto it = done.find(node.get());
    if (it != done.end()) return it->second;
    auto copy = std::make_shared<SceneNode>(*node);
    for (auto& child : copy->children) child = snapshot(child, done);
    done[node.get()] = copy;
    return copy;
}

int integerArg(lua_State* L, int arg, const char* name) {
    const double v = checkNumber(L, arg, "gr.render", name);
    if (v != std::floor(v) || std::abs(v) > 1e9)
        throw ArgumentError(std::string("gr.render: argument ") + std::to_string(arg) + " (" +
                                name + ") must be a whole number",
                            arg);
    return static_cast<int>(v);
}

/// True for a whole number from 0 to `hi`.
bool wholeUpTo(double v, double hi) {
    return v >= 0.0 && v <= hi && v == std::floor(v);
}

/// Under --lenient, check seed 001's trailing values now, where a value outside what its
/// chapters read can still be left out (they check them again when the render starts, for
/// scenes read strictly): other courses put samples, depths and apertures there.
void checkSeed001Values(lua_State* L) {
    const int n = lua_gettop(L);
    const auto refuse = [](int arg, const char* what) {
        throw ArgumentError("gr.render: argument " + std::to_string(arg) + " " + what, arg);
    };
    if (n >= 11 && lua_tonumber(L, 11) != 0.0 && lua_tonumber(L, 11) != 1.0)
        refuse(11, "(aa) must be 0 (off) or 1 (on)");
    if (n >= 12 && !wholeUpTo(lua_tonumber(L, 12), 256))
        refuse(12, "(ss) must be a whole number of samples per axis from 0 to 256");
    if (n >= 13 && !wholeUpTo(lua_tonumber(L, 13), 256))
        refuse(13, "(dist) must be a whole number from 0 to 256");
    if (n >= 14) {
        const auto dof = checkTuple(L, 14, 3, "gr.render", "{aperture, focalLength, dof}");
        // The aperture and focal length matter only when dof asks for rays through the lens.
        if (!wholeUpTo(dof[2], 256) || (dof[2] > 0.0 && (!(dof[0] >= 0.0) || !(dof[1] > 0.0))))
            refuse(14,
                   "({aperture, focalLength, dof}) must be an aperture of 0 or more, a "
                   "focal length above 0 and a whole number of samples from 0 to 256");
    }
}

// [lua-render]
int grRender(lua_State* L) {
    const int given = lua_gettop(L);
    checkArgCount(L, "gr.render", 10, 14,
                  "(root, file, width, height, eye, view, up, fovy, ambient, lights"
                  " [, aa, ss, dist, {aperture, focal, dof}])");
    LoadedRender r;
    RenderJob& job = r.job;
    job.options = sceneBuilder(L).sceneOptions;
    job.fog = sceneBuilder(L).fog;
    // The scene's line, also when the call is read again from C (--lenient) or made through
    // pcall: never "[C]:-1".
    job.where = luaCaller(L);
    auto root = checkNode(L, 1, "gr.render", "root");
    job.output = checkString(L, 2, "gr.render", "file");
    job.width = integerArg(L, 3, "width");
    job.height = integerArg(L, 4, "height");
    checkImageSize(job.width, job.height, "gr.render: ");
    job.camera.eye = checkVec3(L, 5, "gr.render", "eye");
    job.camera.view = checkVec3(L, 6, "gr.render", "view");
    job.camera.up = checkVec3(L, 7, "gr.render", "up");
    job.camera.fovyDegrees = checkNumber(L, 8, "gr.render", "fovy");
    (void)PinholeCamera(job.camera, job.width, job.height);  // validates view, up and fovy
    job.ambient = checkVec3(L, 9, "gr.render", "ambient");
    job.lights = checkLights(L, 10);
    // Seed 001's extra arguments; their chapters (adaptive AA, soft shadows, glossy, DOF)
    // read them.
    // Only seed 001's whole form, ending in its {aperture, focalLength, dof} triple, tells
    // the era: students of every era add samples, depth or aperture after the ten.
    if (given == 14 && lua_type(L, 14) == LUA_TTABLE && lua_rawlen(L, 14) == 3)
        noteEraSign(L, Era::Legacy, "seed 001's gr.render with 14 arguments");
    if (lua_gettop(L) >= 11) job.options["aa"] = checkNumber(L, 11, "gr.render", "aa");
    if (lua_gettop(L) >= 12) job.options["ss"] = checkNumber(L, 12, "gr.render", "ss");
    if (lua_gettop(L) >= 13) job.options["dist"] = checkNumber(L, 13, "gr.render", "dist");
    if (lua_gettop(L) >= 14) {
        const auto dof = checkTuple(L, 14, 3, "gr.render", "{aperture, focalLength, dof}");
        job.options["aperture"] = dof[0];
        job.options["focal_length"] = dof[1];
        job.options["dof"] = dof[2];
    }
    if (sceneBuilder(L).options.lenient) checkSeed001Values(L);
    // Freeze the graph as it is now and flatten it, so errors point at this line. Both
    // recurse once per level: refuse a graph too deep for that first.
    checkGraphDepth(*root);
    std::map<const SceneNode*, std::shared_ptr<SceneNode>> copies;
    auto frozen = snapshot(root, copies);
    r.snapshot = frozen;
    r.fallback = sceneBuilder(L).defaultMaterial;
    r.instances = flatten(*frozen, r.fallback.get(), &r.builtShapes, sceneBuilder(L).featuresOn,
                          &r.leftOutOperands);
    job.root = frozen;
    // Copying and flattening the graph is work done for the script, as are its instances.
    chargeInstructions(L, copies.size() + r.instances.size(), "gr.render");
    chargeMemory(L, copies.size() * sizeof(SceneNode) + r.instances.size() * sizeof(Instance));
    noteStandInLighting(L, 10);
    sceneBuilder(L).renders.push_back(std::move(r));
    return 0;
}
// [lua-render]

}  // namespace

void pushLight(lua_State* L, const PointLight& light) {
    void* mem = lua_newuserdatauv(L, sizeof(PointLight), 0);
    new (mem) PointLight(light);
    luaL_setmetatable(L, kLightType);
}

PointLight checkLight(lua_State* L, int arg, const char* call, const char* argName) {
    void* p = luaL_testudata(L, arg, kLightType);
    if (!p)
        throw ArgumentError(std::string(call) + ": " + argName + " is not a light made by gr.light",
                            arg);
    return *static_cast<PointLight*>(p);
}

std::vector<PointLight> checkLights(lua_State* L, int arg) {
    if (lua_type(L, arg) != LUA_TTABLE)
        throw ArgumentError(
            "gr.render: argument " + std::to_string(arg) + " (lights) must be a table of lights",
            arg);
    const lua_Unsigned n = lua_rawlen(L, arg);
    // A path-traced scene (chapter 18) may be lit by its emitting surfaces alone.
    const auto& options = sceneBuilder(L).sceneOptions;
    const auto path = options.find("integrator_path");
    if (n == 0 && (path == options.end() || path->second == 0.0))
        throw ArgumentError("gr.render: argument " + std::to_string(arg) +
                                " (lights) is empty; a scene needs at least one light (or, "
                                "path traced, an emitting surface)",
                            arg);
    std::vector<PointLight> lights;
    for (lua_Unsigned i = 1; i <= n; ++i) {
        lua_rawgeti(L, arg, static_cast<lua_Integer>(i));
        const int top = lua_gettop(L);
        try {
            lights.push_back(checkLight(
                L, top, "gr.render",
                ("argument " + std::to_string(arg) + " (lights): element " + std::to_string(i))
                    .c_str()));
        } catch (const ArgumentError& e) {
            // The element is read from a slot above the arguments: the lights are at fault.
            lua_pop(L, 1);
            throw ArgumentError(e.what(), arg);
        } catch (...) {
            lua_pop(L, 1);
            throw;
        }
        lua_pop(L, 1);
    }
    return lights;
}

void bindA4(LuaBindings& lua) {
    lua_State* L = lua.state();
    luaL_newmetatable(L, kLightType);
    lua_pushcfunction(L, collectLight);
    lua_setfield(L, -2, "__gc");
    lua_pop(L, 1);
    lua.function("node", luaGuard<grNode>);
    lua.function("joint", luaGuard<grJoint>);
    lua.function("sphere", luaGuard<grSphere>);
    lua.function("cube", luaGuard<grCube>);
    lua.function("nh_sphere", luaGuard<grNhSphere>);
    lua.function("nh_box", luaGuard<grNhBox>);
    lua.function("material", luaGuard<grMaterial>);
    lua.function("light", luaGuard<grLight>);
    lua.function("render", luaGuard<grRender>);
    lua.function("option", luaGuard<grOption>);
    lua.option("max_depth", 4, 0, 1000, true);
    lua.option("min_weight", 4, 0, 1, false);
    // Rendering to an error (--target-error): the target, its floor and its ceiling.
    lua.option("target_error", 1, 1e-9, 1e9, false);
    lua.option("min_spp", 1, kTargetMinSamples, kTargetMaxSamples, true);
    lua.option("max_spp", 1, kTargetMinSamples, kTargetMaxSamples, true);
    lua.nodeMethod("add_child", luaGuard<nodeAddChild>);
    lua.nodeMethod("set_material", luaGuard<nodeSetMaterial>);
    lua.nodeMethod("scale", luaGuard<nodeScale>);
    lua.nodeMethod("translate", luaGuard<nodeTranslate>);
    lua.nodeMethod("rotate", luaGuard<nodeRotate>);
}

// ---- The era's idiom -----------------------------------------------------------------------

namespace {

/// Add a run of `kind` to `order` (a run of the same kind only grows the run); note where
/// the second run began. Three runs tell no more than an ambiguous order: stop there.
void addRun(std::string& order, std::string& where, char kind, lua_State* L) {
    if (!order.empty() && order.back() == kind) return;
    if (order.size() >= 3) return;
    order += kind;
    if (order.size() == 2) where = luaCaller(L);
}

}  // namespace

void notePlacement(lua_State* L, const std::shared_ptr<SceneNode>& node, char kind, const Mat4& m) {
    // A dialect's calls are the TA's, not the student's: they tell nothing of the era.
    if (calledFromDialect(L)) return;
    SceneBuilder& builder = sceneBuilder(L);
    auto [it, added] = builder.placements.try_emplace(node.get());
    SceneBuilder::Placement& p = it->second;
    if (!added && p.node.lock() != node) {
        // A new node at a collected one's address: keep the old one's vote.
        builder.pastPlacements.push_back(std::move(p));
        p = SceneBuilder::Placement{};
        added = true;
    }
    if (added) {
        p.node = node;
        p.first = builder.placingCalls;
    }
    ++builder.placingCalls;
    if (kind != 'R') addRun(p.translateScale, p.whereTS, kind, L);
    if (kind != 'T') addRun(p.rotateScale, p.whereRS, kind, L);
    Mat4& product = kind == 'S' ? p.scale : kind == 'R' ? p.rotation : p.translation;
    product *= m;
}

void restartPlacement(lua_State* L, const SceneNode* node) {
    SceneBuilder& builder = sceneBuilder(L);
    auto it = builder.placements.find(node);
    if (it == builder.placements.end()) return;
    builder.pastPlacements.push_back(std::move(it->second));
    builder.placements.erase(it);
}

EraIdiom placementIdiom(const SceneBuilder& builder) {
    std::vector<const SceneBuilder::Placement*> all;
    for (const auto& p : builder.pastPlacements) all.push_back(&p);
    for (const auto& [node, p] : builder.placements) all.push_back(&p);
    // In the order the nodes were first placed, so the first place named is the script's first.
    std::sort(all.begin(), all.end(), [](auto* a, auto* b) { return a->first < b->first; });
    EraIdiom idiom;
    const auto vote = [&](bool legacy, const std::string& where) {
        if ((legacy ? idiom.legacyVotes : idiom.modernVotes)++ == 0)
            (legacy ? idiom.firstLegacy : idiom.firstModern) = where;
    };
    for (const SceneBuilder::Placement* p : all) {
        const std::string& rs = p->rotateScale;
        const std::string& ts = p->translateScale;
        if (!nearlyEqual(p->rotation * p->scale, p->scale * p->rotation)) {
            // A non-uniform scale and a rotation: which came first decides, if one did.
            if (rs == "RS" || rs == "SR") vote(rs == "RS", p->whereRS);
        } else if ((ts == "TS" || ts == "ST") &&
                   !nearlyEqual(p->translation * p->scale, p->scale * p->translation)) {
            vote(ts == "TS", p->whereTS);
        }
    }
    return idiom;
}

}  // namespace rb

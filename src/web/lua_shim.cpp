// The Lua C API for the WebAssembly build of rt (src/web/README.md): the part of Lua 5.4's
// C API that raybook's scene language uses, over a value store of our own, with the scene
// script itself run by the page's Lua (wasmoon, Lua 5.4 compiled to WebAssembly).
//
// Why: neither Debian nor the npm registry ships Lua 5.4's C sources to compile to WebAssembly,
// and wasmoon's Lua lives in a WebAssembly module of its own, whose memory rt's C++ cannot
// share. So the gr calls (src/scene, each chapter's lua_*.cpp) compile unchanged against
// Debian's lua.h, and this file answers their lua_* and luaL_* calls. Tables, userdata and C
// functions that C++ makes live here; the script's own values live in the page's Lua. A value
// that crosses is copied (nil, booleans, numbers, strings, and the script's plain tables) or
// named by a handle (our tables, userdata and C functions; the page's functions). The page's
// side of the bridge is src/web/lua_host.js.
//
// The native build never compiles this file: it links Debian's liblua5.4.
#include <emscripten.h>

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <lua.hpp>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

namespace {

struct Table;
struct Userdata;
struct Function;

/// One Lua value. Strings are shared so that a char* from lua_tolstring stays valid while the
/// value is on the stack.
struct Value {
    int type = LUA_TNIL;
    bool isInteger = false;
    bool boolean = false;
    lua_Integer integer = 0;
    lua_Number number = 0.0;
    void* light = nullptr;
    std::shared_ptr<const std::string> string;
    std::shared_ptr<Table> table;
    std::shared_ptr<Userdata> userdata;
    std::shared_ptr<Function> function;
};

Value nilValue() {
    return Value{};
}
Value numberValue(lua_Number n) {
    Value v;
    v.type = LUA_TNUMBER;
    v.number = n;
    return v;
}
Value integerValue(lua_Integer i) {
    Value v;
    v.type = LUA_TNUMBER;
    v.isInteger = true;
    v.integer = i;
    v.number = static_cast<lua_Number>(i);
    return v;
}
Value stringValue(std::string s) {
    Value v;
    v.type = LUA_TSTRING;
    v.string = std::make_shared<const std::string>(std::move(s));
    return v;
}
Value booleanValue(bool b) {
    Value v;
    v.type = LUA_TBOOLEAN;
    v.boolean = b;
    return v;
}

/// A key as a string that compares as Lua compares keys (a float with an integer value is that
/// integer).
std::string keyOf(const Value& v) {
    switch (v.type) {
        case LUA_TNUMBER:
            if (v.isInteger) return "i" + std::to_string(v.integer);
            if (std::floor(v.number) == v.number && std::abs(v.number) < 9.2e18)
                return "i" + std::to_string(static_cast<lua_Integer>(v.number));
            {
                char buf[40];
                std::snprintf(buf, sizeof buf, "n%a", v.number);
                return buf;
            }
        case LUA_TSTRING:
            return "s" + *v.string;
        case LUA_TBOOLEAN:
            return v.boolean ? "b1" : "b0";
        case LUA_TLIGHTUSERDATA:
            return "l" + std::to_string(reinterpret_cast<uintptr_t>(v.light));
        case LUA_TTABLE:
            return "t" + std::to_string(reinterpret_cast<uintptr_t>(v.table.get()));
        case LUA_TUSERDATA:
            return "u" + std::to_string(reinterpret_cast<uintptr_t>(v.userdata.get()));
        case LUA_TFUNCTION:
            return "f" + std::to_string(reinterpret_cast<uintptr_t>(v.function.get()));
    }
    return "z";
}

/// A table: its entries in insertion order (lua_next walks them so), found by key.
struct Table {
    std::vector<std::pair<Value, Value>> entries;
    std::unordered_map<std::string, size_t> index;
    std::shared_ptr<Table> meta;

    Value get(const Value& key) const {
        auto it = index.find(keyOf(key));
        return it == index.end() ? nilValue() : entries[it->second].second;
    }
    void set(const Value& key, const Value& value) {
        const std::string k = keyOf(key);
        auto it = index.find(k);
        if (it != index.end()) {
            entries[it->second].second = value;
        } else if (value.type != LUA_TNIL) {
            index.emplace(k, entries.size());
            entries.emplace_back(key, value);
        }
    }
    /// The border Lua's # finds for a sequence.
    lua_Integer length() const {
        lua_Integer n = 0;
        while (get(integerValue(n + 1)).type != LUA_TNIL) ++n;
        return n;
    }
};

/// A full userdata: its block, its metatable and its user values.
struct Userdata {
    std::unique_ptr<std::max_align_t[]> block;
    size_t size = 0;
    std::shared_ptr<Table> meta;
    std::vector<Value> userValues;
};

/// A C function with its upvalues, or a function of the page's Lua (hostRef > 0).
struct Function {
    lua_CFunction c = nullptr;
    std::vector<Value> upvalues;
    int hostRef = 0;
};

/// What is running: a C function, or the page's Lua code that called it (its file and line).
struct Frame {
    size_t base = 0;  ///< Stack index of the frame's first argument.
    Value function;
    bool isLua = false;
    std::string source, shortSrc;
    int line = -1;
};

/// A Lua error in flight: lua_error throws it, lua_pcall and the bridge catch it.
struct LuaThrow {
    Value value;
    int status;
};

}  // namespace

/// The state: a stack of values and frames, the registry, and the hook. lua_getextraspace
/// points just before it.
struct lua_State {
    std::vector<Value> stack;
    std::vector<Frame> frames;
    std::shared_ptr<Table> registry;
    lua_Hook hook = nullptr;
    int hookCount = 0;
    std::vector<std::shared_ptr<Userdata>> allUserdata;  ///< For __gc at lua_close.
    std::vector<Value> handles;                          ///< Values the page's Lua holds.
    std::unordered_map<std::string, int> handleOf;
    std::map<const luaL_Buffer*, std::string> buffers;
};

// ---- The page's side (src/web/lua_host.js) --------------------------------------------------

EM_JS(void, rbHostOpen, (lua_State * L), { Module.luaHost.open(L, Module); });
EM_JS(void, rbHostClose, (lua_State * L), { Module.luaHost.close(L); });
EM_JS(char*, rbHostRequest, (lua_State * L, const char* op, int ref, const char* data, int size), {
    const text = Module.luaHost.request(L, UTF8ToString(op), ref, UTF8ToString(data, size));
    const bytes = lengthBytesUTF8(text) + 1;
    const out = _malloc(bytes);
    stringToUTF8(text, out, bytes);
    return out;
});

namespace {

// ---- Stack access -------------------------------------------------------------------------

Frame& frame(lua_State* L) {
    return L->frames.back();
}
size_t base(lua_State* L) {
    return frame(L).base;
}
int top(lua_State* L) {
    return static_cast<int>(L->stack.size() - base(L));
}

bool isUpvalueIndex(int idx) {
    return idx < LUA_REGISTRYINDEX;
}

/// The stack slot of an index (not a pseudo-index).
size_t slot(lua_State* L, int idx) {
    if (idx > 0) return base(L) + static_cast<size_t>(idx) - 1;
    return L->stack.size() + static_cast<size_t>(idx);  // idx < 0
}

Value get(lua_State* L, int idx) {
    if (idx == LUA_REGISTRYINDEX) {
        Value v;
        v.type = LUA_TTABLE;
        v.table = L->registry;
        return v;
    }
    if (isUpvalueIndex(idx)) {
        const size_t n = static_cast<size_t>(LUA_REGISTRYINDEX - idx);
        const Value& f = frame(L).function;
        if (f.function && n >= 1 && n <= f.function->upvalues.size())
            return f.function->upvalues[n - 1];
        return nilValue();
    }
    if (idx > 0 && idx > top(L)) return nilValue();  // an acceptable index beyond the top
    return L->stack[slot(L, idx)];
}

void set(lua_State* L, int idx, const Value& v) {
    if (isUpvalueIndex(idx)) {
        const size_t n = static_cast<size_t>(LUA_REGISTRYINDEX - idx);
        frame(L).function.function->upvalues.at(n - 1) = v;
        return;
    }
    L->stack[slot(L, idx)] = v;
}

void push(lua_State* L, Value v) {
    L->stack.push_back(std::move(v));
}
Value pop(lua_State* L) {
    Value v = std::move(L->stack.back());
    L->stack.pop_back();
    return v;
}

[[noreturn]] void raise(lua_State*, const std::string& message) {
    throw LuaThrow{stringValue(message), LUA_ERRRUN};
}

/// Lua's number to string: integers as %d, floats as %.14g with ".0" when they look whole.
std::string numberText(const Value& v) {
    if (v.isInteger) return std::to_string(v.integer);
    char buf[64];
    std::snprintf(buf, sizeof buf, LUA_NUMBER_FMT, v.number);
    std::string s = buf;
    if (s.find_first_not_of("-0123456789") == std::string::npos) s += ".0";
    return s;
}

/// Lua's string to number (decimal or hex, integer or float); false when it is not one.
bool textNumber(const std::string& s, Value& out) {
    const char* p = s.c_str();
    while (std::isspace(static_cast<unsigned char>(*p))) ++p;
    if (!*p) return false;
    char* end = nullptr;
    const bool hex = (p[0] == '0' && (p[1] == 'x' || p[1] == 'X')) ||
                     ((p[0] == '-' || p[0] == '+') && p[1] == '0' && (p[2] == 'x' || p[2] == 'X'));
    if (!std::strpbrk(p, ".eEpPnN") || (hex && !std::strpbrk(p + 2, ".pP"))) {
        errno = 0;
        const long long i = std::strtoll(p, &end, hex ? 16 : 10);
        while (end && std::isspace(static_cast<unsigned char>(*end))) ++end;
        if (end && !*end && errno == 0) {
            out = integerValue(i);
            return true;
        }
    }
    const double d = std::strtod(p, &end);
    if (end == p) return false;
    while (std::isspace(static_cast<unsigned char>(*end))) ++end;
    if (*end || std::strpbrk(p, "nN")) return false;  // no "nan" or "inf" in Lua
    out = numberValue(d);
    return true;
}

std::shared_ptr<Table> metatableOf(const Value& v) {
    if (v.type == LUA_TTABLE) return v.table->meta;
    if (v.type == LUA_TUSERDATA) return v.userdata->meta;
    return nullptr;
}

Value call(lua_State* L, const Value& f, std::vector<Value> args, int nresults,
           std::vector<Value>* results = nullptr);

/// t[k] with __index, as lua_gettable.
Value index(lua_State* L, const Value& t, const Value& k, int depth = 0) {
    if (depth > 100) raise(L, "'__index' chain too long; possible loop");
    if (t.type == LUA_TTABLE) {
        Value v = t.table->get(k);
        if (v.type != LUA_TNIL) return v;
    }
    const auto meta = metatableOf(t);
    const Value handler = meta ? meta->get(stringValue("__index")) : nilValue();
    if (handler.type == LUA_TNIL) {
        if (t.type == LUA_TTABLE) return nilValue();
        raise(L, std::string("attempt to index a ") + lua_typename(L, t.type) + " value");
    }
    if (handler.type == LUA_TFUNCTION) {
        std::vector<Value> out;
        call(L, handler, {t, k}, 1, &out);
        return out.empty() ? nilValue() : out[0];
    }
    return index(L, handler, k, depth + 1);
}

/// t[k] = v with __newindex, as lua_settable.
void newIndex(lua_State* L, const Value& t, const Value& k, const Value& v) {
    if (t.type == LUA_TTABLE) {
        if (t.table->get(k).type != LUA_TNIL || !t.table->meta ||
            t.table->meta->get(stringValue("__newindex")).type == LUA_TNIL) {
            if (k.type == LUA_TNIL) raise(L, "index is nil");
            t.table->set(k, v);
            return;
        }
    }
    const auto meta = metatableOf(t);
    const Value handler = meta ? meta->get(stringValue("__newindex")) : nilValue();
    if (handler.type == LUA_TNIL)
        raise(L, std::string("attempt to index a ") + lua_typename(L, t.type) + " value");
    if (handler.type == LUA_TFUNCTION) {
        call(L, handler, {t, k, v}, 0);
        return;
    }
    newIndex(L, handler, k, v);
}

Value globals(lua_State* L) {
    return L->registry->get(integerValue(LUA_RIDX_GLOBALS));
}

// ---- The bridge's encoding ----------------------------------------------------------------
// Values travel as text: z nil, t/f booleans, i<int>; integers, n<%a>; floats, s<bytes>:<text>
// strings, h<id>; our tables, userdata and functions (a handle the page holds), r<id>; the
// page's own functions, T<count>; a table of the page's, copied, followed by its key, value
// pairs.

int handleFor(lua_State* L, const Value& v) {
    const std::string k = keyOf(v);
    auto it = L->handleOf.find(k);
    if (it != L->handleOf.end()) return it->second;
    L->handles.push_back(v);
    const int id = static_cast<int>(L->handles.size());
    L->handleOf.emplace(k, id);
    return id;
}

void encode(lua_State* L, const Value& v, std::string& out) {
    char buf[64];
    switch (v.type) {
        case LUA_TNIL:
            out += 'z';
            return;
        case LUA_TBOOLEAN:
            out += v.boolean ? 't' : 'f';
            return;
        case LUA_TNUMBER:
            if (v.isInteger) {
                out += "i" + std::to_string(v.integer) + ";";
            } else {
                std::snprintf(buf, sizeof buf, "n%a;", v.number);
                out += buf;
            }
            return;
        case LUA_TSTRING:
            out += "s" + std::to_string(v.string->size()) + ":" + *v.string;
            return;
        case LUA_TFUNCTION:
            if (v.function->hostRef > 0) {
                out += "r" + std::to_string(v.function->hostRef) + ";";
                return;
            }
            [[fallthrough]];
        default:
            out += "h" + std::to_string(handleFor(L, v)) + ";";
    }
}

long long readInteger(const char*& p, char end) {
    char* stop = nullptr;
    const long long i = std::strtoll(p, &stop, 10);
    p = stop;
    if (*p == end) ++p;
    return i;
}

Value decode(lua_State* L, const char*& p) {
    const char tag = *p++;
    switch (tag) {
        case 'z':
            return nilValue();
        case 't':
            return booleanValue(true);
        case 'f':
            return booleanValue(false);
        case 'i':
            return integerValue(readInteger(p, ';'));
        case 'n': {
            char* stop = nullptr;
            const double d = std::strtod(p, &stop);
            p = stop;
            if (*p == ';') ++p;
            return numberValue(d);
        }
        case 's': {
            const size_t n = static_cast<size_t>(readInteger(p, ':'));
            std::string s(p, n);
            p += n;
            return stringValue(std::move(s));
        }
        case 'h': {
            const long long id = readInteger(p, ';');
            if (id < 1 || id > static_cast<long long>(L->handles.size())) return nilValue();
            return L->handles[static_cast<size_t>(id - 1)];
        }
        case 'r': {
            Value v;
            v.type = LUA_TFUNCTION;
            v.function = std::make_shared<Function>();
            v.function->hostRef = static_cast<int>(readInteger(p, ';'));
            return v;
        }
        case 'T': {
            const long long n = readInteger(p, ';');
            Value v;
            v.type = LUA_TTABLE;
            v.table = std::make_shared<Table>();
            for (long long k = 0; k < n; ++k) {
                Value key = decode(L, p);
                Value value = decode(L, p);
                v.table->set(key, value);
            }
            return v;
        }
    }
    return nilValue();
}

std::vector<Value> decodeAll(lua_State* L, const std::string& text) {
    std::vector<Value> values;
    const char* p = text.c_str();
    const char* end = p + text.size();
    while (p < end) values.push_back(decode(L, p));
    return values;
}

/// Ask the page's Lua: op is "load", "call", "lib", "hook" or "upvalue"; the answer is
/// "O" and values, or "E" and the error value, or "M" and the error for a lack of memory.
std::vector<Value> request(lua_State* L, const char* op, int ref, const std::string& data) {
    char* answer = rbHostRequest(L, op, ref, data.data(), static_cast<int>(data.size()));
    const std::string text = answer;
    std::free(answer);
    std::vector<Value> values = decodeAll(L, text.substr(1));
    if (text[0] == 'O') return values;
    throw LuaThrow{values.empty() ? nilValue() : values[0],
                   text[0] == 'M' ? LUA_ERRMEM : LUA_ERRRUN};
}

// ---- Calls --------------------------------------------------------------------------------

/// Call f with args; keep nresults results (all with LUA_MULTRET) in *results.
Value call(lua_State* L, const Value& f, std::vector<Value> args, int nresults,
           std::vector<Value>* results) {
    std::vector<Value> out;
    if (f.type == LUA_TFUNCTION && f.function->hostRef > 0) {
        std::string data;
        for (const Value& a : args) encode(L, a, data);
        out = request(L, "call", f.function->hostRef, data);
    } else if (f.type == LUA_TFUNCTION) {
        const size_t frames = L->frames.size();
        Frame fr;
        fr.base = L->stack.size();
        fr.function = f;
        L->frames.push_back(fr);
        for (Value& a : args) push(L, std::move(a));
        int n = 0;
        try {
            n = f.function->c(L);
        } catch (...) {
            L->stack.resize(fr.base);
            L->frames.resize(frames);
            throw;
        }
        out.assign(L->stack.end() - n, L->stack.end());
        L->stack.resize(fr.base);
        L->frames.resize(frames);
    } else {
        raise(L, std::string("attempt to call a ") + lua_typename(L, f.type) + " value");
    }
    if (nresults != LUA_MULTRET) out.resize(static_cast<size_t>(nresults));
    if (results) *results = std::move(out);
    return nilValue();
}

/// lua_call's work: the function and its nargs arguments at the top become its results.
void callAtTop(lua_State* L, int nargs, int nresults) {
    const size_t fslot = L->stack.size() - static_cast<size_t>(nargs) - 1;
    const Value f = L->stack[fslot];
    std::vector<Value> args(L->stack.begin() + static_cast<long>(fslot) + 1, L->stack.end());
    L->stack.resize(fslot);
    std::vector<Value> results;
    call(L, f, std::move(args), nresults, &results);
    for (Value& r : results) push(L, std::move(r));
}

}  // namespace

// ---- Entry points for the page's Lua ------------------------------------------------------

/// The page's Lua calls into C: op is "call" (handle: a function; data: the arguments),
/// "index" (data: key), "newindex" (data: key, value), "next" (data: key), "len", or "hook"
/// (the count hook). The data begins with where the page's Lua code is. Returns "O" and
/// results, or "E" and an error value; free() it.
extern "C" EMSCRIPTEN_KEEPALIVE char* rb_shim_op(lua_State* L, const char* op, int handle,
                                                 const char* data, int size) {
    std::string answer;
    const size_t stackSize = L->stack.size();
    const size_t frames = L->frames.size();
    try {
        std::vector<Value> args = decodeAll(L, std::string(data, static_cast<size_t>(size)));
        const Value target = handle > 0 && handle <= static_cast<int>(L->handles.size())
                                 ? L->handles[static_cast<size_t>(handle - 1)]
                                 : nilValue();
        const std::string what = op;
        std::vector<Value> results;
        // Where the page's Lua code is: a count, then (source, short source, line) for each of
        // its frames, outermost first. A C function called from it sees them as levels 1, 2.
        const size_t count = args.empty() ? 0 : static_cast<size_t>(args[0].integer);
        if (args.size() < 1 + 3 * count) raise(L, "rb_shim_op: no caller");
        for (size_t k = 0; k < count; ++k) {
            const Value* f = &args[1 + 3 * k];
            Frame lua;
            lua.base = L->stack.size();
            lua.isLua = true;
            lua.source = f[0].string ? *f[0].string : "=[C]";
            lua.shortSrc = f[1].string ? *f[1].string : "[C]";
            lua.line = static_cast<int>(f[2].isInteger ? f[2].integer : -1);
            L->frames.push_back(lua);
        }
        args.erase(args.begin(), args.begin() + static_cast<long>(1 + 3 * count));
        if (what == "call") {
            call(L, target, std::move(args), LUA_MULTRET, &results);
        } else if (what == "index") {
            results.push_back(index(L, target, args.at(0)));
        } else if (what == "newindex") {
            newIndex(L, target, args.at(0), args.at(1));
        } else if (what == "next") {
            // The entry after key args[0] (nil: the first), for pairs() on our tables.
            if (target.type != LUA_TTABLE) raise(L, "bad argument to 'next' (table expected)");
            push(L, target);
            push(L, args.at(0));
            if (lua_next(L, -2)) {
                results.push_back(L->stack[L->stack.size() - 2]);
                results.push_back(L->stack.back());
            }
        } else if (what == "len") {
            results.push_back(target.type == LUA_TTABLE ? integerValue(target.table->length())
                                                        : integerValue(0));
        } else if (what == "hook") {
            if (L->hook) {
                lua_Debug ar{};
                ar.event = LUA_HOOKCOUNT;
                ar.i_ci = reinterpret_cast<CallInfo*>(L->frames.size());
                L->hook(L, &ar);
            }
        }
        answer = "O";
        for (const Value& r : results) encode(L, r, answer);
    } catch (const LuaThrow& e) {
        answer = e.status == LUA_ERRMEM ? "M" : "E";
        encode(L, e.value, answer);
    } catch (const std::bad_alloc&) {
        answer = "Ms17:not enough memory";
    } catch (const std::exception& e) {
        answer = "E";
        encode(L, stringValue(std::string("C++ exception: ") + e.what()), answer);
    }
    L->stack.resize(stackSize);
    L->frames.resize(frames);
    char* out = static_cast<char*>(std::malloc(answer.size() + 1));
    std::memcpy(out, answer.c_str(), answer.size() + 1);
    return out;
}

/// The handle of the globals table, for the page's Lua to use as the scripts' _ENV.
extern "C" EMSCRIPTEN_KEEPALIVE int rb_shim_globals(lua_State* L) {
    return handleFor(L, globals(L));
}

// ---- The state ----------------------------------------------------------------------------

extern "C" {

lua_State* lua_newstate(lua_Alloc, void*) {
    void* block = std::malloc(LUA_EXTRASPACE + sizeof(lua_State));
    if (!block) return nullptr;
    std::memset(block, 0, LUA_EXTRASPACE);
    auto* L = new (static_cast<char*>(block) + LUA_EXTRASPACE) lua_State();
    L->registry = std::make_shared<Table>();
    Value g;
    g.type = LUA_TTABLE;
    g.table = std::make_shared<Table>();
    L->registry->set(integerValue(LUA_RIDX_GLOBALS), g);
    L->frames.push_back(Frame{});
    rbHostOpen(L);
    return L;
}

/// A state with the default allocator (rt --batch parses files with one).
lua_State* luaL_newstate() {
    return lua_newstate(nullptr, nullptr);
}

void lua_close(lua_State* L) {
    // __gc, newest first, as Lua finalises at close.
    for (auto it = L->allUserdata.rbegin(); it != L->allUserdata.rend(); ++it) {
        if (!(*it)->meta) continue;
        Value gc = (*it)->meta->get(stringValue("__gc"));
        if (gc.type != LUA_TFUNCTION) continue;
        Value u;
        u.type = LUA_TUSERDATA;
        u.userdata = *it;
        try {
            call(L, gc, {u}, 0);
        } catch (...) {
        }
    }
    rbHostClose(L);
    void* block = reinterpret_cast<char*>(L) - LUA_EXTRASPACE;
    L->~lua_State();
    std::free(block);
}

int lua_gettop(lua_State* L) {
    return top(L);
}
void lua_settop(lua_State* L, int idx) {
    const size_t n = idx >= 0 ? base(L) + static_cast<size_t>(idx) : slot(L, idx) + 1;
    L->stack.resize(n);
}
int lua_absindex(lua_State* L, int idx) {
    return (idx > 0 || idx <= LUA_REGISTRYINDEX) ? idx : top(L) + idx + 1;
}
int lua_checkstack(lua_State*, int) {
    return 1;
}
void lua_rotate(lua_State* L, int idx, int n) {
    const auto first = L->stack.begin() + static_cast<long>(slot(L, idx));
    const long count = L->stack.end() - first;
    if (count == 0) return;
    const long shift = ((n % count) + count) % count;
    std::rotate(first, L->stack.end() - shift, L->stack.end());
}
void lua_copy(lua_State* L, int from, int to) {
    set(L, to, get(L, from));
}
void lua_pushvalue(lua_State* L, int idx) {
    push(L, get(L, idx));
}

int lua_type(lua_State* L, int idx) {
    if (idx > 0 && idx > top(L)) return LUA_TNONE;
    return get(L, idx).type;
}
const char* lua_typename(lua_State*, int t) {
    static const char* const names[] = {"no value", "nil",   "boolean",  "userdata", "number",
                                        "string",   "table", "function", "userdata", "thread"};
    return (t >= -1 && t <= 8) ? names[t + 1] : "?";
}
int lua_isnumber(lua_State* L, int idx) {
    Value v;
    const Value x = get(L, idx);
    return x.type == LUA_TNUMBER || (x.type == LUA_TSTRING && textNumber(*x.string, v));
}
int lua_isstring(lua_State* L, int idx) {
    const int t = lua_type(L, idx);
    return t == LUA_TSTRING || t == LUA_TNUMBER;
}
int lua_iscfunction(lua_State* L, int idx) {
    const Value v = get(L, idx);
    return v.type == LUA_TFUNCTION && v.function->c != nullptr;
}
int lua_isinteger(lua_State* L, int idx) {
    const Value v = get(L, idx);
    return v.type == LUA_TNUMBER && v.isInteger;
}
int lua_isuserdata(lua_State* L, int idx) {
    const int t = lua_type(L, idx);
    return t == LUA_TUSERDATA || t == LUA_TLIGHTUSERDATA;
}

lua_Number lua_tonumberx(lua_State* L, int idx, int* isnum) {
    Value v = get(L, idx);
    if (v.type == LUA_TSTRING && textNumber(*v.string, v)) {
    }
    if (isnum) *isnum = v.type == LUA_TNUMBER;
    return v.type == LUA_TNUMBER ? v.number : 0.0;
}
lua_Integer lua_tointegerx(lua_State* L, int idx, int* isnum) {
    Value v = get(L, idx);
    if (v.type == LUA_TSTRING) textNumber(*v.string, v);
    bool ok = v.type == LUA_TNUMBER &&
              (v.isInteger || (std::floor(v.number) == v.number && std::abs(v.number) < 9.2e18));
    if (isnum) *isnum = ok;
    if (!ok) return 0;
    return v.isInteger ? v.integer : static_cast<lua_Integer>(v.number);
}
int lua_toboolean(lua_State* L, int idx) {
    const Value v = get(L, idx);
    return !(v.type == LUA_TNIL || (v.type == LUA_TBOOLEAN && !v.boolean));
}
const char* lua_tolstring(lua_State* L, int idx, size_t* len) {
    Value v = get(L, idx);
    if (v.type == LUA_TNUMBER) {  // converted in place, as Lua does
        v = stringValue(numberText(v));
        set(L, idx, v);
    }
    if (v.type != LUA_TSTRING) {
        if (len) *len = 0;
        return nullptr;
    }
    if (len) *len = v.string->size();
    // The value's string lives as long as any copy of it: the slot keeps one.
    return get(L, idx).string->c_str();
}
lua_Unsigned lua_rawlen(lua_State* L, int idx) {
    const Value v = get(L, idx);
    if (v.type == LUA_TSTRING) return v.string->size();
    if (v.type == LUA_TTABLE) return static_cast<lua_Unsigned>(v.table->length());
    if (v.type == LUA_TUSERDATA) return v.userdata->size;
    return 0;
}
lua_CFunction lua_tocfunction(lua_State* L, int idx) {
    const Value v = get(L, idx);
    return v.type == LUA_TFUNCTION ? v.function->c : nullptr;
}
void* lua_touserdata(lua_State* L, int idx) {
    const Value v = get(L, idx);
    if (v.type == LUA_TUSERDATA) return v.userdata->block.get();
    if (v.type == LUA_TLIGHTUSERDATA) return v.light;
    return nullptr;
}
const void* lua_topointer(lua_State* L, int idx) {
    const Value v = get(L, idx);
    if (v.type == LUA_TTABLE) return v.table.get();
    if (v.type == LUA_TFUNCTION) return v.function.get();
    return lua_touserdata(L, idx);
}
int lua_rawequal(lua_State* L, int a, int b) {
    const Value x = get(L, a), y = get(L, b);
    if (x.type == LUA_TNIL && y.type == LUA_TNIL) return 1;
    if (x.type != y.type) return 0;
    return keyOf(x) == keyOf(y);
}

void lua_pushnil(lua_State* L) {
    push(L, nilValue());
}
void lua_pushnumber(lua_State* L, lua_Number n) {
    push(L, numberValue(n));
}
void lua_pushinteger(lua_State* L, lua_Integer n) {
    push(L, integerValue(n));
}
const char* lua_pushlstring(lua_State* L, const char* s, size_t len) {
    push(L, stringValue(std::string(s, len)));
    return L->stack.back().string->c_str();
}
const char* lua_pushstring(lua_State* L, const char* s) {
    if (!s) {
        lua_pushnil(L);
        return nullptr;
    }
    return lua_pushlstring(L, s, std::strlen(s));
}
const char* lua_pushvfstring(lua_State* L, const char* fmt, va_list argp) {
    std::string out;
    char buf[64];
    for (const char* p = fmt; *p; ++p) {
        if (*p != '%' || !p[1]) {
            out += *p;
            continue;
        }
        switch (*++p) {
            case 's': {
                const char* s = va_arg(argp, const char*);
                out += s ? s : "(null)";
                break;
            }
            case 'c':
                out += static_cast<char>(va_arg(argp, int));
                break;
            case 'd':
                out += std::to_string(va_arg(argp, int));
                break;
            case 'I':
                out += std::to_string(static_cast<lua_Integer>(va_arg(argp, LUAI_UACINT)));
                break;
            case 'f':
                out +=
                    numberText(numberValue(static_cast<lua_Number>(va_arg(argp, LUAI_UACNUMBER))));
                break;
            case 'p':
                std::snprintf(buf, sizeof buf, "%p", va_arg(argp, void*));
                out += buf;
                break;
            case 'U':
                out += static_cast<char>(va_arg(argp, long));
                break;
            case '%':
                out += '%';
                break;
            default:
                out += '%';
                out += *p;
        }
    }
    return lua_pushlstring(L, out.data(), out.size());
}
const char* lua_pushfstring(lua_State* L, const char* fmt, ...) {
    va_list argp;
    va_start(argp, fmt);
    const char* s = lua_pushvfstring(L, fmt, argp);
    va_end(argp);
    return s;
}
void lua_pushcclosure(lua_State* L, lua_CFunction fn, int n) {
    Value v;
    v.type = LUA_TFUNCTION;
    v.function = std::make_shared<Function>();
    v.function->c = fn;
    for (int k = n; k >= 1; --k) v.function->upvalues.push_back(get(L, -k));
    L->stack.resize(L->stack.size() - static_cast<size_t>(n));
    push(L, v);
}
void lua_pushboolean(lua_State* L, int b) {
    push(L, booleanValue(b != 0));
}
void lua_pushlightuserdata(lua_State* L, void* p) {
    Value v;
    v.type = LUA_TLIGHTUSERDATA;
    v.light = p;
    push(L, v);
}
int lua_pushthread(lua_State* L) {
    lua_pushnil(L);
    return 1;
}

int lua_getglobal(lua_State* L, const char* name) {
    push(L, index(L, globals(L), stringValue(name)));
    return L->stack.back().type;
}
int lua_gettable(lua_State* L, int idx) {
    const Value t = get(L, idx);
    const Value k = pop(L);
    push(L, index(L, t, k));
    return L->stack.back().type;
}
int lua_getfield(lua_State* L, int idx, const char* k) {
    const Value t = get(L, idx);
    push(L, index(L, t, stringValue(k)));
    return L->stack.back().type;
}
int lua_geti(lua_State* L, int idx, lua_Integer n) {
    const Value t = get(L, idx);
    push(L, index(L, t, integerValue(n)));
    return L->stack.back().type;
}
int lua_rawget(lua_State* L, int idx) {
    const Value t = get(L, idx);
    const Value k = pop(L);
    push(L, t.table->get(k));
    return L->stack.back().type;
}
int lua_rawgeti(lua_State* L, int idx, lua_Integer n) {
    const Value t = get(L, idx);
    push(L, t.table->get(integerValue(n)));
    return L->stack.back().type;
}
void lua_createtable(lua_State* L, int, int) {
    Value v;
    v.type = LUA_TTABLE;
    v.table = std::make_shared<Table>();
    push(L, v);
}
void* lua_newuserdatauv(lua_State* L, size_t size, int nuvalue) {
    Value v;
    v.type = LUA_TUSERDATA;
    v.userdata = std::make_shared<Userdata>();
    const size_t words = (size + sizeof(std::max_align_t) - 1) / sizeof(std::max_align_t);
    v.userdata->block.reset(new std::max_align_t[std::max<size_t>(words, 1)]);
    v.userdata->size = size;
    v.userdata->userValues.resize(static_cast<size_t>(std::max(nuvalue, 0)));
    L->allUserdata.push_back(v.userdata);
    push(L, v);
    return v.userdata->block.get();
}
int lua_getmetatable(lua_State* L, int idx) {
    const auto meta = metatableOf(get(L, idx));
    if (!meta) return 0;
    Value v;
    v.type = LUA_TTABLE;
    v.table = meta;
    push(L, v);
    return 1;
}
int lua_getiuservalue(lua_State* L, int idx, int n) {
    const Value u = get(L, idx);
    if (u.type != LUA_TUSERDATA || n < 1 || n > static_cast<int>(u.userdata->userValues.size())) {
        lua_pushnil(L);
        return LUA_TNONE;
    }
    push(L, u.userdata->userValues[static_cast<size_t>(n - 1)]);
    return L->stack.back().type;
}

void lua_setglobal(lua_State* L, const char* name) {
    const Value v = pop(L);
    newIndex(L, globals(L), stringValue(name), v);
}
void lua_settable(lua_State* L, int idx) {
    const Value t = get(L, idx);
    const Value v = pop(L);
    const Value k = pop(L);
    newIndex(L, t, k, v);
}
void lua_setfield(lua_State* L, int idx, const char* k) {
    const Value t = get(L, idx);
    const Value v = pop(L);
    newIndex(L, t, stringValue(k), v);
}
void lua_seti(lua_State* L, int idx, lua_Integer n) {
    const Value t = get(L, idx);
    const Value v = pop(L);
    newIndex(L, t, integerValue(n), v);
}
void lua_rawset(lua_State* L, int idx) {
    const Value t = get(L, idx);
    const Value v = pop(L);
    const Value k = pop(L);
    t.table->set(k, v);
}
void lua_rawseti(lua_State* L, int idx, lua_Integer n) {
    const Value t = get(L, idx);
    const Value v = pop(L);
    t.table->set(integerValue(n), v);
}
int lua_setmetatable(lua_State* L, int idx) {
    const Value t = get(L, idx);
    const Value m = pop(L);
    const auto meta = m.type == LUA_TTABLE ? m.table : nullptr;
    if (t.type == LUA_TTABLE)
        t.table->meta = meta;
    else if (t.type == LUA_TUSERDATA)
        t.userdata->meta = meta;
    return 1;
}
int lua_setiuservalue(lua_State* L, int idx, int n) {
    const Value u = get(L, idx);
    const Value v = pop(L);
    if (u.type != LUA_TUSERDATA || n < 1 || n > static_cast<int>(u.userdata->userValues.size()))
        return 0;
    u.userdata->userValues[static_cast<size_t>(n - 1)] = v;
    return 1;
}

void lua_callk(lua_State* L, int nargs, int nresults, lua_KContext, lua_KFunction) {
    callAtTop(L, nargs, nresults);
}
int lua_pcallk(lua_State* L, int nargs, int nresults, int msgh, lua_KContext, lua_KFunction) {
    const size_t fslot = L->stack.size() - static_cast<size_t>(nargs) - 1;
    const size_t frames = L->frames.size();
    const Value handler = msgh ? get(L, msgh) : nilValue();
    try {
        callAtTop(L, nargs, nresults);
        return LUA_OK;
    } catch (const LuaThrow& e) {
        L->stack.resize(fslot);
        L->frames.resize(frames);
        Value err = e.value;
        if (handler.type == LUA_TFUNCTION) {
            std::vector<Value> out;
            call(L, handler, {err}, 1, &out);
            err = out[0];
        }
        push(L, err);
        return e.status;
    } catch (const std::bad_alloc&) {
        L->stack.resize(fslot);
        L->frames.resize(frames);
        push(L, stringValue("not enough memory"));
        return LUA_ERRMEM;
    }
}

int lua_load(lua_State* L, lua_Reader reader, void* data, const char* chunkname, const char* mode) {
    std::string text;
    size_t size = 0;
    while (const char* piece = reader(L, data, &size)) {
        if (size == 0) break;
        text.append(piece, size);
    }
    return luaL_loadbufferx(L, text.data(), text.size(), chunkname, mode);
}

int lua_error(lua_State* L) {
    throw LuaThrow{pop(L), LUA_ERRRUN};
}

int lua_next(lua_State* L, int idx) {
    const Value t = get(L, idx);
    const Value k = pop(L);
    const auto& entries = t.table->entries;
    size_t at = 0;
    if (k.type != LUA_TNIL) {
        auto it = t.table->index.find(keyOf(k));
        if (it == t.table->index.end()) raise(L, "invalid key to 'next'");
        at = it->second + 1;
    }
    for (; at < entries.size(); ++at) {
        if (entries[at].second.type == LUA_TNIL) continue;
        push(L, entries[at].first);
        push(L, entries[at].second);
        return 1;
    }
    return 0;
}

void lua_concat(lua_State* L, int n) {
    if (n == 0) {
        lua_pushliteral(L, "");
        return;
    }
    std::string s;
    for (int k = n; k >= 1; --k) {
        const Value v = get(L, -k);
        if (v.type == LUA_TSTRING)
            s += *v.string;
        else if (v.type == LUA_TNUMBER)
            s += numberText(v);
        else
            raise(L, std::string("attempt to concatenate a ") + lua_typename(L, v.type) + " value");
    }
    L->stack.resize(L->stack.size() - static_cast<size_t>(n));
    push(L, stringValue(std::move(s)));
}
void lua_len(lua_State* L, int idx) {
    const Value v = get(L, idx);
    if (v.type == LUA_TSTRING)
        lua_pushinteger(L, static_cast<lua_Integer>(v.string->size()));
    else if (v.type == LUA_TTABLE)
        lua_pushinteger(L, v.table->length());
    else
        raise(L, std::string("attempt to get length of a ") + lua_typename(L, v.type) + " value");
}
size_t lua_stringtonumber(lua_State* L, const char* s) {
    Value v;
    if (!textNumber(s, v)) return 0;
    push(L, v);
    return std::strlen(s) + 1;
}
int lua_gc(lua_State*, int, ...) {
    return 0;
}

const char* lua_setupvalue(lua_State* L, int funcindex, int n) {
    const Value f = get(L, funcindex);
    const Value v = pop(L);
    if (f.type != LUA_TFUNCTION) return nullptr;
    if (f.function->hostRef > 0) {
        std::string data;
        encode(L, integerValue(n), data);
        encode(L, v, data);
        const std::vector<Value> name = request(L, "upvalue", f.function->hostRef, data);
        static thread_local std::string last;
        if (name.empty() || name[0].type != LUA_TSTRING) return nullptr;
        last = *name[0].string;
        return last.c_str();
    }
    if (n < 1 || n > static_cast<int>(f.function->upvalues.size())) return nullptr;
    f.function->upvalues[static_cast<size_t>(n - 1)] = v;
    return "";
}

void lua_sethook(lua_State* L, lua_Hook f, int mask, int count) {
    L->hook = (mask & LUA_MASKCOUNT) ? f : nullptr;
    L->hookCount = count;
    std::string data;
    encode(L, integerValue(L->hook ? count : 0), data);
    request(L, "hook", 0, data);
}

int lua_getstack(lua_State* L, int level, lua_Debug* ar) {
    // Level 0 is the running function; each level up is one frame further out.
    const int at = static_cast<int>(L->frames.size()) - 1 - level;
    if (level < 0 || at < 1) return 0;  // frame 0 is the state's own bottom
    ar->i_ci = reinterpret_cast<CallInfo*>(static_cast<uintptr_t>(at + 1));
    return 1;
}

int lua_getinfo(lua_State* L, const char* what, lua_Debug* ar) {
    const size_t at = reinterpret_cast<uintptr_t>(ar->i_ci);
    if (at == 0 || at > L->frames.size()) return 0;
    const Frame& f = L->frames[at - 1];
    for (const char* w = what; *w; ++w) {
        switch (*w) {
            case 'S':
                ar->source = f.isLua ? f.source.c_str() : "=[C]";
                ar->srclen = std::strlen(ar->source);
                std::snprintf(ar->short_src, LUA_IDSIZE, "%s",
                              f.isLua ? f.shortSrc.c_str() : "[C]");
                ar->what = f.isLua ? "Lua" : "C";
                ar->linedefined = ar->lastlinedefined = -1;
                break;
            case 'l':
                ar->currentline = f.isLua ? f.line : -1;
                break;
            case 'f':
                push(L, f.function);
                break;
            case 'n':
                ar->name = nullptr;
                ar->namewhat = "";
                break;
            default:
                break;
        }
    }
    return 1;
}

// ---- The auxiliary library ----------------------------------------------------------------

void luaL_checkversion_(lua_State*, lua_Number, size_t) {}

int luaL_getmetafield(lua_State* L, int obj, const char* e) {
    const auto meta = metatableOf(get(L, obj));
    if (!meta) return LUA_TNIL;
    const Value v = meta->get(stringValue(e));
    if (v.type == LUA_TNIL) return LUA_TNIL;
    push(L, v);
    return v.type;
}

int luaL_callmeta(lua_State* L, int obj, const char* e) {
    obj = lua_absindex(L, obj);
    if (luaL_getmetafield(L, obj, e) == LUA_TNIL) return 0;
    lua_pushvalue(L, obj);
    lua_call(L, 1, 1);
    return 1;
}

const char* luaL_tolstring(lua_State* L, int idx, size_t* len) {
    const Value v = get(L, idx);
    std::string s;
    switch (v.type) {
        case LUA_TNUMBER:
            s = numberText(v);
            break;
        case LUA_TSTRING:
            s = *v.string;
            break;
        case LUA_TBOOLEAN:
            s = v.boolean ? "true" : "false";
            break;
        case LUA_TNIL:
            s = "nil";
            break;
        default: {
            char buf[64];
            std::snprintf(buf, sizeof buf, "%s: %p", lua_typename(L, v.type),
                          lua_topointer(L, idx));
            s = buf;
        }
    }
    push(L, stringValue(s));
    return lua_tolstring(L, -1, len);
}

int luaL_argerror(lua_State* L, int arg, const char* extramsg) {
    return luaL_error(L, "bad argument #%d (%s)", arg, extramsg);
}
int luaL_typeerror(lua_State* L, int arg, const char* tname) {
    std::string msg = std::string(tname) + " expected, got " + luaL_typename(L, arg);
    return luaL_argerror(L, arg, msg.c_str());
}
const char* luaL_checklstring(lua_State* L, int arg, size_t* l) {
    const char* s = lua_tolstring(L, arg, l);
    if (!s) luaL_typeerror(L, arg, lua_typename(L, LUA_TSTRING));
    return s;
}
const char* luaL_optlstring(lua_State* L, int arg, const char* def, size_t* l) {
    if (lua_isnoneornil(L, arg)) {
        if (l) *l = def ? std::strlen(def) : 0;
        return def;
    }
    return luaL_checklstring(L, arg, l);
}
lua_Number luaL_checknumber(lua_State* L, int arg) {
    int ok = 0;
    const lua_Number n = lua_tonumberx(L, arg, &ok);
    if (!ok) luaL_typeerror(L, arg, lua_typename(L, LUA_TNUMBER));
    return n;
}
lua_Number luaL_optnumber(lua_State* L, int arg, lua_Number def) {
    return lua_isnoneornil(L, arg) ? def : luaL_checknumber(L, arg);
}
lua_Integer luaL_checkinteger(lua_State* L, int arg) {
    int ok = 0;
    const lua_Integer n = lua_tointegerx(L, arg, &ok);
    if (!ok) {
        if (lua_isnumber(L, arg))
            luaL_argerror(L, arg, "number has no integer representation");
        else
            luaL_typeerror(L, arg, lua_typename(L, LUA_TNUMBER));
    }
    return n;
}
lua_Integer luaL_optinteger(lua_State* L, int arg, lua_Integer def) {
    return lua_isnoneornil(L, arg) ? def : luaL_checkinteger(L, arg);
}
void luaL_checkstack(lua_State*, int, const char*) {}
void luaL_checktype(lua_State* L, int arg, int t) {
    if (lua_type(L, arg) != t) luaL_typeerror(L, arg, lua_typename(L, t));
}
void luaL_checkany(lua_State* L, int arg) {
    if (lua_type(L, arg) == LUA_TNONE) luaL_argerror(L, arg, "value expected");
}

int luaL_newmetatable(lua_State* L, const char* tname) {
    if (luaL_getmetatable(L, tname) != LUA_TNIL) return 0;
    lua_pop(L, 1);
    lua_createtable(L, 0, 2);
    lua_pushstring(L, tname);
    lua_setfield(L, -2, "__name");
    lua_pushvalue(L, -1);
    lua_setfield(L, LUA_REGISTRYINDEX, tname);
    return 1;
}
void luaL_setmetatable(lua_State* L, const char* tname) {
    luaL_getmetatable(L, tname);
    lua_setmetatable(L, -2);
}
void* luaL_testudata(lua_State* L, int ud, const char* tname) {
    const Value u = get(L, ud);
    if (u.type != LUA_TUSERDATA || !u.userdata->meta) return nullptr;
    const Value expected = L->registry->get(stringValue(tname));
    if (expected.type != LUA_TTABLE || expected.table != u.userdata->meta) return nullptr;
    return u.userdata->block.get();
}
void* luaL_checkudata(lua_State* L, int ud, const char* tname) {
    void* p = luaL_testudata(L, ud, tname);
    if (!p) luaL_typeerror(L, ud, tname);
    return p;
}

void luaL_where(lua_State* L, int lvl) {
    lua_Debug ar;
    if (lua_getstack(L, lvl, &ar)) {
        lua_getinfo(L, "Sl", &ar);
        if (ar.currentline > 0) {
            lua_pushfstring(L, "%s:%d: ", ar.short_src, ar.currentline);
            return;
        }
    }
    lua_pushfstring(L, "");
}
int luaL_error(lua_State* L, const char* fmt, ...) {
    va_list argp;
    va_start(argp, fmt);
    luaL_where(L, 1);
    lua_pushvfstring(L, fmt, argp);
    va_end(argp);
    lua_concat(L, 2);
    return lua_error(L);
}

int luaL_fileresult(lua_State* L, int stat, const char* fname) {
    const int en = errno;
    if (stat) {
        lua_pushboolean(L, 1);
        return 1;
    }
    lua_pushnil(L);
    if (fname)
        lua_pushfstring(L, "%s: %s", fname, std::strerror(en));
    else
        lua_pushstring(L, std::strerror(en));
    lua_pushinteger(L, en);
    return 3;
}

void luaL_setfuncs(lua_State* L, const luaL_Reg* l, int nup) {
    for (; l->name; ++l) {
        if (!l->func) {
            lua_pushboolean(L, 0);
        } else {
            for (int i = 0; i < nup; ++i) lua_pushvalue(L, -nup);
            lua_pushcclosure(L, l->func, nup);
        }
        lua_setfield(L, -(nup + 2), l->name);
    }
    lua_pop(L, nup);
}

/// Text chunks only: the page's Lua compiles them, each with the scripts' globals as _ENV.
int luaL_loadbufferx(lua_State* L, const char* buff, size_t sz, const char* name,
                     const char* mode) {
    if (mode && !std::strchr(mode, 't')) {
        lua_pushfstring(L, "attempt to load a text chunk (mode is '%s')", mode);
        return LUA_ERRSYNTAX;
    }
    std::string data;
    encode(L, stringValue(std::string(buff, sz)), data);
    encode(L, stringValue(name ? name : "?"), data);
    // The scripts' memory limit (lua_sandbox.cpp puts it in the registry), which the page's
    // Lua holds its own allocations to.
    encode(L, L->registry->get(stringValue("rb.memory_limit")), data);
    try {
        const std::vector<Value> f = request(L, "load", rb_shim_globals(L), data);
        push(L, f.empty() ? nilValue() : f[0]);
        return LUA_OK;
    } catch (const LuaThrow& e) {
        push(L, e.value);
        return e.status == LUA_ERRMEM ? LUA_ERRMEM : LUA_ERRSYNTAX;
    }
}
int luaL_loadstring(lua_State* L, const char* s) {
    return luaL_loadbufferx(L, s, std::strlen(s), s, nullptr);
}
int luaL_loadfilex(lua_State* L, const char* filename, const char* mode) {
    std::ifstream in(filename, std::ios::binary);
    if (!in) {
        lua_pushfstring(L, "cannot open %s", filename);
        return LUA_ERRFILE;
    }
    std::stringstream text;
    text << in.rdbuf();
    const std::string chunk = text.str();
    return luaL_loadbufferx(L, chunk.data(), chunk.size(), (std::string("@") + filename).c_str(),
                            mode);
}

void luaL_requiref(lua_State* L, const char* modname, lua_CFunction openf, int glb) {
    lua_getfield(L, LUA_REGISTRYINDEX, LUA_LOADED_TABLE);
    if (lua_type(L, -1) != LUA_TTABLE) {
        lua_pop(L, 1);
        lua_newtable(L);
        lua_pushvalue(L, -1);
        lua_setfield(L, LUA_REGISTRYINDEX, LUA_LOADED_TABLE);
    }
    lua_getfield(L, -1, modname);
    if (!lua_toboolean(L, -1)) {
        lua_pop(L, 1);
        lua_pushcfunction(L, openf);
        lua_pushstring(L, modname);
        lua_call(L, 1, 1);
        lua_pushvalue(L, -1);
        lua_setfield(L, -3, modname);
    }
    lua_remove(L, -2);
    if (glb) {
        lua_pushvalue(L, -1);
        lua_setglobal(L, modname);
    }
}

// Buffers: the placeholder luaL_buffinit pushes stays on the stack until the result replaces it.
void luaL_buffinit(lua_State* L, luaL_Buffer* B) {
    B->L = L;
    B->b = B->init.b;
    B->n = 0;
    B->size = LUAL_BUFFERSIZE;
    lua_pushlightuserdata(L, B);
}
char* luaL_prepbuffsize(luaL_Buffer* B, size_t sz) {
    if (B->size - B->n >= sz) return B->b + B->n;
    std::string& box = B->L->buffers[B];
    if (B->b != box.data()) box.assign(B->b, B->n);
    box.resize(std::max(B->n + sz, B->size * 2));
    B->b = box.data();
    B->size = box.size();
    return B->b + B->n;
}
void luaL_addlstring(luaL_Buffer* B, const char* s, size_t l) {
    if (l == 0) return;
    std::memcpy(luaL_prepbuffsize(B, l), s, l);
    luaL_addsize(B, l);
}
void luaL_addstring(luaL_Buffer* B, const char* s) {
    luaL_addlstring(B, s, std::strlen(s));
}
void luaL_addvalue(luaL_Buffer* B) {
    size_t len = 0;
    const char* s = lua_tolstring(B->L, -1, &len);
    const std::string copy(s ? s : "", len);
    lua_pop(B->L, 1);
    luaL_addlstring(B, copy.data(), copy.size());
}
void luaL_pushresult(luaL_Buffer* B) {
    lua_State* L = B->L;
    lua_pushlstring(L, B->b, B->n);
    L->buffers.erase(B);
    lua_remove(L, -2);  // the placeholder
}
void luaL_pushresultsize(luaL_Buffer* B, size_t sz) {
    luaL_addsize(B, sz);
    luaL_pushresult(B);
}
char* luaL_buffinitsize(lua_State* L, luaL_Buffer* B, size_t sz) {
    luaL_buffinit(L, B);
    return luaL_prepbuffsize(B, sz);
}

// ---- The standard libraries: the page's Lua's own ------------------------------------------
// Opening one copies its functions (as handles to the page's functions) into a table here.

namespace {
int openHostLibrary(lua_State* L, const char* name) {
    std::string data;
    encode(L, stringValue(name), data);
    const std::vector<Value> lib = request(L, "lib", 0, data);
    Value t = lib.empty() ? nilValue() : lib[0];
    if (std::strcmp(name, "_G") == 0) {  // the base library fills the globals table itself
        const Value g = globals(L);
        if (t.type == LUA_TTABLE)
            for (const auto& [k, v] : t.table->entries) g.table->set(k, v);
        g.table->set(stringValue("_G"), g);
        t = g;
    }
    push(L, t);
    return 1;
}
}  // namespace

int luaopen_base(lua_State* L) {
    return openHostLibrary(L, "_G");
}
int luaopen_math(lua_State* L) {
    return openHostLibrary(L, "math");
}
int luaopen_string(lua_State* L) {
    return openHostLibrary(L, "string");
}
int luaopen_table(lua_State* L) {
    return openHostLibrary(L, "table");
}
int luaopen_utf8(lua_State* L) {
    return openHostLibrary(L, "utf8");
}
int luaopen_coroutine(lua_State* L) {
    return openHostLibrary(L, "coroutine");
}

/// --unsafe-lua in the page: the libraries a browser has (no os, io or debug).
void luaL_openlibs(lua_State* L) {
    const std::pair<const char*, lua_CFunction> libs[] = {
        {LUA_GNAME, luaopen_base},        {LUA_MATHLIBNAME, luaopen_math},
        {LUA_STRLIBNAME, luaopen_string}, {LUA_TABLIBNAME, luaopen_table},
        {LUA_UTF8LIBNAME, luaopen_utf8},  {LUA_COLIBNAME, luaopen_coroutine}};
    for (const auto& [name, open] : libs) {
        luaL_requiref(L, name, open, 1);
        lua_pop(L, 1);
    }
}

}  // extern "C"

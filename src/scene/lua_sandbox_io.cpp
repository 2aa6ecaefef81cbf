// The sandbox's read-only io (see lua_sandbox_io.h for what it offers and refuses).
//
// Lua is built as C here, so its errors are longjmps: a function that can raise one (every
// luaL_error, every luaL_Buffer step, which may run out of memory) must not have a C++ object
// with a destructor alive at that point. The C++ work (finding the file) therefore happens in
// a scope of its own, and the error, if any, is raised after the scope has closed.
#include "scene/lua_sandbox_io.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "scene/lua_scene.h"

namespace rb {

namespace fs = std::filesystem;

namespace {

constexpr const char* kFileType = "rb.file";

/// At most this many formats in one lines() call (Lua's own limit).
constexpr int kMaxLineFormats = 250;

/// The standard io names the sandbox leaves out: reading one says why.
constexpr const char* kLeftOutIo[] = {"flush",  "input", "output", "popen",   "read",
                                      "stderr", "stdin", "stdout", "tmpfile", "write"};
/// The standard file methods the sandbox leaves out.
constexpr const char* kLeftOutMethods[] = {"flush", "seek", "setvbuf", "write"};

/// A file the script opened. Lua owns it: close(), __close or __gc closes it, once.
struct SandboxFile {
    std::FILE* fp;  ///< nullptr once closed.
};

// ---- Which files a scene may read ---------------------------------------------------------

/// What looking for a file found.
enum class Lookup {
    Readable,  ///< Under an allowed folder: `path` is its canonical path.
    Missing,   ///< It would be under an allowed folder, but nothing is there.
    Outside,   ///< It leads outside the allowed folders: `path` says where.
};

/// The outcome of looking for a file the script named.
struct Resolved {
    Lookup what = Lookup::Missing;
    std::string path;     ///< Readable: what to open. Outside: where the name leads.
    std::string allowed;  ///< Outside: the allowed folders, for the message.
};

/// `path` made absolute and canonical, symlinks resolved as far as the path exists.
fs::path canonicalForm(const fs::path& path) {
    std::error_code ec;
    const fs::path full = fs::absolute(path, ec);
    fs::path canonical = fs::weakly_canonical(full, ec);
    if (ec) canonical = full.lexically_normal();
    return canonical;
}

/// True when `path` is `folder` or lies below it, comparing whole components (both canonical).
bool isUnder(const fs::path& path, const fs::path& folder) {
    auto p = path.begin();
    for (const fs::path& part : folder) {
        if (part.empty()) continue;  // the empty last component of a trailing separator
        if (p == path.end() || *p != part) return false;
        ++p;
    }
    return true;
}

/// The folders a scene may read from, canonical: its own folder, then each --assets folder.
std::vector<fs::path> readableFolders(const SceneBuilder& builder) {
    std::vector<std::string> folders = {builder.sceneDir.empty() ? "." : builder.sceneDir};
    folders.insert(folders.end(), builder.options.assetDirs.begin(),
                   builder.options.assetDirs.end());
    std::vector<fs::path> canonical;
    for (const std::string& folder : folders) {
        const fs::path c = canonicalForm(folder);
        if (std::find(canonical.begin(), canonical.end(), c) == canonical.end())
            canonical.push_back(c);
    }
    return canonical;
}

/// "the scene's folder /a/b and the --assets folder /c": how a refusal names what is allowed.
std::string describeFolders(const std::vector<fs::path>& folders) {
    std::string text = "the scene's folder " + folders.front().string();
    if (folders.size() == 2) text += " and the --assets folder " + folders[1].string();
    if (folders.size() > 2) {
        text += " and the --assets folders";
        for (size_t i = 1; i < folders.size(); ++i)
            text += (i == 1 ? " " : ", ") + folders[i].string();
    }
    return text;
}

/// Find the file a script named, in the places scene files are looked for, and decide
/// whether the sandbox lets the script read it.
Resolved resolveReadable(const SceneBuilder& builder, const std::string& name) {
    const std::vector<fs::path> folders = readableFolders(builder);
    const auto allowed = [&](const fs::path& p) {
        return std::any_of(folders.begin(), folders.end(),
                           [&](const fs::path& f) { return isUnder(p, f); });
    };
    // Step 1: the first place that exists and is allowed is the file. Note the first place
    // that exists outside (a symlink out, or a file only in the working directory) for the
    // message, and whether any place lies inside at all.
    bool anyInside = false;
    std::string outside;
    for (const std::string& place : sceneFileCandidates(builder, name)) {
        const fs::path full = canonicalForm(place);
        std::error_code ec;
        const bool exists = fs::exists(full, ec);
        if (allowed(full)) {
            if (exists) return {Lookup::Readable, full.string(), ""};
            anyInside = true;
        } else if (exists && outside.empty()) {
            outside = full.string();
        }
    }
    // Step 2: nothing allowed exists. A file found only outside is refused, so is a name that
    // leads outside from every place; otherwise the file is simply missing.
    if (outside.empty() && anyInside) return {Lookup::Missing, "", ""};
    if (outside.empty()) {
        const fs::path base = builder.sceneDir.empty() ? fs::path(".") : fs::path(builder.sceneDir);
        outside = canonicalForm(fs::path(name).is_absolute() ? fs::path(name) : base / name);
    }
    return {Lookup::Outside, outside, describeFolders(folders)};
}

// ---- Opening ------------------------------------------------------------------------------

/// True for the modes the sandbox opens files with: "r" and "rb".
bool isReadMode(const char* mode) {
    return std::strcmp(mode, "r") == 0 || std::strcmp(mode, "rb") == 0;
}

/// Push a new userdata for a file that is not open yet.
SandboxFile* newFile(lua_State* L) {
    auto* file = static_cast<SandboxFile*>(lua_newuserdatauv(L, sizeof(SandboxFile), 0));
    file->fp = nullptr;
    luaL_setmetatable(L, kFileType);
    return file;
}

/// Open `name` for `call` (io.open or io.lines). Pushes the file and returns 1, or, when the
/// file does not exist, pushes nil, a message and errno and returns 3, as Lua's io.open does.
/// Raises a Lua error when the name leads outside the allowed folders.
int openChecked(lua_State* L, const char* call, const char* name, const char* mode) {
    // The userdata comes first, so the FILE* is Lua's to close even if Lua raises later.
    SandboxFile* file = newFile(L);
    Lookup what;
    int error = ENOENT;
    {
        const Resolved found = resolveReadable(sceneBuilder(L), name);
        what = found.what;
        if (what == Lookup::Readable) {
            file->fp = std::fopen(found.path.c_str(), mode);
            if (!file->fp) {
                what = Lookup::Missing;
                error = errno;
            }
        } else if (what == Lookup::Outside) {
            // Say where the name leads unless the name says it already.
            const std::string leads = found.path == name ? "" : " (" + found.path + ")";
            lua_pushfstring(L,
                            "%s: cannot read '%s'%s: raybook's sandbox reads only files under "
                            "%s (--assets DIR adds a folder; ./rt --unsafe-lua lifts the limit)",
                            call, name, leads.c_str(), found.allowed.c_str());
        }
    }
    if (what == Lookup::Outside) return luaL_error(L, "%s", lua_tostring(L, -1));
    if (what == Lookup::Missing) {
        luaL_pushfail(L);
        lua_pushfstring(L, "%s: %s", name, std::strerror(error));
        lua_pushinteger(L, error);
        return 3;
    }
    return 1;
}

/// The file at `arg`, which must be open; `method` names the call in the message.
SandboxFile* checkFile(lua_State* L, int arg, const char* method) {
    auto* file = static_cast<SandboxFile*>(luaL_testudata(L, arg, kFileType));
    if (!file) {
        luaL_error(
            L, "file:%s: argument %d must be a file, got %s (call methods with a colon: f:%s(...))",
            method, arg, luaL_typename(L, arg), method);
        return nullptr;  // not reached: luaL_error does not return
    }
    if (!file->fp) luaL_error(L, "attempt to use a closed file");
    return file;
}

/// Close an open file; Lua's result of close(): true, or nil plus a message.
int closeFile(lua_State* L, SandboxFile* file) {
    const int failed = std::fclose(file->fp);
    file->fp = nullptr;
    if (failed) return luaL_fileresult(L, 0, nullptr);
    lua_pushboolean(L, 1);
    return 1;
}

// ---- Reading ------------------------------------------------------------------------------

/// Format "l" (chop the newline) or "L" (keep it). False at the end of the file.
bool readLine(lua_State* L, std::FILE* f, bool chop) {
    luaL_Buffer b;
    luaL_buffinit(L, &b);
    int c = EOF;
    do {
        // Fill one buffer's worth at a time; the buffer grows through Lua's allocator.
        char* buffer = luaL_prepbuffer(&b);
        int i = 0;
        while (i < LUAL_BUFFERSIZE && (c = std::getc(f)) != EOF && c != '\n') buffer[i++] = char(c);
        luaL_addsize(&b, i);
    } while (c != EOF && c != '\n');
    if (!chop && c == '\n') luaL_addchar(&b, '\n');
    luaL_pushresult(&b);
    return c == '\n' || lua_rawlen(L, -1) > 0;
}

/// Format "a": the rest of the file ("" at its end). A file larger than the memory limit
/// allows fails here with Lua's memory error, as any other string would.
void readAll(lua_State* L, std::FILE* f) {
    luaL_Buffer b;
    luaL_buffinit(L, &b);
    size_t got = 0;
    do {
        char* buffer = luaL_prepbuffer(&b);
        got = std::fread(buffer, 1, LUAL_BUFFERSIZE, f);
        luaL_addsize(&b, got);
    } while (got == LUAL_BUFFERSIZE);
    luaL_pushresult(&b);
}

/// A byte count n > 0: up to n bytes. False at the end of the file.
bool readBytes(lua_State* L, std::FILE* f, size_t n) {
    luaL_Buffer b;
    char* buffer = luaL_buffinitsize(L, &b, n);
    const size_t got = std::fread(buffer, 1, n, f);
    luaL_pushresultsize(&b, got);
    return got > 0;
}

/// A byte count of 0: "" unless at the end of the file.
bool testEof(lua_State* L, std::FILE* f) {
    const int c = std::getc(f);
    std::ungetc(c, f);
    lua_pushliteral(L, "");
    return c != EOF;
}

/// Format "n": the longest numeral at the current position (after white space), read as Lua
/// reads numerals, in the manner of Lua's own liolib. At most 200 characters.
class NumberReader {
  public:
    explicit NumberReader(std::FILE* f) : f_(f) {}

    /// Push the number, or nil when what follows is not one; true on success.
    bool read(lua_State* L) {
        // Step 1: skip white space, then an optional sign and a "0x" prefix.
        do c_ = std::getc(f_);
        while (std::isspace(c_));
        accept("-+");
        int digits = 0;
        bool hex = false;
        if (accept("00")) {
            if (accept("xX"))
                hex = true;
            else
                digits = 1;
        }
        // Step 2: the digits, a fraction, and an exponent after at least one digit.
        digits += readDigits(hex);
        if (accept("..")) digits += readDigits(hex);
        if (digits > 0 && accept(hex ? "pP" : "eE")) {
            accept("-+");
            readDigits(false);
        }
        // Step 3: give back the character after the numeral and convert what was read.
        std::ungetc(c_, f_);
        text_[n_] = '\0';
        if (lua_stringtonumber(L, text_) != 0) return true;
        lua_pushnil(L);
        return false;
    }

  private:
    static constexpr int kMaxLength = 200;

    /// Keep the current character and read the next; false when the numeral is too long.
    bool keep() {
        if (n_ >= kMaxLength) {
            text_[0] = '\0';
            return false;
        }
        text_[n_++] = char(c_);
        c_ = std::getc(f_);
        return true;
    }
    /// Keep the current character if it is one of the two in `pair`.
    bool accept(const char* pair) { return (c_ == pair[0] || c_ == pair[1]) && keep(); }
    /// Keep a run of (hexadecimal) digits; how many.
    int readDigits(bool hex) {
        int count = 0;
        while ((hex ? std::isxdigit(c_) : std::isdigit(c_)) && keep()) ++count;
        return count;
    }

    std::FILE* f_;
    int c_ = EOF;
    int n_ = 0;
    char text_[kMaxLength + 1] = {};
};

/// Read the formats at stack positions first.. (none means "l"), pushing one value each, as
/// Lua's file:read does: the first that fails pushes nil and ends the reading.
int readFormats(lua_State* L, std::FILE* f, int first) {
    int formats = lua_gettop(L) - first + 1;
    std::clearerr(f);
    bool success = true;
    int n = first;
    if (formats == 0) {
        success = readLine(L, f, true);
        n = first + 1;
    } else {
        luaL_checkstack(L, formats + LUA_MINSTACK, "too many formats");
        for (; formats-- > 0 && success; ++n) {
            if (lua_type(L, n) == LUA_TNUMBER) {
                const lua_Integer count = luaL_checkinteger(L, n);
                luaL_argcheck(L, count >= 0, n, "a byte count must not be negative");
                success = count == 0 ? testEof(L, f) : readBytes(L, f, size_t(count));
                continue;
            }
            const char* format = luaL_checkstring(L, n);
            if (*format == '*') ++format;  // Lua 5.1 wrote "*l", "*a", "*n"
            switch (*format) {
                case 'l':
                    success = readLine(L, f, true);
                    break;
                case 'L':
                    success = readLine(L, f, false);
                    break;
                case 'n':
                    success = NumberReader(f).read(L);
                    break;
                case 'a':
                    readAll(L, f);
                    success = true;
                    break;
                default:
                    return luaL_argerror(
                        L, n, "invalid format (use \"l\", \"L\", \"n\", \"a\" or a count)");
            }
        }
    }
    if (std::ferror(f)) return luaL_fileresult(L, 0, nullptr);
    if (!success) {
        lua_pop(L, 1);
        luaL_pushfail(L);
    }
    return n - first;
}

/// The iterator of lines(): upvalues are the file, the number of formats, whether to close
/// the file at its end, then the formats.
int linesStep(lua_State* L) {
    auto* file = static_cast<SandboxFile*>(lua_touserdata(L, lua_upvalueindex(1)));
    if (!file->fp) return luaL_error(L, "file is already closed");
    int n = int(lua_tointeger(L, lua_upvalueindex(2)));
    lua_settop(L, 1);
    luaL_checkstack(L, n, "too many formats");
    for (int i = 1; i <= n; ++i) lua_pushvalue(L, lua_upvalueindex(3 + i));
    n = readFormats(L, file->fp, 2);
    if (lua_toboolean(L, -n)) return n;
    // The end of the file, or an error (nil, message, errno), which is raised.
    if (n > 1) return luaL_error(L, "%s", lua_tostring(L, -n + 1));
    if (lua_toboolean(L, lua_upvalueindex(3))) closeFile(L, file);
    return 0;
}

/// Push the lines() iterator for the file at stack position 1 and the formats after it.
void pushLinesIterator(lua_State* L, bool closeAtEnd) {
    const int formats = lua_gettop(L) - 1;
    luaL_argcheck(L, formats <= kMaxLineFormats, kMaxLineFormats + 2, "too many formats");
    lua_pushvalue(L, 1);
    lua_pushinteger(L, formats);
    lua_pushboolean(L, closeAtEnd);
    lua_rotate(L, 2, 3);  // file, count, flag, then the formats: the upvalues in order
    lua_pushcclosure(L, linesStep, 3 + formats);
}

// ---- File methods -------------------------------------------------------------------------

/// file:read(...).
int fileRead(lua_State* L) {
    return readFormats(L, checkFile(L, 1, "read")->fp, 2);
}

/// file:lines(...): an iterator that leaves the file open at the end.
int fileLines(lua_State* L) {
    checkFile(L, 1, "lines");
    pushLinesIterator(L, false);
    return 1;
}

/// file:close().
int fileClose(lua_State* L) {
    return closeFile(L, checkFile(L, 1, "close"));
}

/// __gc and __close: close the file if the script did not.
int fileCollect(lua_State* L) {
    auto* file = static_cast<SandboxFile*>(luaL_checkudata(L, 1, kFileType));
    if (file->fp) {
        std::fclose(file->fp);
        file->fp = nullptr;
    }
    return 0;
}

/// __tostring: "file (0x...)" or "file (closed)", as Lua prints files.
int fileToString(lua_State* L) {
    auto* file = static_cast<SandboxFile*>(luaL_checkudata(L, 1, kFileType));
    if (file->fp)
        lua_pushfstring(L, "file (%p)", static_cast<void*>(file->fp));
    else
        lua_pushliteral(L, "file (closed)");
    return 1;
}

/// True when `name` is in the list.
template <size_t N>
bool listed(const char* const (&list)[N], const char* name) {
    return std::any_of(std::begin(list), std::end(list),
                       [&](const char* s) { return std::strcmp(s, name) == 0; });
}

/// __index of the file methods: a method the sandbox leaves out says why.
int unknownFileMethod(lua_State* L) {
    const char* name = lua_tostring(L, 2);
    if (name && listed(kLeftOutMethods, name))
        return luaL_error(L,
                          "file:%s is not available in raybook's sandbox, whose files are "
                          "read-only (read, lines, close); ./rt --unsafe-lua allows it",
                          name);
    lua_pushnil(L);
    return 1;
}

// ---- The io table -------------------------------------------------------------------------

/// io.open(name [, mode]).
int ioOpen(lua_State* L) {
    const char* name = luaL_checkstring(L, 1);
    const char* mode = luaL_optstring(L, 2, "r");
    if (!isReadMode(mode))
        return luaL_error(L,
                          "io.open('%s', '%s'): raybook's sandbox opens files for reading only "
                          "(mode 'r' or 'rb'); ./rt --unsafe-lua allows writing",
                          name, mode);
    return openChecked(L, "io.open", name, mode);
}

/// io.lines(name, ...): iterate the file's lines (or formats); closed at the end.
int ioLines(lua_State* L) {
    if (lua_isnoneornil(L, 1))
        return luaL_error(L,
                          "io.lines() reads standard input, which raybook's sandbox does not "
                          "offer; name a file: io.lines('file.obj')");
    const char* name = luaL_checkstring(L, 1);
    if (openChecked(L, "io.lines", name, "r") != 1) return luaL_error(L, "%s", lua_tostring(L, -2));
    lua_replace(L, 1);  // the file in place of its name, the formats after it
    pushLinesIterator(L, true);
    // Lua 5.4's four results: the iterator, two nils, and the file as the to-be-closed value.
    lua_pushnil(L);
    lua_pushnil(L);
    lua_pushvalue(L, 1);
    return 4;
}

/// io.close(file): as file:close(). Without a file it would close standard output.
int ioClose(lua_State* L) {
    if (lua_isnoneornil(L, 1))
        return luaL_error(L,
                          "io.close() closes standard output, which raybook's sandbox does not "
                          "offer; close a file: f:close() or io.close(f)");
    return closeFile(L, checkFile(L, 1, "close"));
}

/// io.type(x): "file", "closed file", or nil.
int ioType(lua_State* L) {
    luaL_checkany(L, 1);
    auto* file = static_cast<SandboxFile*>(luaL_testudata(L, 1, kFileType));
    if (!file)
        luaL_pushfail(L);
    else if (file->fp)
        lua_pushliteral(L, "file");
    else
        lua_pushliteral(L, "closed file");
    return 1;
}

/// __index of io: a standard io name the sandbox leaves out says why; others are nil.
int unknownIoName(lua_State* L) {
    const char* name = lua_tostring(L, 2);
    if (name && listed(kLeftOutIo, name))
        return luaL_error(L,
                          "io.%s is not available in raybook's sandbox, whose io is read-only "
                          "(io.open, io.lines, io.close, io.type); ./rt --unsafe-lua allows it",
                          name);
    lua_pushnil(L);
    return 1;
}

/// Create the file metatable: methods, __gc, __close, __tostring.
void createFileType(lua_State* L) {
    luaL_newmetatable(L, kFileType);
    const luaL_Reg methods[] = {
        {"read", fileRead}, {"lines", fileLines}, {"close", fileClose}, {nullptr, nullptr}};
    luaL_newlib(L, methods);
    lua_newtable(L);  // the methods' metatable: left-out methods say why
    lua_pushcfunction(L, unknownFileMethod);
    lua_setfield(L, -2, "__index");
    lua_setmetatable(L, -2);
    lua_setfield(L, -2, "__index");
    const luaL_Reg meta[] = {{"__gc", fileCollect},
                             {"__close", fileCollect},
                             {"__tostring", fileToString},
                             {nullptr, nullptr}};
    luaL_setfuncs(L, meta, 0);
    lua_pop(L, 1);
}

}  // namespace

void openReadOnlyIo(lua_State* L) {
    createFileType(L);
    const luaL_Reg functions[] = {{"open", ioOpen},
                                  {"lines", ioLines},
                                  {"close", ioClose},
                                  {"type", ioType},
                                  {nullptr, nullptr}};
    luaL_newlib(L, functions);
    lua_newtable(L);  // io's metatable: left-out names say why
    lua_pushcfunction(L, unknownIoName);
    lua_setfield(L, -2, "__index");
    lua_setmetatable(L, -2);
    lua_setglobal(L, "io");
}

}  // namespace rb

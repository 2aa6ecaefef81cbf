/// \file
/// The sandbox's read-only `io`: enough for the course's readobj.lua to read OBJ files.
///
/// A sandboxed scene gets a global `io` table with only
///   - io.open(name [, mode]): mode "r" or "rb"; a file object, or nil, message, errno when the
///     file does not exist (as Lua's io.open);
///   - io.lines(name, ...): iterate a file's lines (or other formats), closing it at the end;
///   - io.close(file) and io.type(x);
/// and file objects with read (formats "l", "L", "n", "a", a byte count, and the Lua 5.1
/// spellings "*l", "*L", "*n", "*a"), lines and close; __gc and __close close the file.
///
/// A name is looked for where the scene's other files are (sceneFileCandidates: the working
/// directory, the scene's folder, each --assets folder), and a place counts only if its
/// canonical path (symlinks resolved) lies under the canonical scene folder or a canonical
/// --assets folder. Anything else is a Lua error naming the scene line and the allowed
/// folders: a path that leads outside them ("../x", "/etc/passwd", a symlink out), a write
/// mode, and the rest of the standard io (io.popen, io.write, io.stdout, file:write, ...),
/// which the sandbox leaves out. Strings read are Lua strings, so the memory limit holds.
#pragma once

#include <lua.hpp>

namespace rb {

/// Define the global `io` of a sandboxed scene: io.open(path, "r"), io.lines and the file
/// methods read, lines and close, for files under the scene's folder and the --assets folders.
void openReadOnlyIo(lua_State* L);

}  // namespace rb

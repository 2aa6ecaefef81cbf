// The page's side of the Lua bridge (src/web/lua_shim.cpp is the other): scene scripts run in
// wasmoon's Lua 5.4, and what they do with raybook's values (gr, nodes, materials, ...) is
// asked of rt's WebAssembly module, where those values live. See src/web/README.md.
//
// createLuaHost(factory) takes a wasmoon LuaFactory and returns the object rt's module finds
// as Module.luaHost: open(L, Module) and close(L) follow lua_newstate and lua_close, and
// request(op, ref, data) answers the shim's questions ("load", "call", "lib", "hook",
// "upvalue") in the bridge's text encoding.

/* exported createLuaHost */
async function createLuaHost(factory) {
  const luaModule = await factory.getLuaModule();
  const states = new Map();

  // The Lua half, run once in each new engine. __rb_js(op, handle, data) is rt's
  // rb_shim_op; the functions it leaves in __rb answer the shim.
  const prelude = String.raw`
local js = __rb_js
local __rb_memory_max = __rb_memory_max
__rb_js, _G.__rb_memory_max = nil, nil
local dgetinfo, dsethook, dsetupvalue = debug.getinfo, debug.sethook, debug.setupvalue
local sformat, ssub, sfind, mtype, tostring, type, pcall, error, select, next =
  string.format, string.sub, string.find, math.type, tostring, type, pcall, error, select, next
local tconcat, tunpack, setmetatable, rawget, load = table.concat, table.unpack, setmetatable, rawget, load

local refs, refOf = {}, {}          -- the page's values that rt holds, by number
local proxies = setmetatable({}, {__mode = "v"})  -- rt's values the page holds, by handle
local handleOf = setmetatable({}, {__mode = "k"})
local hookCount = 0

local function ref(v)
  local id = refOf[v]
  if not id then id = #refs + 1; refs[id] = v; refOf[v] = id end
  return id
end

-- Encoding (the same as lua_shim.cpp's): z, t, f, i<int>;, n<%a>;, s<len>:<bytes>,
-- h<handle>; (rt's value), r<id>; (ours), T<n>; then n key, value pairs (a copied table).
local encode
local function encodeTable(t, out, seen)
  if seen[t] then error("a table that contains itself cannot be passed to raybook in the page", 0) end
  seen[t] = true
  local parts, n = {}, 0
  for k, v in next, t do
    n = n + 1
    encode(k, parts, seen)
    encode(v, parts, seen)
  end
  seen[t] = nil
  out[#out + 1] = "T" .. n .. ";"
  out[#out + 1] = tconcat(parts)
end
encode = function(v, out, seen)
  local tv = type(v)
  if tv == "nil" then out[#out + 1] = "z"
  elseif tv == "boolean" then out[#out + 1] = v and "t" or "f"
  elseif tv == "number" then
    if mtype(v) == "integer" then out[#out + 1] = "i" .. v .. ";"
    elseif v ~= v then out[#out + 1] = "nnan;"
    elseif v == 1/0 then out[#out + 1] = "ninf;"
    elseif v == -1/0 then out[#out + 1] = "n-inf;"
    else out[#out + 1] = sformat("n%a;", v) end
  elseif tv == "string" then out[#out + 1] = "s" .. #v .. ":" .. v
  elseif tv == "table" and handleOf[v] then out[#out + 1] = "h" .. handleOf[v] .. ";"
  elseif tv == "table" then encodeTable(v, out, seen or {})
  else out[#out + 1] = "r" .. ref(v) .. ";" end
end
local function encodeAll(...)
  local out = {}
  for i = 1, select("#", ...) do encode((select(i, ...)), out) end
  return tconcat(out)
end

local proxy
local function decodeOne(s, p)
  local tag = ssub(s, p, p)
  if tag == "z" then return nil, p + 1
  elseif tag == "t" then return true, p + 1
  elseif tag == "f" then return false, p + 1 end
  local stop = sfind(s, tag == "s" and ":" or ";", p + 1, true)
  local body = ssub(s, p + 1, stop - 1)
  if tag == "i" then return math.tointeger(body), stop + 1
  elseif tag == "n" then
    if body == "nan" or body == "-nan" then return 0/0, stop + 1
    elseif body == "inf" then return 1/0, stop + 1
    elseif body == "-inf" then return -1/0, stop + 1 end
    return tonumber(body), stop + 1
  elseif tag == "s" then
    local n = tonumber(body)
    return ssub(s, stop + 1, stop + n), stop + 1 + n
  elseif tag == "h" then return proxy(tonumber(body)), stop + 1
  elseif tag == "r" then return refs[tonumber(body)], stop + 1 end
  error("raybook's page bridge: bad value '" .. tag .. "'", 0)
end
local function decodeAll(s)
  local values, n, p = {}, 0, 1
  while p <= #s do
    n = n + 1
    values[n], p = decodeOne(s, p)
  end
  return values, n
end

-- Where the running Lua code is, for rt's messages (file:line): the code that called the
-- metamethod or hook (level 2) and its caller (level 3), outermost first.
local function frameText(level)
  local info = dgetinfo(level + 1, "Sl")
  if not info or info.what == "C" then return "s4:=[C]s3:[C]i-1;" end
  local src, short = info.source, info.short_src
  return "s" .. #src .. ":" .. src .. "s" .. #short .. ":" .. short .. "i" .. info.currentline .. ";"
end
local function where(inner)
  return "i2;" .. frameText(inner + 1) .. frameText(inner)
end

-- Ask rt: op on handle h with the values; an error rt raised is raised here, unchanged.
-- Called from a metamethod (never as a tail call), the script is 4 levels out of where().
local function ask(op, h, ...)
  local answer = js(op, h, where(4) .. encodeAll(...))
  local values, n = decodeAll(ssub(answer, 2))
  if ssub(answer, 1, 1) ~= "O" then error(values[1], 0) end
  return tunpack(values, 1, n)
end

local function pass(...) return ... end
local Proxy = {
  __index = function(p, k) local v = ask("index", handleOf[p], k) return v end,
  __newindex = function(p, k, v) ask("newindex", handleOf[p], k, v) end,
  __call = function(p, ...) return pass(ask("call", handleOf[p], ...)) end,
  __len = function(p) local n = ask("len", handleOf[p]) return n end,
  __pairs = function(p)
    return function(_, k) return pass(ask("next", handleOf[p], k)) end, p, nil
  end,
  __tostring = function(p) return "raybook value " .. handleOf[p] end,
  __name = "raybook value",
}
proxy = function(h)
  local p = proxies[h]
  if not p then
    p = setmetatable({}, Proxy)
    proxies[h] = p
    handleOf[p] = h
  end
  return p
end

local function hook()
  local answer = js("hook", 0, where(3))  -- the running function is 3 levels out
  if ssub(answer, 1, 1) ~= "O" then error((decodeAll(ssub(answer, 2)))[1], 0) end
end

local function answer(ok, ...)
  if ok then return "O" .. encodeAll(...) end
  local err = ...
  if err == "not enough memory" then return "M" .. encodeAll(err) end
  if type(err) ~= "string" and type(err) ~= "number" then err = nil end
  return "E" .. encodeAll(err)
end

local libraries = {
  _G = {"assert", "collectgarbage", "error", "getmetatable", "ipairs", "next", "pairs",
        "pcall", "print", "rawequal", "rawget", "rawlen", "rawset", "select", "setmetatable",
        "tonumber", "tostring", "type", "xpcall", "_VERSION", "load", "dofile", "loadfile"},
}

local G = _G
__rb = {
  -- text, chunk name; ref: the handle of rt's globals, behind the chunk's own _ENV.
  load = function(ref, data)
    local v = decodeAll(data)
    if v[3] then __rb_memory_max(v[3]) end
    local globals = proxy(ref)
    local env = setmetatable({}, {__index = globals})
    local f, err = load(v[1], v[2], "t", env)
    if not f then return answer(false, err) end
    return answer(true, f)
  end,
  call = function(ref, data)
    local f = refs[ref]
    local args, n = decodeAll(data)
    if hookCount > 0 then dsethook(hook, "", hookCount) end
    return answer(pcall(f, tunpack(args, 1, n)))
  end,
  lib = function(_, data)
    local name = decodeAll(data)[1]
    local t = {}
    if name == "_G" then
      for _, k in ipairs(libraries._G) do t[k] = rawget(G, k) end
    else
      for k, v in next, G[name] or {} do t[k] = v end
    end
    return answer(true, t)
  end,
  hook = function(_, data)
    hookCount = decodeAll(data)[1]
    if hookCount == 0 then dsethook() end
    return "O"
  end,
  upvalue = function(ref, data)
    local v = decodeAll(data)
    return answer(true, dsetupvalue(refs[ref], v[1], v[2]))
  end,
}
`;

  return {
    open(L, rt) {
      const engine = new wasmoonEngine(luaModule);
      const opName = new Map();
      engine.global.set('__rb_js', (op, handle, data) => {
        let ops = opName.get(op);
        if (!ops) {
          ops = rt._malloc(op.length + 1);
          rt.stringToUTF8(op, ops, op.length + 1);
          opName.set(op, ops);
        }
        const bytes = rt.lengthBytesUTF8(data);
        const buffer = rt._malloc(bytes + 1);
        rt.stringToUTF8(data, buffer, bytes + 1);
        const out = rt._rb_shim_op(L, ops, handle, buffer, bytes);
        rt._free(buffer);
        const text = rt.UTF8ToString(out);
        rt._free(out);
        return text;
      });
      // The sandbox's memory limit for scripts, counted by wasmoon's own allocator.
      engine.global.set('__rb_memory_max', (bytes) => { engine.global.setMemoryMax(bytes); });
      engine.doStringSync(prelude);
      const table = engine.global.get('__rb');
      states.set(L, { engine, table, opName, rt });
    },
    close(L) {
      const state = states.get(L);
      if (!state) return;
      for (const p of state.opName.values()) state.rt._free(p);
      state.engine.global.close();
      states.delete(L);
    },
    request(L, op, ref, data) {
      const state = states.get(L);
      return state.table[op](ref, data);
    },
  };

  function wasmoonEngine(module) {
    // wasmoon's own conversions are not used: every value crosses as text (see the prelude).
    return new wasmoon.LuaEngine(module, { openStandardLibs: true, injectObjects: false, enableProxy: false,
                                          traceAllocations: true });
  }
}

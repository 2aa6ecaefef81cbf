-- batch-expect: skipped helper
-- objreader.lua: a 2014-style helper that turns OBJ text into the tables the old gr.mesh
-- takes (0-based faces). It uses string.gfind, as Lua 5.1 scenes did. No picture here.
function obj_tables(text)
  local verts, faces = {}, {}
  for line in string.gfind(text, '[^\n]+') do
    local kind, rest = string.match(line, '^(%a+)%s+(.*)$')
    if kind == 'v' then
      local v = {}
      for n in string.gfind(rest, '%S+') do table.insert(v, tonumber(n)) end
      table.insert(verts, v)
    elseif kind == 'f' then
      local f = {}
      for n in string.gfind(rest, '%d+') do table.insert(f, tonumber(n) - 1) end
      table.insert(faces, f)
    end
  end
  return verts, faces
end

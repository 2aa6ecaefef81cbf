-- rt-module: a helper for village-readobj-2014.lua, not a scene (tests/scenes/run_all.sh skips it)
-- readobj.lua: an OBJ reader in the style of the course's pre-2015 readobj.lua helper (Lua
-- 5.1, string.gfind). The original opened a file with io.open; a raybook scene runs in a
-- sandbox without io, so this one reads OBJ text from a Lua string instead.
--
--   require('readobj')
--   local verts, faces = readobj(text)
--   local node = gr.mesh('name', verts, faces)
--
-- It reads 'v x y z' and 'f a b c ...' lines (a corner may be written v, v/vt, v//vn or
-- v/vt/vn; only v is used) and ignores everything else. OBJ indices count from 1 (negative
-- ones from the end); the faces it returns count from 0, as the legacy gr.mesh expects.

function readobj(text)
  local verts = {}
  local faces = {}
  for line in string.gfind(text, '[^\n]+') do
    local words = {}
    for word in string.gfind(line, '%S+') do
      table.insert(words, word)
    end
    if words[1] == 'v' then
      table.insert(verts, {tonumber(words[2]), tonumber(words[3]), tonumber(words[4])})
    elseif words[1] == 'f' then
      local face = {}
      for k = 2, #words do
        local index = tonumber(string.gsub(words[k], '/.*', ''), 10)
        if index < 0 then index = #verts + 1 + index end
        table.insert(face, index - 1)
      end
      table.insert(faces, face)
    end
  end
  return verts, faces
end

-- rt-module: a helper for village-io-2012.lua, not a scene (tests/scenes/run_all.sh skips it)
-- readobj-io.lua: an OBJ reader written the way the course's pre-2015 readobj.lua was: it opens
-- the file with io.open, walks it with file:lines() and splits lines with string.gfind (a Lua
-- 5.0/5.1 name). raybook's sandbox offers a read-only io for exactly this: io.open may read
-- files under the scene's folder and the --assets folders, nothing else.
--
--   require('readobj-io')
--   local verts, faces = readobj('house.obj')
--   local node = gr.mesh('name', verts, faces)
--
-- It reads 'v x y z' and 'f a b c ...' lines (a corner may be written v, v/vt, v//vn or
-- v/vt/vn; only v is used) and ignores everything else. OBJ indices count from 1 (negative
-- ones from the end); the faces it returns count from 0, as the legacy gr.mesh expects.

function readobj(filename)
  local file, message = io.open(filename, 'r')
  if not file then
    error('readobj: ' .. message, 2)
  end
  local verts = {}
  local faces = {}
  for line in file:lines() do
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
  file:close()
  return verts, faces
end

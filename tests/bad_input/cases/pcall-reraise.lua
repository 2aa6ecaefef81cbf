-- A call made through pcall, its message raised again on the same line: the line once, never [C].
-- expect: gr.sphere: argument 1 (name) must be a string, got number
-- reject: pcall-reraise.lua:4: pcall-reraise.lua:4:
local ok, err = pcall(gr.sphere, 5) if not ok then error(err) end --!

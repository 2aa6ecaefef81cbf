-- rt-args: --legacy
-- A legacy table mesh with a 1-based index (the legacy form is 0-based). Lua names the line
-- where the call starts.
-- expect: gr.mesh: face 2 has an index that is not a vertex (0-based, below 3)
local m = gr.mesh('m', {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, --!
                  {{0, 1, 2}, {1, 2, 3}})

-- rt-args: --legacy
-- A legacy table mesh with a 2-D vertex. The vertices are gr.mesh's argument 2: the message
-- must name that argument and the vertex, not an internal stack slot.
-- expect: argument 2 (vertices): vertex 2
-- reject: argument 4
local m = gr.mesh('m', {{0, 0, 0}, {1, 0}, {0, 1, 0}}, {{0, 1, 2}}) --!

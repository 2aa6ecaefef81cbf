-- A scene that never calls gr.render.
-- expect: never calls gr.render
local root = gr.node('root')

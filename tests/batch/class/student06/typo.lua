-- batch-expect: error
-- Broken: a syntax error (a stray '<' where a value belongs), so the script never runs.
local root = gr.node('root')
local ball = gr.sphere('ball')
ball:set_material(gr.material({0.8, 0.2, 0.2}, {0.5, 0.5, 0.5}, < 25))
root:add_child(ball)
gr.render(root, 'typo.png', 64, 48, {0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 50,
          {0.2, 0.2, 0.2}, {gr.light({5, 5, 5}, {1, 1, 1}, {1, 0, 0})})

-- batch-expect: error
-- Broken: calls gr.torus, which is no call of the A4 language or of any seed.
local root = gr.node('root')
local ring = gr.torus('ring', 1.0, 0.3)
root:add_child(ring)
gr.render(root, 'torus.png', 64, 48, {0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 50,
          {0.2, 0.2, 0.2}, {gr.light({5, 5, 5}, {1, 1, 1}, {1, 0, 0})})

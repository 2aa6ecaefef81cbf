-- batch-expect: error
-- Broken: a scene left half written, with no gr.render yet and a 'function' without its
-- 'end'. It does not parse, so it is an error with its line, not a helper that renders nothing.
local root = gr.node('root')
function add_ball(name, x)
  local ball = gr.sphere(name)
  ball:translate(x, 0, 0)
  root:add_child(ball)

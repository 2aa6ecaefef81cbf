-- A scene lit only by lights under other names: gr.point_light, gr.arealight, gr.spot_light and
-- raybook's own gr.area_light called positionally. Each becomes a point light at its first
-- triple with the colour of the next one; the render says on one line that its lighting is
-- all stand-ins. Without --lenient the first is an error; with it the sphere is lit.
-- expect-error: other-lights.lua:11: gr.point_light is not a raybook call
-- expect-stderr: rt: warning: other-lights.lua:11: gr.point_light: --lenient stands in a point light at {0, 0, 10} of colour {0.5, 0.5, 0.5} (its first two triples)
-- expect-stderr: rt: warning: other-lights.lua:14: gr.spot_light: --lenient stands in a point light at {5, 5, 10} of colour {0.4, 0.4, 0.4} (its first two triples)
-- expect-stderr: rt: warning: other-lights.lua:21: gr.render: every light is a --lenient stand-in (point lights in place of gr.point_light, gr.arealight, gr.spot_light, gr.area_light): the lighting is a guess
-- expect-lit: 0.4 0.4 0.6 0.6
-- expect-black: 0 0 0.1 0.1
local a = gr.point_light({0, 0, 10}, {0.5, 0.5, 0.5}, {1, 0, 0})
local b = gr.arealight({position = {-5, 5, 10}, colour = {0.3, 0.3, 0.3}, size = 2})
-- A spot light: position, colour, falloff, direction and angle.
local c = gr.spot_light({5, 5, 10}, {0.4, 0.4, 0.4}, {1, 0, 0}, {0, 0, -1}, 30)
local d = gr.area_light({0, 5, 10}, {0.3, 0.3, 0.3}, {1, 0, 0}, 2, 2)
root = gr.node('root')
ball = gr.sphere('ball')
ball:scale(2, 2, 2)
ball:set_material(gr.material({0.8, 0.8, 0.8}, {0.2, 0.2, 0.2}, 10))
root:add_child(ball)
gr.render(root, 'out.png', 48, 36, {0, 0, 10}, {0, 0, -1}, {0, 1, 0}, 50, {0, 0, 0}, {a, b, c, d})

-- Uses every call the example dialect files in scenes/dialects/ define (ctest: dialect_examples).
root = gr.node('root')
local a = gr.sphere('a'); a:set_material(gr.mirror_material({0.2,0.2,0.2},{0.8,0.8,0.8},50,0.8)); root:add_child(a)
local b = gr.sphere('b'); b:translate(2.5,0,0); b:set_material(gr.glass_material({0.1,0.1,0.1},1.5)); root:add_child(b)
local c = gr.sphere('c'); c:translate(-2.5,0,0); c:set_material(gr.material({0.8,0.2,0.2},{0.5,0.5,0.5},20,0.2,0.5,1.3)); root:add_child(c)
local p = gr.plane('floor'); p:scale(10,1,10); p:translate(0,-1,0); p:set_material(gr.material({0.5,0.5,0.5},{0,0,0},1)); root:add_child(p)
local cy = gr.cylinder('cy'); cy:set_texture('wood.png'); cy:rotate_xyz(10,20,30); cy:translate(0,2.2,0); cy:set_material(gr.material({0.2,0.7,0.2},{0,0,0},1)); root:add_child(cy)
gr.render(root, 'd.png', 160, 120, {0,2,10}, {0,-0.2,-1}, {0,1,0}, 50, {0.2,0.2,0.2}, {gr.area_light_rect({0,6,3},{0.9,0.9,0.9},{1,0,0},2,2), gr.sphere_light({-4,5,5},{0.4,0.4,0.4},{1,0,0},0.5)})

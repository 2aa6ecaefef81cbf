-- Later chapters' calls with arguments of another course: a texture table whose image is a
-- number, a texture slot named 'diffuse', a bump table whose strength is a word, and seed
-- 000's keyword material with a keyword raybook does not know. The texture and bump calls are
-- ignored; the material is read without its keyword, a plain green Phong material.
-- expect-error: chapter-calls.lua:13: gr.texture: field 'image' must be a file name
-- expect-lenient: gr.texture (arguments raybook cannot read: field 'image' must be a file name; a stand-in took its place), first at chapter-calls.lua:13
-- expect-lenient: gr.material (arguments raybook cannot read: unknown keyword "mirror" (expected "reflect", "refract" or "glossy"); read with its first 3 arguments), first at chapter-calls.lua:14
-- expect-lenient: material:set_texture (arguments raybook cannot read: slot 'diffuse' must be 'kd' or 'ks'; the call was ignored), first at chapter-calls.lua:15
-- expect-lenient: material:set_bump (arguments raybook cannot read: field 'strength' must be a number, got string; the call was ignored), first at chapter-calls.lua:16
-- expect-green: 0.4 0.4 0.6 0.6
root = gr.node('root')
ball = gr.sphere('ball')
local wood = gr.texture{image = 42}
local m = gr.material({0.1, 0.8, 0.1}, {0.2, 0.2, 0.2}, 25, 'mirror', 0.5)
m:set_texture('diffuse', 'wood.png')
m:set_bump{pattern = 'noise', strength = 'strong'}
ball:set_material(m)
ball:scale(2, 2, 2)
root:add_child(ball)
gr.render(root, 'out.png', 48, 36, {0, 0, 10}, {0, 0, -1}, {0, 1, 0}, 50, {0.3, 0.3, 0.3},
          {gr.light({0, 0, 10}, {0.9, 0.9, 0.9}, {1, 0, 0})})

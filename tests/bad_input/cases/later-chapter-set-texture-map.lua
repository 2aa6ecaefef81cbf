-- skip-if-feature: texture
-- Seed 002's material:set_texture_map belongs to chapter 10: a build without it names it.
-- expect: method 'set_texture_map' needs chapter 10 (texture)
local m = gr.material({1, 1, 1}, {0, 0, 0}, 1)
m:set_texture_map('cup.png') --!

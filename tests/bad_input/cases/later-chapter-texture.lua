-- skip-if-feature: texture
-- Seed 000's gr.texture belongs to chapter 10: a build without it names the chapter.
-- expect: gr.texture needs chapter 10 (texture)
local m = gr.material({1, 1, 1}, {0, 0, 0}, 1)
gr.texture(m, 'wood.jpg') --!

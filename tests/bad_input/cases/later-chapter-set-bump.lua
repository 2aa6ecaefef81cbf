-- skip-if-feature: bump
-- material:set_bump belongs to chapter 11: a build without it names the chapter.
-- expect: method 'set_bump' needs chapter 11 (bump)
local m = gr.material({0.5, 0.5, 0.5}, {0.5, 0.5, 0.5}, 20)
m:set_bump{pattern = 'ripples', strength = 0.01, wavelength = 0.1} --!

-- skip-if-feature: bump
-- Seed 002's set_bump_map belongs to chapter 11: a build without it names the chapter.
-- expect: method 'set_bump_map' needs chapter 11 (bump)
local m = gr.material({0.5, 0.5, 0.5}, {0.5, 0.5, 0.5}, 20)
m:set_bump_map('ridges.png') --!

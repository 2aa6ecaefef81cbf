-- skip-if-feature: soft_shadows
-- Seed 001's rectangular area light needs the soft-shadows chapter.
-- expect: needs chapter 6 (soft_shadows)
local l = gr.light({0, 5, 0}, {1, 1, 1}, {1, 0, 0}, {1, 1}, {0, -1, 0}, {1, 0, 0}) --!

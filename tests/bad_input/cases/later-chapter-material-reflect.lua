-- skip-if-feature: reflection
-- Seed 000's gr.material(kd, ks, shin, "reflect", r) needs the reflection chapter.
-- expect: needs chapter 4 (reflection)
local m = gr.material({0.5, 0.5, 0.5}, {0.5, 0.5, 0.5}, 20, 'reflect', 0.5) --!

-- skip-if-feature: quadrics
-- gr.cyllinder (seed 001's spelling) belongs to chapter 15.
-- expect: gr.cyllinder needs chapter 15 (quadrics)
local c = gr.cyllinder('c') --!

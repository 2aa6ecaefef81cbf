-- skip-if-feature: csg
-- gr.union belongs to chapter 14: a build without it names the chapter.
-- expect: gr.union needs chapter 14 (csg)
local u = gr.union(gr.sphere('a'), gr.sphere('b')) --!

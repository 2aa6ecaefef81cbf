-- skip-if-feature: reflection
-- gr.phongMat (seed 001) belongs to a later chapter: the error names the chapter.
-- expect: gr.phongMat needs chapter 4 (reflection)
local m = gr.phongMat({0.5, 0.5, 0.5}, {0.5, 0.5, 0.5}, 20, 0.5, 0) --!

-- skip-if-feature: adaptive_aa
-- gr.antialias belongs to chapter 8: a build without it names the chapter.
-- expect: gr.antialias needs chapter 8 (adaptive_aa)
gr.antialias{sampler = 'adaptive'} --!

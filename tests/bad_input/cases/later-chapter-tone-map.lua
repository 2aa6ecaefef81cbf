-- skip-if-feature: tone_map
-- gr.tone_map belongs to chapter 12: a build without it names the chapter.
-- expect: gr.tone_map needs chapter 12 (tone_map)
gr.tone_map{operator = 'global'} --!

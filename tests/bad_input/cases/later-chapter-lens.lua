-- skip-if-feature: dof
-- gr.lens belongs to chapter 13: a build without it names the chapter.
-- expect: gr.lens needs chapter 13 (dof)
gr.lens{aperture = 0.2, focus = 8} --!

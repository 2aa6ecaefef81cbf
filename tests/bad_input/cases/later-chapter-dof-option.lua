-- skip-if-feature: dof
-- The lens options belong to chapter 13: a build without it names the chapter.
-- expect: 'dof_aperture' needs chapter 13 (dof)
gr.option('dof_aperture', 0.2) --!

-- needs-feature: path_tracing
-- A path of no bounces could not see anything: refused, naming the field and its range.
-- expect: gr.integrator: field 'max_depth' must be
gr.integrator{method = 'path', max_depth = 0} --!

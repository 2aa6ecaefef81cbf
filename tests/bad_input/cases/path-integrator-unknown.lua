-- needs-feature: path_tracing
-- An integrator raybook does not have: refused, naming the call and the two it has.
-- expect: gr.integrator: method must be 'path' or 'whitted'
gr.integrator('bidirectional') --!

-- A bad call inside table.sort's comparison: the comparison's line, not [C]:-1.
-- expect: gr.nh_sphere: argument 2 (centre) must be a table of 3 numbers, got a table of 2
-- reject: [C]
table.sort({3, 1, 2}, function(a, b)
  return gr.nh_sphere('s', {0, 0}, 1) --!
end)

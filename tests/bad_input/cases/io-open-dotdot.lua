-- A relative path that climbs out of the scene's folder is refused, whether or not the file
-- exists (tests/bad_input/x does not).
-- expect: io.open: cannot read '../x'
-- expect: raybook's sandbox reads only files under the scene's folder
-- expect: --assets DIR adds a folder
local f = io.open('../x') --!

-- error() with a table, not a message: the error says what was raised, at the line.
-- expect: the script raised an error whose value is a table, not a message
local code = 1
error({code = code}) --!

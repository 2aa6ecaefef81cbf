-- require of a long module name with a character a module name may not have (rt once leaked
-- the copy of a name this long: LeakSanitizer).
-- expect: may use only letters, digits
require('a_rather_long_module_name/with_a_slash') --!

-- require of an absolute path.
-- expect: require: module name '/etc/passwd'
require('/etc/passwd') --!

// rt_node.js: the page's rt (build-web/rt_web.js and rt_web.wasm, with wasmoon's Lua and
// src/web/lua_host.js, as the live panels' worker runs them) in node, for profiling and for
// comparing its images with native rt's.
//
//   node tests/perf/web/rt_node.js [--build-web DIR] [--runs N] [--out FILE.png] -- RT_ARGS...
//
// RT_ARGS are rt's own, with the scene under /scenes (the bundled scenes/ folder), e.g.
//   node --cpu-prof tests/perf/web/rt_node.js --out /tmp/ch17.png -- --size 160x120 \
//       --threads 1 /scenes/chapter17-media.lua
// rt writes its image to /tmp/out.png in its own file system, copied to --out. With --runs N
// rt renders N times in one instance (as the page does, one render after another) and prints
// each callMain's time on stderr. Exits with rt's exit code.
'use strict';
const fs = require('fs');
const path = require('path');
const vm = require('vm');

const root = path.resolve(__dirname, '..', '..', '..');
let buildWeb = path.join(root, 'build-web');
let out = null;
let runs = 1;
const argv = process.argv.slice(2);
let rtArgs = [];
for (let i = 0; i < argv.length; i++) {
  if (argv[i] === '--build-web') buildWeb = path.resolve(argv[++i]);
  else if (argv[i] === '--out') out = argv[++i];
  else if (argv[i] === '--runs') runs = Number(argv[++i]);
  else if (argv[i] === '--') { rtArgs = argv.slice(i + 1); break; }
  else { console.error('rt_node.js: unknown option ' + argv[i]); process.exit(2); }
}

const wasmoonDir = path.join(buildWeb, 'npm', 'node_modules', 'wasmoon');
global.wasmoon = require(wasmoonDir);
vm.runInThisContext(fs.readFileSync(path.join(root, 'src', 'web', 'lua_host.js'), 'utf8'),
                    {filename: 'lua_host.js'});
const createRaybook = require(path.join(buildWeb, 'rt_web.js'));

(async () => {
  const factory = new wasmoon.LuaFactory(path.join(wasmoonDir, 'dist', 'glue.wasm'));
  const host = await createLuaHost(factory); // eslint-disable-line no-undef
  const rt = await createRaybook({
    // Given, since emscripten 3.1.6's own load of rt_web.wasm in node tries fetch() on a path.
    wasmBinary: fs.readFileSync(path.join(buildWeb, 'rt_web.wasm')),
    luaHost: host,
    print: (s) => process.stdout.write(s + '\n'),
    printErr: (s) => process.stderr.write(s + '\n'),
  });
  const args = out ? [...rtArgs, '--output', '/tmp/out.png'] : rtArgs;
  let code = 0;
  for (let r = 0; r < runs; r++) {
    const t0 = performance.now();
    try {
      code = rt.callMain(args);
    } catch (e) {
      if (e && e.name === 'ExitStatus') code = e.status;
      else throw e;
    }
    if (runs > 1) process.stderr.write('rt_node.js: run ' + (r + 1) + ': ' +
                                       ((performance.now() - t0) / 1000).toFixed(3) + ' s\n');
  }
  if (out && code === 0) fs.writeFileSync(out, rt.FS.readFile('/tmp/out.png'));
  process.exitCode = code;
})();

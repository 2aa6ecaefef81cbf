// raybook's live panels: the Web Worker that runs rt (see src/web/panel.js for the page side).
//
// bundle.py builds the worker's source from, in this order: wasmoon's dist/index.js (defines
// self.wasmoon), `var RB_GLUE_B64 = "..."` (wasmoon's glue.wasm in base64), lua_host.js
// (defines createLuaHost), rt_web.js (defines createRaybook, the whole rt program built with
// emscripten, single-threaded, the repository's scenes/ folder at /scenes) and this file. The
// page starts it from a Blob URL, so it works from file:// as well as from a server, and
// stops an endless render with worker.terminate().
//
// Messages in:  {type: 'init'}
//               {type: 'render', id, scene, text, features, size}
// Messages out: {type: 'ready', features: [{chapter, name, on, core, what}], ms}
//               {type: 'done', id, code, png (ArrayBuffer or null), out, err, ms}
//               {type: 'failed', id, message}   (rt could not be started or aborted)
'use strict';

// wasmoon loads glue.wasm through emscripten's locateFile: a data: URI is fetched in place
// (Chromium fetches data: URIs in a worker, file:// page or not), so nothing else is loaded.
const RB_GLUE_URI = 'data:application/octet-stream;base64,' + RB_GLUE_B64;

let rbFactory = null; // one wasmoon LuaFactory (the compiled Lua VM) for the worker's life
let rbRt = null;      // the rt instance; dropped after an abort, made again on the next render
let rbOut = '';
let rbErr = '';

async function rbInstance() {
  if (rbRt) return rbRt;
  if (!rbFactory) rbFactory = new wasmoon.LuaFactory(RB_GLUE_URI);
  const host = await createLuaHost(rbFactory);
  rbRt = await createRaybook({
    luaHost: host,
    print: (s) => { rbOut += s + '\n'; },
    printErr: (s) => { rbErr += s + '\n'; },
  });
  return rbRt;
}

// Runs rt with ARGS; returns its exit code, or throws when rt aborted (the instance is then
// dropped, so the next run starts a fresh one).
function rbRun(rt, args) {
  rbOut = '';
  rbErr = '';
  try {
    return rt.callMain(args);
  } catch (e) {
    rbRt = null;
    // emscripten's exit() unwinds with an ExitStatus; anything else is an abort.
    if (e && e.name === 'ExitStatus' && typeof e.status === 'number') return e.status;
    throw e;
  }
}

// ./rt --list-features: " 1  raycast        on   rays, ... (core)"
function rbParseFeatures(text) {
  const features = [];
  for (const line of text.split('\n')) {
    const m = /^\s*(\d+)\s+(\S+)\s+(on|off)\s+(.*?)\s*$/.exec(line);
    if (!m) continue;
    features.push({chapter: Number(m[1]), name: m[2], on: m[3] === 'on',
                   core: /\(core\)$/.test(m[4]), what: m[4].replace(/\s*\(core\)$/, '')});
  }
  return features;
}

async function rbInit() {
  const t0 = performance.now();
  const rt = await rbInstance();
  const code = rbRun(rt, ['--list-features']);
  if (code !== 0) throw new Error('rt --list-features exited with ' + code + ': ' + rbErr);
  return {type: 'ready', features: rbParseFeatures(rbOut), ms: performance.now() - t0};
}

async function rbRender(m) {
  const rt = await rbInstance();
  // The edited scene replaces the bundled one in its own folder, so that the meshes, textures
  // and require()d files it names resolve as they do for ./rt scenes/NAME.lua.
  const scene = '/scenes/' + m.scene;
  rt.FS.writeFile(scene, m.text);
  try { rt.FS.unlink('/tmp/out.png'); } catch (e) { /* not there */ }
  const args = ['--features=' + m.features, '--size', m.size, '--threads', '1',
                '--output', '/tmp/out.png', scene];
  const t0 = performance.now();
  const code = rbRun(rt, args);
  const ms = performance.now() - t0;
  let png = null;
  if (code === 0) {
    try {
      png = rt.FS.readFile('/tmp/out.png').slice().buffer; // a copy, out of the wasm heap
    } catch (e) {
      rbErr += 'rt exited with 0 but wrote no image\n';
    }
  }
  return {type: 'done', id: m.id, code, png, out: rbOut, err: rbErr, ms, args};
}

// One message at a time: the page sends the next render only after 'done'.
let rbQueue = Promise.resolve();
self.onmessage = (e) => {
  const m = e.data;
  rbQueue = rbQueue.then(async () => {
    try {
      if (m.type === 'init') {
        self.postMessage(await rbInit());
      } else if (m.type === 'render') {
        const r = await rbRender(m);
        self.postMessage(r, r.png ? [r.png] : []);
      }
    } catch (e) {
      rbRt = null;
      self.postMessage({type: 'failed', id: m.id, message: String(e && e.stack || e),
                        err: rbErr});
    }
  });
};

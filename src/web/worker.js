// raybook's live panels: the Web Worker that runs rt (see src/web/panel.js for the page side).
//
// bundle.py builds the worker's source from, in this order: wasmoon's dist/index.js (defines
// self.wasmoon), lua_host.js (defines createLuaHost), rt_web.js (defines createRaybook, the
// JavaScript half of the whole rt program built with emscripten, single-threaded) and this
// file. The page starts it from a Blob URL, so it works from file:// as well as from a server,
// and stops an endless render with worker.terminate(). The WebAssembly comes with 'init':
// rt's module, compiled once by the page for all its workers (the repository's scenes/ folder
// inside, at /scenes), and the bytes of wasmoon's glue.wasm.
//
// Messages in:  {type: 'init', rt: WebAssembly.Module, glue: ArrayBuffer}
//               {type: 'render', id, scene, text, features, size, extra, progress}
//                 extra: more options for rt (the page's previews: --preview --spp N ...);
//                 progress: true to send rt's progress bar while it renders
// Messages out: {type: 'ready', features: [{chapter, name, on, core, what}], ms, origin, phases}
//                 ms: from 'init' to ready; phases: when (ms after the worker's start, at
//                 ORIGIN, its performance.timeOrigin) its script had run, and wasmoon, rt
//                 and rt --list-features were ready
//               {type: 'progress', id, line}   (each redraw of the bar, while rt runs)
//               {type: 'done', id, code, png (ArrayBuffer or null), out, err, ms}
//               {type: 'failed', id, message}   (rt could not be started or aborted)
'use strict';

const rbPhases = {script: performance.now()};
let rbModule = null;  // rt's WebAssembly.Module, from 'init'
let rbGlueUrl = null; // wasmoon's glue.wasm, from 'init', as a Blob URL of this worker's
let rbFactory = null; // one wasmoon LuaFactory (the compiled Lua VM) for the worker's life
let rbRt = null;      // the rt instance; dropped after an abort, made again on the next render
let rbOut = '';
let rbErr = '';
let rbProgress = null; // called with each line of rt's progress bar, during a render that asks

// rt draws its progress bar on stderr (a terminal here), each redraw after a carriage return,
// but emscripten's terminal hands its text on only at a newline, when the render is over. So
// the terminal's put_char is watched: a carriage return ends the line drawn before it, which
// goes to rbProgress at once (a worker's postMessage is sent while rt still runs).
function rbWatchProgress(rt) {
  const ops = rt.FS.getStream(2).tty.ops;
  const putChar = ops.put_char;
  ops.put_char = (tty, byte) => {
    if (byte === 13 && rbProgress) {
      let start = tty.output.length;
      while (start > 0 && tty.output[start - 1] !== 13) start--;
      const line = new TextDecoder().decode(Uint8Array.from(tty.output.slice(start))).trim();
      if (line) rbProgress(line);
    }
    putChar(tty, byte);
  };
}

async function rbInstance() {
  if (rbRt) return rbRt;
  if (!rbModule) throw new Error('rt was asked to run before the worker\'s init');
  // wasmoon loads glue.wasm through emscripten's locateFile, from this URL.
  if (!rbFactory) rbFactory = new wasmoon.LuaFactory(rbGlueUrl);
  const host = await createLuaHost(rbFactory);
  if (!rbPhases.wasmoon) rbPhases.wasmoon = performance.now();
  // rt's module is the page's, compiled once: here it is only instantiated (and after an abort,
  // instantiated again, with a fresh memory).
  let failed;
  const failure = new Promise((resolve, reject) => { failed = reject; });
  rbRt = await Promise.race([failure, createRaybook({
    luaHost: host,
    print: (s) => { rbOut += s + '\n'; },
    printErr: (s) => { rbErr += s + '\n'; },
    instantiateWasm: (imports, receive) => {
      WebAssembly.instantiate(rbModule, imports).then((instance) => receive(instance, rbModule),
                                                     failed);
      return {};
    },
  })]);
  if (!rbPhases.rt) rbPhases.rt = performance.now();
  rbWatchProgress(rbRt);
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

async function rbInit(m) {
  const t0 = performance.now();
  rbPhases.init = t0;
  rbModule = m.rt;
  rbGlueUrl = URL.createObjectURL(new Blob([m.glue], {type: 'application/wasm'}));
  const rt = await rbInstance();
  const code = rbRun(rt, ['--list-features']);
  if (code !== 0) throw new Error('rt --list-features exited with ' + code + ': ' + rbErr);
  rbPhases.features = performance.now();
  return {type: 'ready', features: rbParseFeatures(rbOut), ms: performance.now() - t0,
          origin: performance.timeOrigin, phases: rbPhases};
}

async function rbRender(m) {
  const rt = await rbInstance();
  // The edited scene replaces the bundled one in its own folder, so that the meshes, textures
  // and require()d files it names resolve as they do for ./rt scenes/NAME.lua.
  const scene = '/scenes/' + m.scene;
  rt.FS.writeFile(scene, m.text);
  try { rt.FS.unlink('/tmp/out.png'); } catch (e) { /* not there */ }
  const args = ['--features=' + m.features, '--size', m.size, '--threads', '1',
                ...(m.extra || []), '--output', '/tmp/out.png', scene];
  rbProgress = m.progress ? (line) => self.postMessage({type: 'progress', id: m.id, line}) : null;
  const t0 = performance.now();
  let code;
  try {
    code = rbRun(rt, args);
  } finally {
    rbProgress = null;
  }
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
        self.postMessage(await rbInit(m));
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

// raybook's live panels: the page side. bundle.py wraps this file in raybook-live.js with
//   RB_WORKER_SOURCE  the worker's whole source (wasmoon, lua_host.js, rt_web.js, worker.js),
//                     started from a Blob URL so that file:// pages work too;
//   RB_RT_WASM        rt_web.wasm, gzip'd, in base64: compiled once when the page opens, for
//                     every worker it starts;
//   RB_GLUE_WASM      wasmoon's glue.wasm (Lua), gzip'd, in base64;
//   RB_SCENES         {"chapter05-refraction.lua": "...the scene's text...", ...};
//   RB_CSS            panel.css.
// Every <div class="rb-live" data-scene="chapterNN-....lua" data-chapter="N"> on the page
// becomes a panel: the scene in a text box, the chapter switches (rt --features), the size, a
// Render and a Stop button, a canvas and rt's messages.
//
// Progressive: while rt renders the picture, a second worker renders previews of it with
// rt --preview (no antialiasing, one sample of each area light, glossy lobe, lens and photon
// pass for each of a pixel's samples): a quarter of each side at one sample a pixel, then the
// full size at 1, 4, 16, ... samples a pixel (under a target error: at 8, 4 and 2 times the
// target). Each is drawn when it arrives, and the render itself (the command line's options, so
// the command line's pixels) replaces the last. A preview starts only if rt's progress bar says
// it should finish before the picture; the status line shows the bar's fraction, time left and,
// under a target error, its error estimate.
//
// Each panel starts its rt (a worker, rt instantiated, rt --list-features) when the page opens,
// and keeps it for every render after, so Render finds it ready.
//
// For tests: window.raybookLive.panels[i].render({size, text, features}) returns a promise of
// {code, err, out, ms, args, pixels (canvas.toDataURL of the drawn image), frames (the
// previews drawn before it, in order: {label, size, spp, error, ms, at, pixels}), t0 and shown
// (performance.now() when the render was asked for and its picture drawn)}; panels[i].readyInfo
// says when its rt was ready ({at: performance.now(), worker: the worker's phases}); and a page
// opened with ?rb-autorender=WxH renders its first panel at that size when it loads and writes
// that result (the frames without their pixels) as JSON into <pre id="rb-autorender-result">.
'use strict';

const RB_SIZES = ['160x120', '320x240', '640x480'];
// Previews begin only for a render with at least this many seconds left, on a machine with a
// core to spare for them.
const RB_PREVIEW_MIN_SECONDS = 1;

// The WebAssembly modules, unpacked from the bundle and compiled once (the first panel asks,
// when the page opens): {rt: WebAssembly.Module, glue: ArrayBuffer}. The compiling runs off
// the page's thread, while the first worker reads its script.
let rbWasmReady = null;
function rbWasm() {
  if (!rbWasmReady) {
    const rt = rbGunzip(RB_RT_WASM);
    rbWasmReady = Promise.all([
      typeof WebAssembly.compileStreaming === 'function'
        ? WebAssembly.compileStreaming(new Response(rt, {headers: {'Content-Type': 'application/wasm'}}))
        : new Response(rt).arrayBuffer().then((bytes) => WebAssembly.compile(bytes)),
      new Response(rbGunzip(RB_GLUE_WASM)).arrayBuffer(),
    ]).then(([rt, glue]) => ({rt, glue}));
  }
  return rbWasmReady;
}

// The stream of bytes that B64 (gzip'd, in base64) packs.
function rbGunzip(b64) {
  let bytes;
  if (typeof Uint8Array.fromBase64 === 'function') {
    bytes = Uint8Array.fromBase64(b64);
  } else {
    const text = atob(b64);
    bytes = new Uint8Array(text.length);
    for (let i = 0; i < text.length; i++) bytes[i] = text.charCodeAt(i);
  }
  return new Blob([bytes]).stream().pipeThrough(new DecompressionStream('gzip'));
}

let rbWorkerUrl = null;
function rbNewWorker() {
  if (!rbWorkerUrl) {
    rbWorkerUrl = URL.createObjectURL(new Blob([RB_WORKER_SOURCE], {type: 'text/javascript'}));
  }
  return new Worker(rbWorkerUrl);
}

// rt's output as a terminal would leave it: a progress bar redrawn with carriage returns
// (rt's WebAssembly build writes one, since its stderr counts as a terminal) keeps only what
// follows the last return of its line.
function rbTerminal(text) {
  return text.split('\n').map((l) => l.slice(l.lastIndexOf('\r') + 1)).join('\n');
}

// rt's progress line, "[#####     ]  48%  elapsed 3.1 s  ETA 3.4 s  12.3 Mrays/s" (under a
// target error the last field is "error 0.031/0.02"): {fraction, left (seconds, or Infinity
// while unknown), error and target (the finished pixels' estimated error and the target, or
// null)}; null for any other line.
function rbParseProgress(line) {
  const m = /^\[[# ]*\]\s*(\d+)%  elapsed (.+?)  ETA (.+?)  (.+)$/.exec(line);
  if (!m) return null;
  const fraction = Number(m[1]) / 100;
  const elapsed = rbSeconds(m[2]);
  let left = rbSeconds(m[3]);
  // No ETA yet ("..."): rt has not measured every band of the image; assume the rest goes
  // as fast as what is done.
  if (left === null) {
    left = fraction > 0 && elapsed !== null ? elapsed * (1 - fraction) / fraction : Infinity;
  }
  const error = /^error (\S+)\/(\S+)$/.exec(m[4]);
  return {fraction, left, error: error ? Number(error[1]) : null,
          target: error ? Number(error[2]) : null};
}

// Seconds of rt's durations ("3.4 s", "2 min 05 s", "1 h 02 min"); null for "...".
function rbSeconds(text) {
  let m;
  if ((m = /^([\d.]+) s$/.exec(text))) return Number(m[1]);
  if ((m = /^(\d+) min (\d+) s$/.exec(text))) return 60 * Number(m[1]) + Number(m[2]);
  if ((m = /^(\d+) h (\d+) min$/.exec(text))) return 3600 * Number(m[1]) + 60 * Number(m[2]);
  return null;
}

// Preview pass K of a WxH render: first rt --preview's own size (a quarter of each side) at one
// sample a pixel, then the full size at 4^(K-1) samples a pixel. Each pass costs about four
// times the one before (after the first, sixteen). A render to a TARGET error (--target-error)
// replaces the samples with a target, 8 times TARGET for the first two, then 4 and 2 times:
// a quarter of the time each; null after that.
function rbPreviewPass(k, size, target) {
  const [w, h] = size.split('x').map(Number);
  const quarter = (n) => Math.max(1, Math.floor((n + 2) / 4));
  const pass = {size: k === 0 ? quarter(w) + 'x' + quarter(h) : size, spp: null, error: null};
  const where = k === 0 ? 'a quarter of the size, ' : '';
  // --stats tells the render's time from the rest, and a target error's estimate.
  pass.extra = ['--preview', '--quiet', '--stats'];
  if (target) {
    if (k > 3) return null;
    pass.error = target * 2 ** (k === 0 ? 3 : 4 - k);
    pass.label = where + 'to an error of ' + pass.error.toPrecision(2);
    pass.extra.push('--target-error', String(pass.error));
    return pass;
  }
  pass.spp = k === 0 ? 1 : 4 ** (k - 1);
  pass.label = where + pass.spp + (pass.spp === 1 ? ' sample' : ' samples') + ' a pixel';
  // The photon passes (chapter 16) and the lamp points of a medium (chapter 17, which are a
  // pixel's, shared by its samples) grow with the samples; every other count stays at one
  // sample for each of a pixel's samples.
  pass.extra.push('--spp', String(pass.spp), '--photon-passes=' + pass.spp,
                  '--media-points=' + Math.min(pass.spp, 1024));
  return pass;
}

function rbLoad(key) {
  try { return window.localStorage.getItem(key); } catch (e) { return null; }
}

function rbSave(key, value) {
  try {
    if (value === null) window.localStorage.removeItem(key);
    else window.localStorage.setItem(key, value);
  } catch (e) { /* storage off or full: the edit lasts until the page is left */ }
}

function rbEl(tag, attrs, children) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs || {})) {
    if (k === 'text') e.textContent = v;
    else if (k.startsWith('on')) e.addEventListener(k.slice(2), v);
    else e.setAttribute(k, v);
  }
  for (const c of children || []) e.appendChild(c);
  return e;
}

class RbPanel {
  constructor(root) {
    this.root = root;
    this.scene = root.dataset.scene;
    this.chapter = Number(root.dataset.chapter || 17);
    this.original = RB_SCENES[this.scene];
    this.worker = null;
    this.ready = null;      // promise of the worker's 'ready' message
    this.features = null;   // rt --list-features, parsed
    this.pending = null;    // {id, resolve, reject} of the render in flight
    this.run = null;        // the render in flight: its request, progress and previews
    this.previewer = null;  // the previews' worker, started with the first render
    this.drawing = Promise.resolve(); // the canvas's draws, one after the other
    this.nextId = 1;
    this.build();
  }

  build() {
    const root = this.root;
    root.textContent = '';
    root.classList.add('rb-live-on');
    if (this.original === undefined) {
      root.appendChild(rbEl('p', {class: 'rb-msg rb-error',
                                  text: 'raybook live: no bundled scene named ' + this.scene}));
      return;
    }
    this.text = rbEl('textarea', {class: 'rb-text', spellcheck: 'false', rows: '18',
                                   'aria-label': 'scene ' + this.scene});
    // The reader's edit survives a reload (kept per scene in localStorage, when the browser
    // allows it); Reset scene puts the chapter's own text back and forgets the edit.
    this.storeKey = 'raybook-live:' + this.scene;
    const kept = rbLoad(this.storeKey);
    this.text.value = kept !== null && kept !== this.original ? kept : this.original;
    this.text.addEventListener('input', () => {
      clearTimeout(this.saveTimer);
      this.saveTimer = setTimeout(() => {
        if (this.text.value === this.original) rbSave(this.storeKey, null);
        else rbSave(this.storeKey, this.text.value);
      }, 300);
    });
    this.text.addEventListener('keydown', (e) => {
      if (e.key === 'Enter' && (e.ctrlKey || e.metaKey)) { e.preventDefault(); this.onRender(); }
      if (e.key === 'Tab' && !e.shiftKey && !e.ctrlKey && !e.altKey) {
        e.preventDefault();
        this.text.setRangeText('  ', this.text.selectionStart, this.text.selectionEnd, 'end');
      }
    });
    this.switches = rbEl('span', {class: 'rb-switches', text: 'chapters: loading rt…'});
    this.size = rbEl('select', {class: 'rb-size', 'aria-label': 'image size'},
                     RB_SIZES.map((s) => rbEl('option', {value: s, text: s.replace('x', ' × ')})));
    this.renderButton = rbEl('button', {type: 'button', class: 'rb-render', text: 'Render',
                                        title: 'render the scene (Ctrl+Enter in the text)',
                                        onclick: () => this.onRender()});
    this.stopButton = rbEl('button', {type: 'button', class: 'rb-stop', text: 'Stop',
                                      disabled: '', onclick: () => this.stop('stopped')});
    this.resetButton = rbEl('button', {type: 'button', class: 'rb-reset', text: 'Reset scene',
                                       title: 'put the chapter\'s scene back in the text box',
                                       onclick: () => {
                                         this.text.value = this.original;
                                         rbSave(this.storeKey, null);
                                         this.show('', '');
                                       }});
    this.status = rbEl('span', {class: 'rb-status', role: 'status'});
    this.canvas = rbEl('canvas', {class: 'rb-canvas', width: '160', height: '120'});
    this.messages = rbEl('pre', {class: 'rb-msg'});
    root.appendChild(rbEl('div', {class: 'rb-head'}, [
      rbEl('span', {class: 'rb-title', text: 'scenes/' + this.scene}),
      this.resetButton]));
    root.appendChild(this.text);
    root.appendChild(rbEl('div', {class: 'rb-controls'}, [this.switches]));
    root.appendChild(rbEl('div', {class: 'rb-controls'}, [
      rbEl('label', {text: 'size '}, [this.size]), this.renderButton, this.stopButton,
      this.status]));
    root.appendChild(rbEl('div', {class: 'rb-view'}, [this.canvas]));
    root.appendChild(this.messages);
    if (this.text.value !== this.original) {
      this.show('', 'This is your edited scene from an earlier visit; Reset scene puts the ' +
                    'chapter\'s own back.');
    }
    this.start();
  }

  // Starts a worker (and rt in it) unless one runs; resolves once rt listed its features.
  start() {
    if (this.ready) return this.ready;
    const worker = rbNewWorker();
    this.worker = worker;
    this.ready = new Promise((resolve, reject) => {
      worker.onmessage = (e) => {
        const m = e.data;
        if (m.type === 'ready') {
          this.readyInfo = {at: performance.now(), worker: {origin: m.origin - performance.timeOrigin,
                                                            phases: m.phases}};
          this.showSwitches(m.features);
          resolve();
          // The previews' rt starts now too, so that the first render's previews find it ready.
          this.startPreviewer();
        } else if (m.type === 'progress') {
          this.onProgress(m);
        } else if (m.type === 'done' || m.type === 'failed') {
          if (m.type === 'failed' && !this.features) reject(new Error(m.message));
          this.finish(m);
        }
      };
      worker.onerror = (e) => {
        const message = 'the worker stopped: ' + (e.message || 'an error');
        reject(new Error(message));
        this.finish({type: 'failed', message});
      };
    });
    this.ready.catch((e) => {
      this.switches.textContent = 'chapters: rt did not start';
      this.show('error', String(e.message || e));
    });
    rbWasm().then((wasm) => worker.postMessage({type: 'init', rt: wasm.rt, glue: wasm.glue}),
                  (e) => worker.onmessage({data: {type: 'failed', message:
                    'this browser could not unpack or compile rt\'s WebAssembly: ' + (e.message || e)}}));
    return this.ready;
  }

  showSwitches(features) {
    const keep = this.features; // after Stop: keep what the reader switched
    this.features = features;
    this.switches.textContent = 'chapters: ';
    this.boxes = [];
    for (const f of features) {
      // A later chapter in rt's core (2 phong, 3 bvh) is shown too, checked and disabled: it
      // stays on (chapter 1's scene is shaded as from chapter 2 on, unlike make chapter1's rt).
      if (f.chapter > this.chapter && !f.core) continue;
      const box = rbEl('input', {type: 'checkbox', value: f.name});
      box.checked = keep && this.prevBoxes ? (this.prevBoxes[f.name] ?? true) : true;
      if (f.core) { box.checked = true; box.disabled = true; }
      this.boxes.push(box);
      this.switches.appendChild(rbEl('label', {
        class: 'rb-switch', title: 'chapter ' + f.chapter + ': ' + f.what +
          (f.core ? ' (core: always on)' : '')}, [box, document.createTextNode(
          ' ' + f.chapter + ' ' + f.name)]));
    }
  }

  // rt --features for the boxes: all, minus the chapters switched off.
  featureArg() {
    const off = (this.boxes || []).filter((b) => !b.checked && !b.disabled).map((b) => '-' + b.value);
    return ['all'].concat(off).join(',');
  }

  // After an error naming a line of the scene (/scenes/NAME.lua:LINE: ...), a link that
  // selects that line in the text box.
  linkLine(log) {
    const m = new RegExp(this.scene.replace(/[.]/g, '[.]') + ':(\\d+):').exec(log);
    if (!m) return;
    const line = Number(m[1]);
    this.messages.appendChild(document.createTextNode('\n'));
    this.messages.appendChild(rbEl('a', {href: '#', class: 'rb-goto', text: 'show line ' + line,
                                         onclick: (e) => { e.preventDefault(); this.selectLine(line); }}));
  }

  selectLine(line) {
    const lines = this.text.value.split('\n');
    if (line < 1 || line > lines.length) return;
    let start = 0;
    for (let i = 0; i < line - 1; i++) start += lines[i].length + 1;
    this.text.focus();
    this.text.setSelectionRange(start, start + lines[line - 1].length);
    // Scroll the line into the middle of the box.
    const lineHeight = this.text.scrollHeight / lines.length;
    this.text.scrollTop = Math.max(0, (line - 1) * lineHeight - this.text.clientHeight / 2);
  }

  show(kind, text) {
    this.messages.textContent = text;
    this.messages.className = 'rb-msg' + (kind ? ' rb-' + kind : '');
  }

  busy(on) {
    this.renderButton.disabled = on;
    if (on) this.stopButton.removeAttribute('disabled');
    else this.stopButton.setAttribute('disabled', '');
  }

  onRender() {
    this.render({}).catch(() => { /* shown in the panel */ });
  }

  render(opts) {
    if (this.pending) return Promise.reject(new Error('a render is running'));
    if (opts.text !== undefined) this.text.value = opts.text;
    if (opts.size) {
      if (!RB_SIZES.includes(opts.size)) this.size.appendChild(rbEl('option', {value: opts.size, text: opts.size}));
      this.size.value = opts.size;
    }
    const id = this.nextId++;
    const size = this.size.value;
    const text = this.text.value;
    this.busy(true);
    this.t0 = performance.now();
    this.status.textContent = 'starting rt…';
    this.tick = setInterval(() => this.showProgress(), 200);
    return new Promise((resolve, reject) => {
      this.pending = {id, resolve, reject};
      this.start().then(() => {
        if (!this.pending || this.pending.id !== id) return;
        const features = opts.features || this.featureArg();
        this.run = {id, size, text, features, progress: null, previews: null, frames: []};
        this.status.textContent = 'rendering…';
        this.worker.postMessage({type: 'render', id, scene: this.scene, text, size, features,
                                 progress: true});
        this.startPreviewer();
      }, (e) => this.finish({type: 'failed', id, message: String(e.message || e)}));
    });
  }

  // The status line while rt renders: the time, the bar's fraction, ETA and error estimate,
  // and which preview the canvas shows.
  showProgress() {
    const run = this.run;
    let text = 'rendering… ' + ((performance.now() - this.t0) / 1000).toFixed(1) + ' s';
    const p = run && run.progress;
    if (p) {
      text += ', ' + Math.round(100 * p.fraction) + '% done';
      const left = this.secondsLeft(run);
      if (left < Infinity) text += ', about ' + Math.max(0, left).toFixed(1) + ' s left';
      if (p.target) {
        text += ', estimated error ' + p.error.toPrecision(2) + ' (target ' + p.target + ')';
      }
    }
    const frame = run && run.frames[run.frames.length - 1];
    if (frame) text += ' · shown: a preview, ' + frame.label;
    this.status.textContent = text;
  }

  // The seconds rt's last progress line left for the render, less those gone by since.
  secondsLeft(run) {
    const p = run.progress;
    return p ? p.left - (performance.now() - p.at) / 1000 : Infinity;
  }

  onProgress(m) {
    const run = this.run;
    if (!run || m.id !== run.id) return;
    const p = rbParseProgress(m.line);
    if (!p) return;
    run.progress = Object.assign(p, {at: performance.now()});
    this.showProgress();
    if (!run.previews && this.previewer && this.secondsLeft(run) >= RB_PREVIEW_MIN_SECONDS) {
      run.previews = {k: 0, busy: false, done: false, last: null, target: p.target};
      this.nextPreview(run);
    }
  }

  // Sends the next preview pass to the previews' worker, unless it would end after the render.
  // A pass costs what the last did (the script, building the scene), except that its render
  // (--stats) takes 16 times as long (a quarter of each side to the full size) or 4 times (four
  // times the samples).
  nextPreview(run) {
    const pv = run.previews;
    if (this.run !== run || pv.done) return;
    if (pv.last && pv.last.seconds - pv.last.render + pv.last.render * (pv.k === 1 ? 16 : 4) >
                   this.secondsLeft(run)) {
      pv.done = true;
      return;
    }
    const pass = rbPreviewPass(pv.k, run.size, pv.target);
    if (!pass) {
      pv.done = true;
      return;
    }
    this.startPreviewer();
    pv.busy = true;
    this.previewer.postMessage({type: 'render', id: run.id, scene: this.scene, text: run.text,
                                size: pass.size, features: run.features, extra: pass.extra});
  }

  // Starts the previews' worker and its rt, unless it runs: once the panel's own rt is ready
  // (and again with a render, after a preview was stopped), so that a render that needs
  // previews finds it ready. Not on a machine with one core.
  startPreviewer() {
    if (this.previewer || (navigator.hardwareConcurrency || 1) < 2) return;
    this.previewer = rbNewWorker();
    this.previewer.onmessage = (e) => this.onPreview(e.data);
    this.previewer.onerror = () => this.endPreviews(true);
    const previewer = this.previewer;
    rbWasm().then((wasm) => previewer.postMessage({type: 'init', rt: wasm.rt, glue: wasm.glue}),
                  () => { if (this.previewer === previewer) this.endPreviews(true); });
  }

  onPreview(m) {
    const run = this.run;
    if (!run || !run.previews || m.id !== run.id) return;
    const pv = run.previews;
    pv.busy = false;
    // A preview that fails says nothing: the render itself reports the scene's errors.
    if (m.type !== 'done' || m.code !== 0 || !m.png) {
      pv.done = true;
      return;
    }
    const pass = rbPreviewPass(pv.k, run.size, pv.target);
    const render = /\brender ([\d.]+) s/.exec(m.err);
    const error = /estimated RMS error (\S+)/.exec(m.err);
    if (error) pass.label += ' (estimated ' + Number(error[1]).toPrecision(2) + ')';
    pv.last = {seconds: m.ms / 1000, render: render ? Number(render[1]) : m.ms / 1000};
    pv.k++;
    this.queueDraw(m.png, run.size, () => this.run === run).then((drawn) => {
      if (!drawn) return;
      run.frames.push({label: pass.label, size: pass.size, spp: pass.spp, error: pass.error,
                       ms: m.ms, at: performance.now() - this.t0,
                       pixels: this.canvas.toDataURL('image/png')});
      this.showProgress();
    });
    this.nextPreview(run);
  }

  // Ends the previews of the render in flight: a pass still running is stopped with its worker
  // (the next render starts another), as is the worker in any case when it FAILED.
  endPreviews(failed) {
    const pv = this.run && this.run.previews;
    if (this.previewer && (failed || (pv && pv.busy))) {
      this.previewer.terminate();
      this.previewer = null;
    }
    if (pv) pv.done = true;
  }

  async finish(m) {
    const p = this.pending;
    if (!p || (m.id !== undefined && m.id !== p.id)) return;
    this.pending = null;
    clearInterval(this.tick);
    this.busy(false);
    const run = this.run;
    const frames = run ? run.frames : [];
    this.endPreviews(false);
    this.run = null;
    const log = rbTerminal((m.out || '') + (m.err || '')).replace(/\n+$/, '');
    if (m.type === 'failed') {
      this.status.textContent = 'failed';
      this.show('error', (m.err || '') + m.message);
      this.worker.terminate();
      this.worker = null;
      this.ready = null;
      p.reject(new Error(m.message));
      return;
    }
    const secs = (m.ms / 1000).toFixed(2);
    const result = {code: m.code, out: m.out, err: m.err, ms: m.ms, args: m.args, pixels: null,
                    frames, t0: this.t0, shown: null};
    if (m.code === 0 && m.png) {
      try {
        await this.queueDraw(m.png, run ? run.size : '', () => true);
        result.shown = performance.now();
        result.pixels = this.canvas.toDataURL('image/png');
        const previews = frames.length === 1 ? ' (after 1 preview)' :
                         frames.length ? ' (after ' + frames.length + ' previews)' : '';
        this.status.textContent = 'rendered ' + this.canvas.width + ' × ' + this.canvas.height +
                                  ' in ' + secs + ' s' + previews;
        this.show('', log);
      } catch (e) {
        this.status.textContent = 'could not draw the image';
        this.show('error', String(e.message || e));
        result.code = -1;
      }
    } else {
      this.status.textContent = 'rt stopped with exit code ' + m.code + ' after ' + secs + ' s';
      this.show('error', log || 'rt exit code ' + m.code);
      this.linkLine(log);
    }
    p.resolve(result);
  }

  // Draws rt's PNG into the canvas after the draws before it, if still wanted() once decoded;
  // resolves to whether it drew. A rejected draw does not stop the ones after it.
  queueDraw(png, size, wanted) {
    const draw = this.drawing.then(() => this.draw(png, size, wanted));
    this.drawing = draw.catch(() => false);
    return draw;
  }

  // Draws rt's PNG into the canvas, pixel for pixel: decoded without colour management or
  // premultiplication (rt writes 8-bit RGB with no colour chunks), shown scaled up, not smoothed,
  // as wide as the picture of SIZE (WxH) is shown, so that a smaller preview takes its place.
  async draw(png, size, wanted) {
    const bitmap = await createImageBitmap(new Blob([png], {type: 'image/png'}),
                                           {colorSpaceConversion: 'none', premultiplyAlpha: 'none'});
    if (!wanted()) {
      bitmap.close();
      return false;
    }
    this.canvas.width = bitmap.width;
    this.canvas.height = bitmap.height;
    const width = Number(size.split('x')[0]) || bitmap.width;
    this.canvas.style.width = width * Math.max(1, Math.floor(480 / width)) + 'px';
    const ctx = this.canvas.getContext('2d', {colorSpace: 'srgb'});
    ctx.imageSmoothingEnabled = false;
    ctx.drawImage(bitmap, 0, 0);
    bitmap.close();
    return true;
  }

  stop(why) {
    if (this.worker) this.worker.terminate();
    this.worker = null;
    this.ready = null;
    const previews = this.run ? this.run.frames.length : 0;
    this.endPreviews(false);
    this.run = null;
    this.prevBoxes = {};
    for (const b of this.boxes || []) this.prevBoxes[b.value] = b.checked;
    const p = this.pending;
    this.pending = null;
    clearInterval(this.tick);
    this.busy(false);
    this.status.textContent = why + ' after ' + ((performance.now() - this.t0) / 1000).toFixed(1) + ' s';
    if (p) p.reject(new Error(why));
    this.show('', 'Render stopped' + (previews ? ' (the picture is its last preview)' : '') +
                  '. A new render starts rt again.');
    this.start();
  }
}

function rbSetup() {
  if (!document.getElementById('rb-live-css')) {
    document.head.appendChild(rbEl('style', {id: 'rb-live-css', text: RB_CSS}));
  }
  const panels = [];
  for (const root of document.querySelectorAll('div.rb-live')) {
    if (!root.rbPanel) root.rbPanel = new RbPanel(root);
    panels.push(root.rbPanel);
  }
  window.raybookLive = {panels};
  const auto = new URLSearchParams(location.search).get('rb-autorender');
  if (auto && panels.length) {
    const out = rbEl('pre', {id: 'rb-autorender-result'});
    const write = (r) => {
      const frames = (r.frames || []).map((f) => Object.assign({}, f, {pixels: undefined}));
      out.textContent = JSON.stringify(Object.assign({}, r, {frames}));
      document.body.appendChild(out);
    };
    panels[0].render({size: auto}).then(write, (e) => write({code: -1, err: String(e.message || e)}));
  }
}

if (document.readyState === 'loading') document.addEventListener('DOMContentLoaded', rbSetup);
else rbSetup();

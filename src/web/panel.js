// raybook's live panels: the page side. bundle.py wraps this file in raybook-live.js with
//   RB_WORKER_SOURCE  the worker's whole source (wasmoon, glue.wasm, lua_host.js, rt_web.js,
//                     worker.js), started from a Blob URL so that file:// pages work too;
//   RB_SCENES         {"chapter05-refraction.lua": "...the scene's text...", ...};
//   RB_CSS            panel.css.
// Every <div class="rb-live" data-scene="chapterNN-....lua" data-chapter="N"> on the page
// becomes a panel: the scene in a text box, the chapter switches (rt --features), the size, a
// Render and a Stop button, a canvas and rt's messages.
//
// For tests: window.raybookLive.panels[i].render({size, text, features}) returns a promise of
// {code, err, out, ms, args, pixels (canvas.toDataURL of the drawn image)}; and a page opened
// with ?rb-autorender=WxH renders its first panel at that size when it loads and writes that
// result as JSON into <pre id="rb-autorender-result">.
'use strict';

const RB_SIZES = ['160x120', '320x240', '640x480'];

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
          this.showSwitches(m.features);
          resolve();
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
    worker.postMessage({type: 'init'});
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
    this.tick = setInterval(() => {
      this.status.textContent = 'rendering… ' + ((performance.now() - this.t0) / 1000).toFixed(1) + ' s';
    }, 200);
    return new Promise((resolve, reject) => {
      this.pending = {id, resolve, reject};
      this.start().then(() => {
        if (!this.pending || this.pending.id !== id) return;
        this.status.textContent = 'rendering…';
        this.worker.postMessage({type: 'render', id, scene: this.scene, text, size,
                                 features: opts.features || this.featureArg()});
      }, (e) => this.finish({type: 'failed', id, message: String(e.message || e)}));
    });
  }

  async finish(m) {
    const p = this.pending;
    if (!p || (m.id !== undefined && m.id !== p.id)) return;
    this.pending = null;
    clearInterval(this.tick);
    this.busy(false);
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
    const result = {code: m.code, out: m.out, err: m.err, ms: m.ms, args: m.args, pixels: null};
    if (m.code === 0 && m.png) {
      try {
        await this.draw(m.png);
        result.pixels = this.canvas.toDataURL('image/png');
        this.status.textContent = 'rendered ' + this.canvas.width + ' × ' + this.canvas.height +
                                  ' in ' + secs + ' s';
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

  // Draws rt's PNG into the canvas, pixel for pixel: decoded without colour management or
  // premultiplication (rt writes 8-bit RGB with no colour chunks), shown scaled up, not smoothed.
  async draw(png) {
    const bitmap = await createImageBitmap(new Blob([png], {type: 'image/png'}),
                                           {colorSpaceConversion: 'none', premultiplyAlpha: 'none'});
    this.canvas.width = bitmap.width;
    this.canvas.height = bitmap.height;
    const scale = Math.max(1, Math.floor(480 / bitmap.width));
    this.canvas.style.width = bitmap.width * scale + 'px';
    const ctx = this.canvas.getContext('2d', {colorSpace: 'srgb'});
    ctx.imageSmoothingEnabled = false;
    ctx.drawImage(bitmap, 0, 0);
    bitmap.close();
  }

  stop(why) {
    if (this.worker) this.worker.terminate();
    this.worker = null;
    this.ready = null;
    this.prevBoxes = {};
    for (const b of this.boxes || []) this.prevBoxes[b.value] = b.checked;
    const p = this.pending;
    this.pending = null;
    clearInterval(this.tick);
    this.busy(false);
    this.status.textContent = why + ' after ' + ((performance.now() - this.t0) / 1000).toFixed(1) + ' s';
    if (p) p.reject(new Error(why));
    this.show('', 'Render stopped. A new render starts rt again.');
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
    const write = (r) => { out.textContent = JSON.stringify(r); document.body.appendChild(out); };
    panels[0].render({size: auto}).then(write, (e) => write({code: -1, err: String(e.message || e)}));
  }
}

if (document.readyState === 'loading') document.addEventListener('DOMContentLoaded', rbSetup);
else rbSetup();
